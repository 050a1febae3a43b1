// Options, reports, the plain polygon soup and the loaded mesh (a template over any mesh type) of
// the mesh reader (mesh_io.h). No CGAL here, so loggers and facades can include it cheaply
// (DESIGN.md §3).
#pragma once

#include <tapeline/core/errors.h>

#include <boost/graph/graph_traits.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace tapeline {

/// How the loader behaves. Where the data lives is the path (or the soup) given to the loader.
struct MeshLoadOptions {
    /// Reject (TopologyError) instead of repairing polygon faces, duplicate vertices, duplicate
    /// faces, unreferenced vertices and non-manifold edges/vertices.
    bool strict = false;
    /// A non-degenerate triangle whose smallest angle is below this is reported as a needle.
    double needle_angle_degrees = 1.0;
};

/// What the loader found and what it did. Counts refer to the input unless they say otherwise.
struct MeshReport {
    /// format: "off", "obj", "ply-ascii", "ply-binary-le", "ply-binary-be", "stl-ascii",
    /// "stl-binary" or "soup".
    ///@{
    std::string file, format;
    ///@}
    /// Sizes of the input and of the mesh built from it.
    ///@{
    std::size_t input_vertices = 0, input_faces = 0, vertices = 0, faces = 0;
    ///@}
    /// Repairs made and defects found; see core/README.md for each.
    ///@{
    std::size_t polygons_triangulated = 0, duplicate_vertices_merged = 0, unreferenced_vertices = 0,
                degenerate_faces = 0, needle_faces = 0, non_manifold_edges = 0,
                non_manifold_vertices = 0, vertices_split = 0, boundary_loops = 0, components = 0;
    ///@}
    /// Input faces dropped because merging duplicate vertices left them with fewer than three
    /// distinct corners, and input faces dropped because they repeat an earlier face.
    ///@{
    std::size_t collapsed_faces_dropped = 0, duplicate_faces_dropped = 0;
    ///@}
    /// Input faces whose vertex order was reversed so that neighbours agree on the orientation.
    std::size_t faces_reoriented = 0;
    /// One line each, naming the file and the first element concerned.
    std::vector<std::string> warnings;

    /// Human-readable multi-line summary (counts that are zero are left out, warnings follow).
    std::string summary() const {
        std::ostringstream s;
        s << file << " (" << format << "): " << input_vertices << " vertices, " << input_faces
          << " faces read; mesh has " << vertices << " vertices, " << faces << " triangles, "
          << components << (components == 1 ? " component, " : " components, ") << boundary_loops
          << (boundary_loops == 1 ? " boundary loop" : " boundary loops") << '\n';
        const std::pair<const char*, std::size_t> counts[] = {
            {"polygons triangulated", polygons_triangulated},
            {"duplicate vertices merged", duplicate_vertices_merged},
            {"unreferenced vertices dropped", unreferenced_vertices},
            {"collapsed faces dropped", collapsed_faces_dropped},
            {"duplicate faces dropped", duplicate_faces_dropped},
            {"faces reoriented", faces_reoriented},
            {"non-manifold edges", non_manifold_edges},
            {"non-manifold vertices", non_manifold_vertices},
            {"vertices added by splitting", vertices_split},
            {"degenerate faces", degenerate_faces},
            {"needle faces", needle_faces},
        };
        for (const auto& [what, n] : counts) {
            if (n != 0) {
                s << "  " << what << ": " << n << '\n';
            }
        }
        for (const std::string& w : warnings) {
            s << "  warning: " << w << '\n';
        }
        return s.str();
    }
};

/// A mesh file as written: points and polygons with the indices of the file (0-based), before any
/// validation beyond what parsing needs. Produced by read_polygon_soup (mesh_io.h).
struct PolygonSoup {
    /// Source file (or name) and format as in MeshReport.
    ///@{
    std::string file, format;  // format as in MeshReport
    ///@}
    std::vector<std::array<double, 3>> points;    ///< coordinates, in file order
    std::vector<std::vector<std::size_t>> faces;  ///< corner indices into `points`
    /// Text formats: 1-based line of each point / face, for messages. Empty for binary formats.
    ///@{
    std::vector<std::uint32_t> point_lines, face_lines;
    ///@}
    /// PLY: every scalar vertex property other than x, y, z, converted to double.
    std::map<std::string, std::vector<double>> vertex_properties;
};

/// How write_scalar_ply (mesh_writers.h) writes a per-vertex scalar field.
struct ScalarPlyOptions {
    std::string property = "distance";  ///< name of the per-vertex float property
    bool binary = true;                 ///< binary_little_endian, else ascii
};

/// A mesh read from a file or a soup, with the map back to the input's vertex numbering.
/// Input vertices and faces are numbered from 0 in file order (OBJ's vertex `1` is vertex 0; for
/// STL, vertex i is the i-th distinct point in order of first appearance, face i is facet i).
/// LoadedMesh<CGAL::Polyhedron_3<...>> must not be copied: a Polyhedron copy has new handles.
///
/// \tparam TriangleMesh a model of `MutableFaceGraph` and `FaceListGraph` (see
///         read_triangle_mesh).
template <class TriangleMesh>
struct LoadedMesh {
    /// A vertex of the mesh.
    using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
    /// A face of the mesh.
    using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;

    TriangleMesh mesh;                          ///< the validated, repaired triangle mesh
    std::vector<vertex_descriptor> vertices;    ///< all mesh vertices, in mesh order
    std::vector<std::size_t> input_index;       ///< parallel to `vertices`: input vertex of each
    std::size_t input_vertex_count = 0;         ///< vertices in the input
    std::vector<face_descriptor> faces;         ///< all mesh faces, in mesh order
    std::vector<std::size_t> face_input_index;  ///< parallel to `faces`: input face each came from
    /// Positions in `vertices` of the mesh vertices representing input vertex i are
    /// copies[copies_begin[i]] .. copies[copies_begin[i + 1] - 1]; a duplicate vertex that was
    /// merged shares those of the vertex it was merged into. Filled by the loader.
    ///@{
    std::vector<std::size_t> copies_begin, copies;
    ///@}
    MeshReport report;  ///< what the loader found and repaired

    /// Mesh vertices that represent input vertex i (several after a non-manifold split, none if
    /// it was unreferenced, those of its twin if it was merged as a duplicate); throws InvalidInput
    /// naming the file if i >= input_vertex_count.
    std::vector<vertex_descriptor> mesh_vertices_of(std::size_t input_vertex) const {
        if (input_vertex >= input_vertex_count) {
            throw InvalidInput(report.file + ": vertex " + std::to_string(input_vertex) +
                               " does not exist (the input has " +
                               std::to_string(input_vertex_count) + " vertices)");
        }
        std::vector<vertex_descriptor> out;
        if (copies_begin.size() == input_vertex_count + 1) {
            for (std::size_t k = copies_begin[input_vertex]; k < copies_begin[input_vertex + 1];
                 ++k) {
                out.push_back(vertices[copies[k]]);
            }
        } else {
            for (std::size_t k = 0; k < input_index.size(); ++k) {
                if (input_index[k] == input_vertex) {
                    out.push_back(vertices[k]);
                }
            }
        }
        return out;
    }

    /// Per-mesh-vertex values (indexed like `vertices`) -> per-input-vertex values: minimum over
    /// the copies, +infinity for input vertices with no mesh vertex.
    ///
    /// \throws InvalidInput when `per_mesh_vertex` does not hold one value per mesh vertex.
    std::vector<double> to_input_order(const std::vector<double>& per_mesh_vertex) const {
        if (per_mesh_vertex.size() != vertices.size()) {
            throw InvalidInput(report.file + ": to_input_order needs one value per mesh vertex (" +
                               std::to_string(vertices.size()) + "), got " +
                               std::to_string(per_mesh_vertex.size()));
        }
        std::vector<double> out(input_vertex_count, std::numeric_limits<double>::infinity());
        // A NaN copy wins over finite ones: hiding a failed value would be worse.
        auto take = [](double& slot, double v) {
            if (std::isnan(v) || v < slot) {
                slot = v;
            }
        };
        if (copies_begin.size() == input_vertex_count + 1) {
            for (std::size_t i = 0; i < input_vertex_count; ++i) {
                for (std::size_t k = copies_begin[i]; k < copies_begin[i + 1]; ++k) {
                    take(out[i], per_mesh_vertex[copies[k]]);
                }
            }
        } else {
            for (std::size_t k = 0; k < per_mesh_vertex.size(); ++k) {
                take(out[input_index[k]], per_mesh_vertex[k]);
            }
        }
        return out;
    }
};

}  // namespace tapeline
