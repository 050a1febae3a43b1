// Options and result of unfolding the faces crossed by a path on a mesh (unfold.h).
//
// Light header without CGAL (DESIGN.md §3): the SVG writer, loggers and test facades include it.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace tapeline::geodesic {

/// Behaviour of unfold_path.
struct UnfoldOptions {
    /// A point lies on a face when it is within tolerance * (mean edge length) of it (> 0).
    /// Consecutive path points closer than that are merged.
    double tolerance = 1e-8;
};

/// One face of the unfolded strip.
struct UnfoldedFace {
    std::size_t face = 0;                 ///< face index (the face_index_map's value)
    std::array<std::size_t, 3> vertices;  ///< vertex indices of its corners (vertex_index_map)
    /// Corners in the plane, in the order of the face's halfedges (the PMP Face_location order).
    std::array<std::array<double, 2>, 3> corners;
};

/// The faces crossed by a path, laid into the plane one after another across their shared edges
/// (rigidly: every face keeps its edge lengths), with the path mapped into that plane. The first
/// path point is at the origin and the last one on the +x axis.
struct UnfoldedPath {
    /// The strip in path order; consecutive faces share an edge (the hinge). A face appears again
    /// when the path comes back to it; faces around a vertex the path touches are included.
    std::vector<UnfoldedFace> faces;
    /// The path's points in the plane (consecutive repeats merged).
    std::vector<std::array<double, 2>> points;
    /// Per point: the index in `faces` of the face it was mapped by.
    std::vector<std::size_t> point_face;
    double traced_length = 0;    ///< length of the path on the mesh (3D polyline)
    double unfolded_length = 0;  ///< length of the mapped polyline (= traced_length, an isometry)
    double straight_length = 0;  ///< distance between the unfolded end points
    /// Whether the straight segment between the unfolded end points crosses every hinge, i.e.
    /// stays inside the strip: it is then a path on the mesh no longer than the traced one, and a
    /// shortest path through this face sequence has exactly straight_length.
    bool straight_inside = false;
    /// Interior path points at a mesh vertex. There the path may bend legitimately (a geodesic
    /// can pass a saddle vertex) and the unfolding goes around one side of the vertex only.
    std::size_t vertex_points = 0;
    std::size_t fan_faces = 0;  ///< faces added to go around a vertex the path touches
};

}  // namespace tapeline::geodesic
