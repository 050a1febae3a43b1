// Options, reports and the plain polygon soup of the mesh reader (mesh_io.h). No CGAL here, so
// loggers and test facades can include it cheaply (DESIGN.md §3).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
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

}  // namespace tapeline
