// A rectangular garment piece as a grid of triangles, for the wrinkle tests.
#pragma once

#include <tapeline/garment/garment_types.h>

#include <cstdint>
#include <functional>
#include <string>

namespace tapeline::test {

/// nx × ny right-triangle cells of `cell` mm from (u0, v0) in the pattern, on piece `piece` (named
/// "pieceN" when the mesh has no name for it yet), placed by `place`; counter-clockwise in the
/// pattern.
inline void add_grid(garment::GarmentMesh& g, int nx, int ny, double cell, double u0, double v0,
                     std::uint32_t piece,
                     const std::function<garment::Vec3(double, double)>& place) {
    const auto base = std::uint32_t(g.positions.size());
    auto id = [&](int i, int j) { return base + std::uint32_t(j * (nx + 1) + i); };
    for (int j = 0; j <= ny; ++j) {
        for (int i = 0; i <= nx; ++i) {
            g.positions.push_back(place(u0 + i * cell, v0 + j * cell));
        }
    }
    auto uv = [&](int i, int j) { return garment::UV{u0 + i * cell, v0 + j * cell}; };
    for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
            g.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            g.uv.push_back({uv(i, j), uv(i + 1, j), uv(i + 1, j + 1)});
            g.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
            g.uv.push_back({uv(i, j), uv(i + 1, j + 1), uv(i, j + 1)});
            g.triangle_piece.push_back(piece);
            g.triangle_piece.push_back(piece);
        }
    }
    while (g.piece_names.size() <= piece) {
        g.piece_names.push_back("piece" + std::to_string(g.piece_names.size()));
    }
}

}  // namespace tapeline::test
