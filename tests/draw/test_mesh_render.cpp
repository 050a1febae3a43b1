// The mesh renderer (draw/mesh_render.h) on a unit cube, whose picture is known exactly: seen
// from the front it covers precisely the pixels whose centres fall in its projected square, at the
// depth of its front face; the nearer of two overlapping squares wins whichever is drawn first;
// seen along a body diagonal (isometric) the three edges at the far corner are hidden and the
// other nine visible, and drawn through visible_runs the hidden ones leave no ink.
#include <tapeline/core/errors.h>
#include <tapeline/draw/mesh_render.h>

#include <tapeline_test/image.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

using namespace tapeline::draw;
using tapeline::Vec2;

namespace {

/// The cube [-0.5, 0.5]³, faces outward, two triangles each.
struct Cube {
    std::vector<Vec3> points;
    MeshTriangles triangles;
    Cube() {
        for (int i = 0; i < 8; ++i) {
            points.push_back({i & 1 ? 0.5 : -0.5, i & 2 ? 0.5 : -0.5, i & 4 ? 0.5 : -0.5});
        }
        // Quads by corner index (bit 0: x, bit 1: y, bit 2: z), counter-clockwise from outside.
        const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                 {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
        for (const auto& q : quads) {
            triangles.push_back({std::uint32_t(q[0]), std::uint32_t(q[1]), std::uint32_t(q[2])});
            triangles.push_back({std::uint32_t(q[0]), std::uint32_t(q[2]), std::uint32_t(q[3])});
        }
    }
    /// The 12 edges as corner pairs (corners differing in one bit).
    std::vector<std::array<int, 2>> edges() const {
        std::vector<std::array<int, 2>> out;
        for (int a = 0; a < 8; ++a) {
            for (int bit : {1, 2, 4}) {
                if (!(a & bit)) {
                    out.push_back({a, a | bit});
                }
            }
        }
        return out;
    }
};

}  // namespace

TEST(DrawMeshRender, CubeFromTheFrontCoversItsSquare) {
    const Cube cube;
    OrthoView v = front_view();
    v.scale = 20;  // picture mm per unit: the cube is 20 mm wide
    v.u_min = -1;  // x = -1 at the left edge: the cube spans view-local x 10..30 mm
    v.v_max = 1;
    const RenderedView r = render_mesh(v, 40, 40, 1, cube.points, cube.triangles,
                                       vertex_normals(cube.points, cube.triangles));
    ASSERT_EQ(r.image.width, 41u);
    ASSERT_EQ(r.image.height, 41u);
    for (std::size_t y = 0; y < 41; ++y) {
        for (std::size_t x = 0; x < 41; ++x) {
            const bool inside = x >= 10 && x < 30 && y >= 10 && y < 30;
            SCOPED_TRACE(std::to_string(x) + ", " + std::to_string(y));
            ASSERT_EQ(r.image.pixel(x, y)[3], inside ? 255 : 0);
            const float z = r.depth[y * 41 + x];
            if (inside) {
                EXPECT_EQ(z, 0.5f);  // the front face, not the back one
                EXPECT_LT(r.image.pixel(x, y)[0], 255);
                EXPECT_GT(r.image.pixel(x, y)[0], 0);
            } else {
                EXPECT_EQ(z, -HUGE_VALF);
            }
        }
    }
    // A point on the back face, in the middle, is hidden; on the front face, visible.
    EXPECT_FALSE(r.visible({0, 0, -0.5}, 0.01));
    EXPECT_TRUE(r.visible({0, 0, 0.5}, 0.01));
    EXPECT_TRUE(r.visible({0, 0, -0.5}, 1.5));  // within the tolerance
}

TEST(DrawMeshRender, NearerSquareWinsInEitherOrder) {
    // Two unit squares facing the viewer, at z = 0 and z = 1, overlapping in x ∈ [0.5, 1].
    const std::vector<Vec3> pts = {{0, 0, 0},   {1, 0, 0},   {1, 1, 0},   {0, 1, 0},
                                   {0.5, 0, 1}, {1.5, 0, 1}, {1.5, 1, 1}, {0.5, 1, 1}};
    const MeshTriangles far = {{0, 1, 2}, {0, 2, 3}}, near = {{4, 5, 6}, {4, 6, 7}};
    OrthoView v;
    v.scale = 10;
    v.v_max = 1;
    for (const bool near_first : {false, true}) {
        MeshTriangles tris = near_first ? near : far;
        const MeshTriangles& second = near_first ? far : near;
        tris.insert(tris.end(), second.begin(), second.end());
        const RenderedView r = render_mesh(v, 15, 10, 1, pts, tris, vertex_normals(pts, tris));
        EXPECT_EQ(r.depth[5 * r.image.width + 7], 1.0f) << near_first;  // overlap
        EXPECT_EQ(r.depth[5 * r.image.width + 2], 0.0f) << near_first;  // far square alone
    }
}

TEST(DrawMeshRender, HiddenEdgesOfAnIsometricCubeAreNotDrawn) {
    const Cube cube;
    OrthoView v;
    // Looking from the corner (1, 1, 1): the far corner (-0.5, -0.5, -0.5) projects onto the near
    // one, its three edges run behind the three faces the viewer sees.
    v.toward_viewer = {1 / std::sqrt(3.0), 1 / std::sqrt(3.0), 1 / std::sqrt(3.0)};
    v.right = {1 / std::sqrt(2.0), 0, -1 / std::sqrt(2.0)};
    v.up = {-1 / std::sqrt(6.0), 2 / std::sqrt(6.0), -1 / std::sqrt(6.0)};
    v.scale = 40;
    v.u_min = -1;
    v.v_max = 1;
    const RenderedView r = render_mesh(v, 80, 80, 2, cube.points, cube.triangles,
                                       vertex_normals(cube.points, cube.triangles));
    RgbaImage img = RgbaImage::filled(160, 160, 255);
    Canvas cv(img, 2);
    std::size_t hidden = 0;
    std::vector<Vec2> hidden_midpoints, visible_midpoints;
    for (const auto& [a, b] : cube.edges()) {
        const std::vector<Vec3> edge = {cube.points[std::size_t(a)], cube.points[std::size_t(b)]};
        const auto runs = r.visible_runs(edge, false, 0.01);
        const Vec2 mid = 0.5 * (v.page(edge[0]) + v.page(edge[1]));
        SCOPED_TRACE(std::to_string(a) + "-" + std::to_string(b));
        if (a == 0) {  // the far corner's edges
            ++hidden;
            EXPECT_TRUE(runs.empty());
            hidden_midpoints.push_back(mid);
        } else {
            ASSERT_EQ(runs.size(), 1u);
            EXPECT_EQ(runs[0].size(), 2u);
            visible_midpoints.push_back(mid);
        }
        for (const auto& run : runs) {
            cv.polyline(run, 1, {0, 0, 0});
        }
    }
    EXPECT_EQ(hidden, 3u);
    const tapeline_test::Decoded d = tapeline_test::from_image(img);
    for (const Vec2& m : hidden_midpoints) {
        EXPECT_EQ(d.darkest(long(m.x * 2), long(m.y * 2)), 255) << m.x << ", " << m.y;
    }
    for (const Vec2& m : visible_midpoints) {
        EXPECT_LT(d.darkest(long(m.x * 2), long(m.y * 2)), 64) << m.x << ", " << m.y;
    }
}

TEST(DrawMeshRender, BadInputIsRefused) {
    const Cube cube;
    MeshTriangles bad = cube.triangles;
    bad[3][1] = 8;
    try {
        render_mesh({}, 10, 10, 1, cube.points, bad, vertex_normals(cube.points, cube.triangles));
        ADD_FAILURE();
    } catch (const tapeline::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("render_mesh: face 3 references vertex 8 of 8"),
                  std::string::npos)
            << e.what();
    }
    try {
        render_mesh({}, 10, 10, 1, cube.points, cube.triangles, {});
        ADD_FAILURE();
    } catch (const tapeline::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("0 normals for 8 points"), std::string::npos)
            << e.what();
    }
}
