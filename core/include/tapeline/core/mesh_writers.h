// Writing meshes (OFF, OBJ, PLY, STL by extension) and distance fields as coloured PLY that MeshLab
// or Blender open directly. Every file is written atomically (atomic_write.h): a failure never
// leaves a half-written file. The colour map is a piecewise-linear rendition of viridis (van der
// Walt and Smith, matplotlib 2015), perceptually uniform and readable by colour-blind people.
#pragma once

#include <tapeline/core/atomic_write.h>
#include <tapeline/core/errors.h>
#include <tapeline/core/internal/text_scan.h>
#include <tapeline/core/mesh_io_types.h>  // ScalarPlyOptions

#include <CGAL/boost/graph/IO/OBJ.h>
#include <CGAL/boost/graph/IO/OFF.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/properties.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

namespace tapeline {

namespace internal {

/// Viridis at t in [0, 1] (clamped), through 9 control points.
inline std::array<std::uint8_t, 3> viridis(double t) {
    static const double control[9][3] = {
        {68, 1, 84},    {72, 40, 120},  {62, 74, 137},  {49, 104, 142}, {38, 130, 142},
        {31, 158, 137}, {53, 183, 121}, {109, 205, 89}, {253, 231, 37},
    };
    t = std::min(1.0, std::max(0.0, t)) * 8.0;
    const int k = std::min(7, static_cast<int>(t));
    const double s = t - k;
    std::array<std::uint8_t, 3> rgb{};
    for (int c = 0; c < 3; ++c) {
        rgb[c] = static_cast<std::uint8_t>(
            std::lround(control[k][c] * (1.0 - s) + control[k + 1][c] * s));
    }
    return rgb;
}

/// Little-endian binary output whatever the host.
class LittleEndianWriter {
public:
    explicit LittleEndianWriter(std::ostream& out) : out_(out) {}
    template <class T>
    void put(T value) {
        unsigned char b[sizeof(T)];
        std::memcpy(b, &value, sizeof(T));
        if (!host_little_) {
            for (std::size_t i = 0; i < sizeof(T) / 2; ++i) {
                std::swap(b[i], b[sizeof(T) - 1 - i]);
            }
        }
        out_.write(reinterpret_cast<const char*>(b), sizeof(T));
    }

private:
    std::ostream& out_;
    bool host_little_ = [] {
        const std::uint16_t one = 1;
        unsigned char first = 0;
        std::memcpy(&first, &one, 1);
        return first == 1;
    }();
};

/// Vertex positions as doubles in mesh order and faces as indices into them.
template <class TriangleMesh>
void mesh_arrays(const TriangleMesh& tm, std::vector<std::array<double, 3>>& points,
                 std::vector<std::vector<std::size_t>>& polygons) {
    using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
    auto vpm = get(CGAL::vertex_point, tm);
    auto index = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
    points.clear();
    polygons.clear();
    for (vertex_descriptor v : vertices(tm)) {
        put(index, v, points.size());
        const auto& p = get(vpm, v);
        points.push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
    }
    for (auto f : faces(tm)) {
        std::vector<std::size_t> polygon;
        for (auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
            polygon.push_back(get(index, target(h, tm)));
        }
        polygons.push_back(std::move(polygon));
    }
}

inline void check_face_degree(const std::string& path,
                              const std::vector<std::vector<std::size_t>>& polygons) {
    for (std::size_t f = 0; f < polygons.size(); ++f) {
        if (polygons[f].size() > 255) {
            throw InvalidInput(path + ": face " + std::to_string(f) + " has " +
                               std::to_string(polygons[f].size()) +
                               " vertices; PLY lists here hold at most 255");
        }
    }
}

inline void write_ply_geometry(const std::string& path,
                               const std::vector<std::array<double, 3>>& points,
                               const std::vector<std::vector<std::size_t>>& polygons) {
    check_face_degree(path, polygons);
    write_file_atomically(
        path,
        [&](std::ostream& out) {
            out << "ply\nformat binary_little_endian 1.0\ncomment written by tapeline\n"
                << "element vertex " << points.size()
                << "\nproperty double x\nproperty double y\nproperty double z\n"
                << "element face " << polygons.size()
                << "\nproperty list uchar int vertex_indices\nend_header\n";
            LittleEndianWriter w(out);
            for (const auto& p : points) {
                w.put(p[0]);
                w.put(p[1]);
                w.put(p[2]);
            }
            for (const auto& polygon : polygons) {
                w.put(static_cast<std::uint8_t>(polygon.size()));
                for (std::size_t v : polygon) {
                    w.put(static_cast<std::int32_t>(v));
                }
            }
        },
        true);
}

inline void write_stl_binary(const std::string& path,
                             const std::vector<std::array<double, 3>>& points,
                             const std::vector<std::vector<std::size_t>>& polygons) {
    std::vector<std::array<std::size_t, 3>> triangles;  // polygons as fans
    for (const auto& polygon : polygons) {
        for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
            triangles.push_back({polygon[0], polygon[k], polygon[k + 1]});
        }
    }
    if (triangles.size() > 0xffffffffULL) {
        throw InvalidInput(path + ": too many triangles for binary STL");
    }
    write_file_atomically(
        path,
        [&](std::ostream& out) {
            std::string header = "binary STL written by tapeline";
            header.resize(80, ' ');
            out.write(header.data(), 80);
            LittleEndianWriter w(out);
            w.put(static_cast<std::uint32_t>(triangles.size()));
            for (const auto& t : triangles) {
                const auto& a = points[t[0]];
                const auto& b = points[t[1]];
                const auto& c = points[t[2]];
                const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
                const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
                double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                               u[0] * v[1] - u[1] * v[0]};
                const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
                for (double& x : n) {
                    x = len > 0 ? x / len : 0.0;
                    w.put(static_cast<float>(x));
                }
                for (const auto* p : {&a, &b, &c}) {
                    for (double x : *p) {
                        w.put(static_cast<float>(x));
                    }
                }
                w.put(std::uint16_t{0});
            }
        },
        true);
}

}  // namespace internal

namespace internal {

inline void check_mesh_extension(const std::string& path) {
    const std::string ext = lower_extension(path);
    if (ext != ".off" && ext != ".obj" && ext != ".ply" && ext != ".stl") {
        throw InvalidInput(path + ": unknown mesh format '" + ext +
                           "' for writing (expected .off, .obj, .ply or .stl)");
    }
}

}  // namespace internal

/// Refuses, before any work, a mesh output write_mesh could not write: an extension other than
/// .off, .obj, .ply or .stl, or a path check_output_path refuses.
///
/// \throws InvalidInput naming `path`.
inline void check_mesh_output(const std::string& path) {
    internal::check_mesh_extension(path);
    check_output_path(path);
}

/// Writes `tm` as OFF, OBJ (17 significant digits, via CGAL), PLY (binary little endian, double
/// coordinates) or STL (binary, float coordinates), chosen by the extension; atomically.
/// An unknown extension is InvalidInput.
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `VertexListGraph` with an internal vertex
///         point map (CGAL::Surface_mesh, CGAL::Polyhedron_3, ...).
/// \throws InvalidInput naming `path` on an unknown extension, an output path that cannot be
///         written (missing or unwritable directory, a directory), a failed write or rename,
///         a non-polygon face count beyond binary STL's limit, or CGAL failing to write;
///         `path` is left untouched then.
template <class TriangleMesh>
void write_mesh(const std::string& path, const TriangleMesh& tm) {
    const std::string ext = internal::lower_extension(path);
    if (ext == ".off" || ext == ".obj") {
        write_file_atomically(path, [&](std::ostream& out) {
            const bool ok =
                ext == ".off"
                    ? CGAL::IO::write_OFF(out, tm, CGAL::parameters::stream_precision(17))
                    : CGAL::IO::write_OBJ(out, tm, CGAL::parameters::stream_precision(17));
            if (!ok) {
                throw InvalidInput(path + ": CGAL could not write the mesh");
            }
        });
        return;
    }
    internal::check_mesh_extension(path);
    std::vector<std::array<double, 3>> points;
    std::vector<std::vector<std::size_t>> polygons;
    internal::mesh_arrays(tm, points, polygons);
    if (ext == ".ply") {
        internal::write_ply_geometry(path, points, polygons);
    } else {
        internal::write_stl_binary(path, points, polygons);
    }
}

/// PLY with x y z (float), the scalar as a float property and red/green/blue uchar colours from
/// viridis over the finite range of `values`; non-finite values are written as they are and
/// coloured grey. `values` are indexed in mesh vertex order (as `vertices` in LoadedMesh).
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `VertexListGraph` with an internal vertex
///         point map, every face a triangle.
/// \throws InvalidInput naming `path` on an invalid property name, a value count that is not
///         the vertex count, a face that is not a triangle, an output path that cannot be
///         written, or a failed write or rename; `path` is left untouched then.
template <class TriangleMesh>
void write_scalar_ply(const std::string& path, const TriangleMesh& tm,
                      const std::vector<double>& values, const ScalarPlyOptions& options = {}) {
    if (options.property.empty() || options.property == "x" || options.property == "y" ||
        options.property == "z" || options.property == "red" || options.property == "green" ||
        options.property == "blue" ||
        options.property.find_first_of(" \t\r\n") != std::string::npos) {
        throw InvalidInput(path + ": invalid PLY property name '" + options.property + "'");
    }
    std::vector<std::array<double, 3>> points;
    std::vector<std::vector<std::size_t>> polygons;
    internal::mesh_arrays(tm, points, polygons);
    if (values.size() != points.size()) {
        throw InvalidInput(path + ": " + std::to_string(values.size()) + " values for a mesh of " +
                           std::to_string(points.size()) + " vertices");
    }
    internal::check_face_degree(path, polygons);
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (double v : values) {
        if (std::isfinite(v)) {
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    }
    auto colour = [&](double v) -> std::array<std::uint8_t, 3> {
        if (!std::isfinite(v)) {
            return {128, 128, 128};
        }
        return internal::viridis(hi > lo ? (v - lo) / (hi - lo) : 0.0);
    };
    write_file_atomically(
        path,
        [&](std::ostream& out) {
            out << "ply\nformat " << (options.binary ? "binary_little_endian" : "ascii")
                << " 1.0\ncomment written by tapeline; colours: viridis over [" << lo << ", " << hi
                << "], grey = no value\n"
                << "element vertex " << points.size()
                << "\nproperty float x\nproperty float y\nproperty float z\nproperty float "
                << options.property
                << "\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
                << "element face " << polygons.size()
                << "\nproperty list uchar int vertex_indices\nend_header\n";
            if (options.binary) {
                internal::LittleEndianWriter w(out);
                for (std::size_t i = 0; i < points.size(); ++i) {
                    for (double x : points[i]) {
                        w.put(static_cast<float>(x));
                    }
                    w.put(static_cast<float>(values[i]));
                    for (std::uint8_t c : colour(values[i])) {
                        w.put(c);
                    }
                }
                for (const auto& polygon : polygons) {
                    w.put(static_cast<std::uint8_t>(polygon.size()));
                    for (std::size_t v : polygon) {
                        w.put(static_cast<std::int32_t>(v));
                    }
                }
            } else {
                out.precision(9);
                for (std::size_t i = 0; i < points.size(); ++i) {
                    const auto rgb = colour(values[i]);
                    out << static_cast<float>(points[i][0]) << ' '
                        << static_cast<float>(points[i][1]) << ' '
                        << static_cast<float>(points[i][2]) << ' ' << static_cast<float>(values[i])
                        << ' ' << int{rgb[0]} << ' ' << int{rgb[1]} << ' ' << int{rgb[2]} << '\n';
                }
                for (const auto& polygon : polygons) {
                    out << polygon.size();
                    for (std::size_t v : polygon) {
                        out << ' ' << v;
                    }
                    out << '\n';
                }
            }
        },
        options.binary);
}

}  // namespace tapeline
