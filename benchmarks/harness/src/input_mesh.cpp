#include <tapeline/bench/methods.h>

#include <tapeline/core/errors.h>
#include <tapeline/core/mesh_io.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace tapeline::bench {

InputMesh load_input_mesh_file(const std::string& path, bool strict) {
    MeshLoadOptions options;
    options.strict = strict;
    InputMesh input;
    input.loaded = read_triangle_mesh<Mesh>(path, options);
    input.file = path;
    input.name = std::filesystem::path(path).filename().string();
    input.family = std::filesystem::path(path).stem().string();
    return input;
}

InputMesh make_input_surface(const std::string& spec_text, std::uint64_t seed) {
    InputMesh input;
    input.spec = SurfaceSpec::parse(spec_text);
    input.spec->seed = seed;
    LoadedMesh<Mesh>& loaded = input.loaded;
    make_surface_mesh(*input.spec, loaded.mesh);
    for (Vertex v : vertices(loaded.mesh)) {
        loaded.vertices.push_back(v);
        loaded.input_index.push_back(loaded.input_index.size());
    }
    loaded.input_vertex_count = loaded.vertices.size();
    loaded.report.file = input.spec->to_string();
    loaded.report.format = "generated";
    loaded.report.input_vertices = loaded.report.vertices = num_vertices(loaded.mesh);
    loaded.report.input_faces = loaded.report.faces = num_faces(loaded.mesh);
    input.name = input.spec->to_string();
    input.family = input.spec->family();
    return input;
}

std::vector<std::array<double, 3>> mesh_points(const Mesh& mesh) {
    std::vector<std::array<double, 3>> points;
    points.reserve(num_vertices(mesh));
    for (Vertex v : vertices(mesh)) {
        const Point& p = mesh.point(v);
        points.push_back({p.x(), p.y(), p.z()});
    }
    return points;
}

std::size_t current_rss_bytes() {
    std::ifstream status("/proc/self/status");
    std::string key;
    while (status >> key) {
        if (key == "VmRSS:") {
            std::size_t kb = 0;
            status >> kb;
            return kb * 1024;
        }
        std::getline(status, key);
    }
    return 0;
}

}  // namespace tapeline::bench
