// Options, results and file writers of piece meshing (meshing.h), without CGAL, so that loggers,
// the command-line tool and test facades can include them cheaply (DESIGN.md §3, §5).
//
// A PieceMesh holds the 2D triangulation of one piece (pattern coordinates in mm, the UVs), its
// 3D rest position (the GarmentCode placement when the piece has one, else z = 0), and for every
// outline edge the boundary vertices along it. Boundary vertices come first, in outline order.
// A SeamStitch pairs the boundary vertices of a seam's two sides one to one, as a cloth
// simulator's stitching needs.
#pragma once

#include <tapeline/core/atomic_write.h>
#include <tapeline/core/errors.h>
#include <tapeline/pattern/geometry.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace tapeline::pattern {

/// Sizes and shape bounds of the piece meshes.
struct MeshingOptions {
    /// Boundary segments are at most this long (uniform in arc length along each edge), and it is
    /// the size bound of the Delaunay refinement (longest edge of a refined triangle).
    double target_edge_mm = 10;
    /// Enough boundary points that each chord stays within this of a curved edge.
    double curve_tolerance_mm = 0.5;
    /// Shape bound B of CGAL::Delaunay_mesh_size_criteria_2: B = sin²(smallest angle), so 0.125
    /// asks for angles of at least 20.7° (where the boundary allows it).
    double aspect_bound = 0.125;
    /// Use the piece's 3D placement for the 3D positions when it has one.
    bool use_placement = true;
};

/// A boundary vertex as a point of the outline: edge index and curve parameter t.
struct BoundaryParam {
    std::size_t edge = 0;  ///< outline edge index
    double t = 0;          ///< curve parameter on that edge
};

/// The triangle mesh of one piece; boundary vertices come first.
struct PieceMesh {
    std::string piece;                                    ///< piece name
    std::vector<Point2> uv;                               ///< 2D pattern coordinates, mm
    std::vector<std::array<double, 3>> xyz;               ///< 3D rest position, mm
    std::vector<std::array<std::uint32_t, 3>> triangles;  ///< counter-clockwise in 2D
    std::size_t boundary_count = 0;                       ///< vertices [0, boundary_count)
    std::vector<BoundaryParam> boundary_params;           ///< per boundary vertex
    /// Per outline edge: its boundary vertices from start to end, both included (the last is the
    /// next edge's first). A degenerate edge (< 1e-6 mm) outside seams holds just its start.
    std::vector<std::vector<std::uint32_t>> edge_vertices;
};

/// Seam `seam` of the pattern: vertex `pairs[k].first` of piece `piece_a` is sewn to vertex
/// `pairs[k].second` of piece `piece_b` (indices into PatternMesh::pieces).
struct SeamStitch {
    std::size_t seam = 0;  ///< index into Pattern::seams
    /// The pieces of side A and side B.
    ///@{
    std::size_t piece_a = 0, piece_b = 0;
    ///@}
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;  ///< sewn vertex pairs
};

/// Meshes of every piece and the vertex pairs of every seam (mesh_pattern).
struct PatternMesh {
    std::vector<PieceMesh> pieces;  ///< in Pattern::pieces order
    std::vector<SeamStitch> seams;  ///< one per seam
};

/// Sizes and quality of the meshes mesh_pattern made.
struct MeshingReport {
    /// Totals over the pieces.
    ///@{
    std::size_t pieces = 0, vertices = 0, triangles = 0, boundary_vertices = 0;
    ///@}
    std::size_t boundary_steiner_points = 0;  ///< vertices the refinement put on the outline: 0
    double max_edge_mm = 0;                   ///< longest triangle edge
    double max_boundary_edge_mm = 0;          ///< longest boundary segment
    double min_angle_deg = 180;               ///< smallest triangle angle
    double area_mm2 = 0;                      ///< total area
    double seconds = 0;                       ///< wall-clock time
};

/// Wavefront OBJ: one object per piece; v = 3D position (mm), vt = 2D pattern coordinates ×
/// `uv_scale` (1: mm; 0.001: m), f v/vt.
inline void write_mesh_obj(const PatternMesh& mesh, std::ostream& out, double uv_scale = 1.0) {
    char buf[128];
    out << "# Tapeline pattern mesh: v = 3D rest position (mm), vt = 2D pattern coordinates (mm x "
        << uv_scale << ")\n";
    std::size_t base = 1;
    for (const PieceMesh& p : mesh.pieces) {
        std::string name = p.piece;
        for (char& c : name) {
            c = (c == ' ' || c == '\t' || c == '\n' || c == '\r') ? '_' : c;
        }
        out << "o " << name << '\n';
        for (const auto& v : p.xyz) {
            std::snprintf(buf, sizeof buf, "v %.9g %.9g %.9g\n", v[0], v[1], v[2]);
            out << buf;
        }
        for (const Point2& t : p.uv) {
            std::snprintf(buf, sizeof buf, "vt %.9g %.9g\n", t.x * uv_scale, t.y * uv_scale);
            out << buf;
        }
        for (const auto& f : p.triangles) {
            const std::size_t a = base + f[0], b = base + f[1], c = base + f[2];
            out << "f " << a << '/' << a << ' ' << b << '/' << b << ' ' << c << '/' << c << '\n';
        }
        base += p.uv.size();
    }
}

/// ASCII PLY: vertex x y z (3D, mm), u v (2D pattern coordinates × uv_scale), piece (index);
/// face vertex_indices.
inline void write_mesh_ply(const PatternMesh& mesh, std::ostream& out, double uv_scale = 1.0) {
    std::size_t nv = 0, nf = 0;
    for (const PieceMesh& p : mesh.pieces) {
        nv += p.uv.size();
        nf += p.triangles.size();
    }
    out << "ply\nformat ascii 1.0\ncomment Tapeline pattern mesh; u v = 2D pattern coordinates "
           "(mm x "
        << uv_scale << ")\n";
    for (std::size_t i = 0; i < mesh.pieces.size(); ++i) {
        out << "comment piece " << i << " " << mesh.pieces[i].piece << '\n';
    }
    out << "element vertex " << nv
        << "\nproperty double x\nproperty double y\nproperty double z\nproperty double u\n"
           "property double v\nproperty int piece\nelement face "
        << nf << "\nproperty list uchar int vertex_indices\nend_header\n";
    char buf[160];
    for (std::size_t i = 0; i < mesh.pieces.size(); ++i) {
        const PieceMesh& p = mesh.pieces[i];
        for (std::size_t k = 0; k < p.uv.size(); ++k) {
            std::snprintf(buf, sizeof buf, "%.9g %.9g %.9g %.9g %.9g %zu\n", p.xyz[k][0],
                          p.xyz[k][1], p.xyz[k][2], p.uv[k].x * uv_scale, p.uv[k].y * uv_scale, i);
            out << buf;
        }
    }
    std::size_t base = 0;
    for (const PieceMesh& p : mesh.pieces) {
        for (const auto& f : p.triangles) {
            out << "3 " << base + f[0] << ' ' << base + f[1] << ' ' << base + f[2] << '\n';
        }
        base += p.uv.size();
    }
}

/// Writes OBJ (".obj") or PLY (".ply") by the file's extension, atomically.
///
/// \throws InvalidInput naming `path` for another extension, or when it cannot be written.
inline void write_mesh(const PatternMesh& mesh, const std::string& path, double uv_scale = 1.0) {
    const auto ends = [&](const char* s) {
        const std::string e(s);
        return path.size() >= e.size() && path.compare(path.size() - e.size(), e.size(), e) == 0;
    };
    if (ends(".obj")) {
        write_file_atomically(path, [&](std::ostream& o) { write_mesh_obj(mesh, o, uv_scale); });
    } else if (ends(".ply")) {
        write_file_atomically(path, [&](std::ostream& o) { write_mesh_ply(mesh, o, uv_scale); });
    } else {
        throw InvalidInput(path + ": unknown mesh format (expected .obj or .ply)");
    }
}

}  // namespace tapeline::pattern
