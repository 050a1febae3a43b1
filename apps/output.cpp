#include "output.h"

#include <tapeline/core/atomic_write.h>
#include <tapeline/core/errors.h>
#include <tapeline/core/mesh_writers.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <ostream>

namespace tapeline::app {

std::string extension_of(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

void write_distance(std::ostream& out, double d) {
    if (std::isfinite(d)) {
        out << d;
    } else {
        out << "inf";
    }
}

void write_distances(const std::string& path, const Mesh& mesh,
                     const std::vector<double>& per_mesh_vertex,
                     const std::vector<double>& per_input_vertex) {
    const std::string ext = extension_of(path);
    if (ext == ".txt") {
        write_file_atomically(path, [&](std::ostream& out) {
            out << std::setprecision(17);
            for (double d : per_input_vertex) {
                write_distance(out, d);
                out << '\n';
            }
        });
    } else if (ext == ".ply") {
        write_scalar_ply(path, mesh, per_mesh_vertex);
    } else {
        throw InvalidInput(path + ": unknown output format '" + ext +
                           "' (use .txt for one distance per line or .ply for a coloured mesh)");
    }
}

}  // namespace tapeline::app
