// On-face trace of a sample polyline of the curvature flow (the thesis' output (b)): consecutive
// samples joined by the plane cut of the faces between them. One routine for the two-point paths
// (curvature_flow.h, run_flow) and the single-source distances (gcf_distances.h); plain arrays, no
// CGAL.
#pragma once

#include <tapeline/geodesic/internal/gcf_engine.h>

#include <cstdint>
#include <limits>
#include <vector>

namespace tapeline::geodesic::internal::gcf {

/// Normal contained in the cut plane of the segment from sample a to sample b: the sum of the
/// normals of the two samples' faces (the mesh's orientation, so no sign to guess). Vertex
/// normals are eigenvectors of either sign, and at a crease vertex the normal follows the sheet
/// with more faces, so it can be perpendicular to the face the sample lies on; orienting them by
/// each other then turned the cut plane nearly into the surface (fandisk: a 0.84-edge segment
/// traced 4.1 edges long). Measured with vertex normals instead (gcf-window:8/faces, shared
/// meshes): armadillo max error 3.0e-2 -> 7.2e-2, fandisk mean 8.3e-4 -> 8.6e-4; two-point
/// paths (test printouts): the same on-mesh lengths, plane-cut traces mostly longer (spot 0-2929:
/// +4.6e-3 against +3.5e-3 over exact). At a knife edge (the face normals cancel) the vertex
/// normals, oriented by each other.
inline Vec3 cut_normal(const Mesh& m, const Sample& a, const Sample& b) {
    if (a.face != kNone && b.face != kNone) {
        const Vec3 n = m.face_normal[a.face] + m.face_normal[b.face];
        if (n.norm() > 0.1)
            return n;
    }
    const Vec3 n0 = m.frame(a.vertex).col(2), n1 = m.frame(b.vertex).col(2);
    return n0 + (n0.dot(n1) < 0 ? Vec3(-n1) : n1);
}

/// Appends to `out` (ending with a.p) the plane cut of the faces from sample a to sample b
/// (trace_segment with cut_normal): false, nothing appended, when no cut reaches b within 1.5x
/// the chord. A sample on an edge or at a vertex lies on several faces, and the cut must start in
/// the one the segment enters: a's face (the projection may have found it outside the nearest
/// vertex's 1-ring) and every face around a's vertex that holds a are tried, the shortest trace
/// kept. The 1.5x limit: a cut can wander far (around a thin part, fandisk: 19 mean edges for a
/// 0.9-edge segment), while a fold of up to ~97 degrees lengthens a segment by at most 1.5x;
/// without it the straightened two-point paths on mh_male_average left the faces (3 of 36 pairs
/// below the exact distance, down to -10 %, test PathOnFaces.OnMeshNeverBelowExactOnABody).
inline bool plane_cut(const Mesh& m, const Sample& a, const Sample& b, std::vector<Vec3>& out) {
    const double chord = (b.p - a.p).norm();
    if (a.face != kNone && a.face == b.face) {
        out.push_back(b.p);
        return true;
    }
    const Vec3 nrm = cut_normal(m, a, b);
    thread_local std::vector<Vec3> tmp, best;
    double best_len = std::numeric_limits<double>::infinity();
    auto attempt = [&](std::uint32_t f) {
        tmp.assign(1, a.p);
        if (!trace_segment(m, a.p, f, b.p, b.face, nrm, tmp))
            return;
        const double len = polyline_length(tmp);
        if (len < best_len) {
            best_len = len;
            best.swap(tmp);
        }
    };
    if (a.face != kNone)
        attempt(a.face);
    for (std::uint32_t k = m.vf_start[a.vertex]; k < m.vf_start[a.vertex + 1]; ++k) {
        const std::uint32_t f = m.vf[k];
        if (f != a.face && on_face(m, f, a.p))
            attempt(f);
    }
    if (!(best_len <= 1.5 * chord))
        return false;
    out.insert(out.end(), best.begin() + 1, best.end());
    return true;
}

/// Appends to `out` (ending with a.p) a path on the faces from sample a to sample b: the plane
/// cut; without one, the segment split at its midpoint projected onto the faces (up to 3 times;
/// samples on two sheets of a fold or across a narrow gap, whose chord cuts through the solid).
/// A piece still without a cut is handed to `join(p, q, out)`, which appends a connection from p
/// ending with q.p (the caller's choice: an edge path, or the chord and a note that the trace
/// failed). Returns the number of such pieces.
template <class Join>
std::size_t trace_on_faces(const Mesh& m, const Sample& a, const Sample& b, std::vector<Vec3>& out,
                           const Join& join, int depth = 0) {
    if (plane_cut(m, a, b, out))
        return 0;
    if (depth < 3 && (b.p - a.p).norm() > 1e-3 * m.mean_edge) {
        Sample mid;
        mid.p = 0.5 * (a.p + b.p);
        mid.vertex = nearest_vertex_walk(m, mid.p, a.vertex);
        project_around(m, mid);
        if (mid.face != kNone && (mid.p - a.p).norm() > 0 && (mid.p - b.p).norm() > 0)
            return trace_on_faces(m, a, mid, out, join, depth + 1) +
                   trace_on_faces(m, mid, b, out, join, depth + 1);
    }
    join(a, b, out);
    return 1;
}

}  // namespace tapeline::geodesic::internal::gcf
