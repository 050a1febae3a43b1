// The MMP window propagation's view of the compact mesh (core/compact_mesh.h): edge lengths,
// planar face layouts and vertex flags on top of the shared arrays, so that the engine
// (mmp_engine.h) is compiled once per translation unit whatever the input mesh type is.
#pragma once

#include <tapeline/core/compact_mesh_types.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace tapeline::geodesic::internal::mmp {

constexpr std::uint32_t kNone = tapeline::CompactMesh::kNone;
constexpr double kPi = 3.14159265358979323846;

struct Vec2 {
    double x = 0, y = 0;
};
inline Vec2 operator-(Vec2 a, Vec2 b) {
    return {a.x - b.x, a.y - b.y};
}
inline Vec2 operator+(Vec2 a, Vec2 b) {
    return {a.x + b.x, a.y + b.y};
}
inline Vec2 operator*(double s, Vec2 a) {
    return {s * a.x, s * a.y};
}
inline double dot(Vec2 a, Vec2 b) {
    return a.x * b.x + a.y * b.y;
}
inline double norm(Vec2 a) {
    return std::sqrt(a.x * a.x + a.y * a.y);
}

inline std::uint32_t next_he(std::uint32_t h) {
    return tapeline::CompactMesh::next_halfedge(h);
}
inline std::uint32_t prev_he(std::uint32_t h) {
    return tapeline::CompactMesh::prev_halfedge(h);
}

enum VertexFlag : std::uint8_t {
    kBorder = 1,       ///< on the mesh border
    kSaddle = 2,       ///< total angle >= 2 pi (minus round-off): geodesics may bend here
    kNonManifold = 4,  ///< several fans of faces meet at the vertex
    kDegenerate = 8,   ///< corner of a face with no area or a zero-length edge
    kPseudoSource = kBorder | kSaddle | kNonManifold | kDegenerate,
};

struct CompactMesh : tapeline::CompactMesh {
    std::vector<double> len;  ///< 3 per face: length of halfedge 3f+k
    std::vector<Vec2> apex;   ///< 3 per face: corner k+2 in the frame of halfedge 3f+k
    std::vector<std::uint8_t> vflags;

    CompactMesh() = default;
    explicit CompactMesh(tapeline::CompactMesh&& base) : tapeline::CompactMesh(std::move(base)) {}

    /// Planar layout of face f with corner k at the origin and corner k+1 on the positive x axis;
    /// the face lies in y >= 0 (counter-clockwise). The x axis carries the exact edge length, so
    /// a shared edge has the same layout in both faces; the third corner comes from 3D dot and
    /// cross products (precomputed in `apex`), which stay accurate on needles where the law of
    /// cosines loses the height to cancellation (b^2 - cx^2 ~ 1e-18 for a 1e-9 high needle).
    std::array<Vec2, 3> layout(std::uint32_t f, int k) const {
        std::array<Vec2, 3> p;
        p[k] = {0, 0};
        p[(k + 1) % 3] = {len[3 * f + k], 0};
        p[(k + 2) % 3] = apex[3 * f + k];
        return p;
    }

    /// Computes lengths, layouts and the vertex flags. `degenerate_slack`:
    /// a face whose relative triangle-inequality slack is below it marks its corners kDegenerate.
    void finish(double degenerate_slack = 1e-12) {
        const std::size_t nf = face_count(), nv = vertex_count();
        len.assign(3 * nf, 0.0);
        for (std::size_t h = 0; h < 3 * nf; ++h) {
            const auto p = point(corner[h]);
            const auto q = point(corner[next_he(static_cast<std::uint32_t>(h))]);
            const double dx = p[0] - q[0], dy = p[1] - q[1], dz = p[2] - q[2];
            len[h] = std::sqrt(dx * dx + dy * dy + dz * dz);
        }
        apex.assign(3 * nf, Vec2{});
        for (std::size_t h = 0; h < 3 * nf; ++h) {
            const std::uint32_t hh = static_cast<std::uint32_t>(h);
            const auto a = point(corner[hh]);
            const auto b = point(corner[next_he(hh)]);
            const auto c = point(corner[prev_he(hh)]);
            const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
            const double w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
            const double l = len[h];
            if (!(l > 0)) {
                apex[h] = {0, len[prev_he(hh)]};
                continue;
            }
            const double cr[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
                                  u[0] * w[1] - u[1] * w[0]};
            apex[h] = {(u[0] * w[0] + u[1] * w[1] + u[2] * w[2]) / l,
                       std::sqrt(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]) / l};
        }

        vflags.assign(nv, 0);
        std::vector<double> angle(nv, 0.0);
        for (std::uint32_t f = 0; f < nf; ++f) {
            const double l0 = len[3 * f], l1 = len[3 * f + 1], l2 = len[3 * f + 2];
            const double perimeter = l0 + l1 + l2;
            const double slack =
                perimeter > 0 ? std::min({l0 + l1 - l2, l1 + l2 - l0, l2 + l0 - l1}) / perimeter
                              : 0.0;
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t v = corner[3 * f + k];
                if (slack <= degenerate_slack) {
                    vflags[v] |= kDegenerate;
                    continue;
                }
                // Angle at corner k between its two edges (law of cosines).
                const double a = len[3 * f + k], b = len[3 * f + (k + 2) % 3];
                const double c = len[3 * f + (k + 1) % 3];
                const double cosine = std::clamp((a * a + b * b - c * c) / (2 * a * b), -1.0, 1.0);
                angle[v] += std::acos(cosine);
            }
        }
        for (std::uint32_t v = 0; v < nv; ++v) {
            const std::uint32_t total = vstart[v + 1] - vstart[v];
            if (total == 0)
                continue;
            // Walk one fan around v; a border stops the walk, several fans make v non-manifold.
            std::uint32_t visited = 1;
            bool border = false;
            const std::uint32_t start = vcorners[vstart[v]];
            std::uint32_t c = start;
            for (;;) {  // clockwise: through the halfedge arriving at v
                const std::uint32_t t = twin[prev_he(c)];
                if (t == kNone) {
                    border = true;
                    break;
                }
                c = t;  // twin of (prev -> v) leaves v in the next face: its start corner is v
                if (c == start || visited > total)
                    break;
                ++visited;
            }
            if (border) {
                c = start;
                for (;;) {
                    const std::uint32_t t = twin[c];  // halfedge leaving v
                    if (t == kNone || visited > total)
                        break;
                    c = next_he(t);  // t arrives at v; the next halfedge leaves v
                    ++visited;
                }
            }
            if (border)
                vflags[v] |= kBorder;
            if (visited != total)
                vflags[v] |= kNonManifold;
            // Flat vertices (2 pi up to round-off) are pseudo-sources too: treating a vertex as a
            // possible bending point is always safe, missing a saddle is not.
            if (angle[v] >= 2 * kPi * (1 - 1e-9))
                vflags[v] |= kSaddle;
        }
    }
};

}  // namespace tapeline::geodesic::internal::mmp
