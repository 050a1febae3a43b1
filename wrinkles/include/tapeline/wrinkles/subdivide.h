// Midpoint subdivision of a draped garment: every triangle split into four at its edge midpoints,
// `levels` times, carrying the pattern coordinates, the grain and the piece of each triangle. The
// fine mesh lies exactly on the coarse one (the new vertices are midpoints, nothing is smoothed),
// so that a later displacement is all that separates them, and every fine vertex knows the coarse
// triangle and barycentric coordinates it came from.
//
// A coarse edge shared by two triangles (inside a piece, or across a welded seam) gets one
// midpoint, so the fine mesh is welded wherever the coarse one is. Pattern coordinates are per
// triangle corner: a midpoint's are the mean of its edge's two corners in that triangle, so the
// two sides of a seam keep their own pieces' coordinates.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/core/vec3.h>
#include <tapeline/garment/garment_types.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace tapeline::wrinkles {

/// A subdivided garment and where each of its vertices came from.
struct Subdivision {
    garment::GarmentMesh mesh;  ///< the fine mesh (positions on the coarse surface)
    /// Per fine vertex: a coarse triangle holding it and its barycentric coordinates there.
    std::vector<std::uint32_t> coarse_triangle;
    std::vector<std::array<double, 3>> barycentric;
    /// Per fine triangle: the coarse triangle it lies in.
    std::vector<std::uint32_t> parent_triangle;
};

/// Splits every triangle of `coarse` into 4^levels (see the file comment).
///
/// \throws InvalidInput when levels is outside [0, 4], the arrays' sizes disagree, or a triangle
///         names a vertex out of range.
inline Subdivision subdivide(const garment::GarmentMesh& coarse, int levels) {
    if (levels < 0 || levels > 4) {
        throw InvalidInput("subdivide: levels must be in [0, 4], got " + std::to_string(levels));
    }
    const std::size_t nt = coarse.triangles.size();
    if (coarse.uv.size() != nt || coarse.triangle_piece.size() != nt ||
        (!coarse.grain.empty() && coarse.grain.size() != nt)) {
        throw InvalidInput("subdivide: " + std::to_string(nt) + " triangles with " +
                           std::to_string(coarse.uv.size()) + " pattern triangles, " +
                           std::to_string(coarse.triangle_piece.size()) + " piece indices and " +
                           std::to_string(coarse.grain.size()) + " grain directions");
    }
    Subdivision s;
    s.mesh = coarse;
    s.coarse_triangle.assign(coarse.positions.size(), 0);
    s.barycentric.assign(coarse.positions.size(), {0, 0, 0});
    s.parent_triangle.resize(nt);
    std::vector<std::uint8_t> seen(coarse.positions.size(), 0);
    // Per triangle corner: barycentric coordinates in the parent coarse triangle.
    std::vector<std::array<std::array<double, 3>, 3>> corner_bary(nt);
    for (std::size_t f = 0; f < nt; ++f) {
        s.parent_triangle[f] = std::uint32_t(f);
        corner_bary[f] = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = coarse.triangles[f][std::size_t(k)];
            if (v >= coarse.positions.size()) {
                throw InvalidInput("subdivide: triangle " + std::to_string(f) + " names vertex " +
                                   std::to_string(v) + " of " +
                                   std::to_string(coarse.positions.size()));
            }
            if (!seen[v]) {
                seen[v] = 1;
                s.coarse_triangle[v] = std::uint32_t(f);
                s.barycentric[v] = corner_bary[f][std::size_t(k)];
            }
        }
    }
    for (int level = 0; level < levels; ++level) {
        const garment::GarmentMesh& m = s.mesh;
        garment::GarmentMesh next;
        next.positions = m.positions;
        next.piece_names = m.piece_names;
        std::unordered_map<std::uint64_t, std::uint32_t> midpoint;
        midpoint.reserve(m.triangles.size() * 2);
        std::vector<std::uint32_t> parent;
        std::vector<std::array<std::array<double, 3>, 3>> next_bary;
        parent.reserve(m.triangles.size() * 4);
        for (std::size_t f = 0; f < m.triangles.size(); ++f) {
            const garment::Tri& t = m.triangles[f];
            const auto& u = m.uv[f];
            const auto& b = corner_bary[f];
            std::array<std::uint32_t, 3> mid{};
            std::array<garment::UV, 3> mid_uv{};
            std::array<std::array<double, 3>, 3> mid_b{};
            for (int e = 0; e < 3; ++e) {  // edge e joins corners e and e+1
                const int e1 = (e + 1) % 3;
                const std::uint32_t a = t[std::size_t(e)], c = t[std::size_t(e1)];
                const std::uint64_t key = (std::uint64_t(std::min(a, c)) << 32) | std::max(a, c);
                auto it = midpoint.find(key);
                if (it == midpoint.end()) {
                    const std::uint32_t id = std::uint32_t(next.positions.size());
                    next.positions.push_back(
                        vec3::scale(vec3::add(m.positions[a], m.positions[c]), 0.5));
                    it = midpoint.emplace(key, id).first;
                    std::array<double, 3> bb{};
                    for (int i = 0; i < 3; ++i) {
                        bb[std::size_t(i)] = 0.5 * (b[std::size_t(e)][std::size_t(i)] +
                                                    b[std::size_t(e1)][std::size_t(i)]);
                    }
                    s.coarse_triangle.push_back(s.parent_triangle[f]);
                    s.barycentric.push_back(bb);
                }
                mid[std::size_t(e)] = it->second;
                mid_uv[std::size_t(e)] = {0.5 * (u[std::size_t(e)][0] + u[std::size_t(e1)][0]),
                                          0.5 * (u[std::size_t(e)][1] + u[std::size_t(e1)][1])};
                for (int i = 0; i < 3; ++i) {
                    mid_b[std::size_t(e)][std::size_t(i)] =
                        0.5 *
                        (b[std::size_t(e)][std::size_t(i)] + b[std::size_t(e1)][std::size_t(i)]);
                }
            }
            // Corner triangles (corner k with the midpoints of its two edges), then the middle.
            const std::array<std::array<int, 3>, 3> corner_tris{{{0, 0, 2}, {1, 1, 0}, {2, 2, 1}}};
            for (int k = 0; k < 3; ++k) {
                const int prev = corner_tris[std::size_t(k)][2];  // edge ending at corner k
                next.triangles.push_back(
                    {t[std::size_t(k)], mid[std::size_t(k)], mid[std::size_t(prev)]});
                next.uv.push_back(
                    {u[std::size_t(k)], mid_uv[std::size_t(k)], mid_uv[std::size_t(prev)]});
                next_bary.push_back(
                    {b[std::size_t(k)], mid_b[std::size_t(k)], mid_b[std::size_t(prev)]});
            }
            next.triangles.push_back({mid[0], mid[1], mid[2]});
            next.uv.push_back({mid_uv[0], mid_uv[1], mid_uv[2]});
            next_bary.push_back({mid_b[0], mid_b[1], mid_b[2]});
            for (int k = 0; k < 4; ++k) {
                next.triangle_piece.push_back(m.triangle_piece[f]);
                if (!m.grain.empty()) {
                    next.grain.push_back(m.grain[f]);
                }
                parent.push_back(s.parent_triangle[f]);
            }
        }
        s.mesh = std::move(next);
        s.parent_triangle = std::move(parent);
        corner_bary = std::move(next_bary);
    }
    return s;
}

}  // namespace tapeline::wrinkles
