// Orthographic pictures of triangle meshes: a z-buffer rasteriser (Catmull 1974; no
// painter's-order artefacts where parts of the mesh cross) with Gouraud-interpolated vertex normals
// and Lambert shading in one colour, lit from the viewer's upper left; and hidden-line tests of
// polylines in space against that z-buffer, so that tapes, seams or edges drawn over the mesh are
// split into the runs a viewer sees. The body pictures of measurement and the garment pictures
// built on them draw through it.
//
// Frames. A view projects a point p to view-local picture millimetres (x right, y down):
// (scale (p·right − u_min), scale (v_max − p·up)), and to page millimetres by adding the view's
// offset on the page. Depth is p·toward_viewer (larger is nearer). The rendered image covers the
// view-local box [0, width_mm] × [0, height_mm] at r pixels per mm: ceil(width_mm r) + 1 by
// ceil(height_mm r) + 1 pixels, so that the far edge of the box is inside; a pixel is covered when
// its centre lies in a projected triangle (edges inclusive).
//
// Hidden lines. A point is hidden when it lies more than `tolerance` (model units) behind the
// farthest of the surfaces seen in the 3 × 3 pixels around its own pixel; a point near the
// silhouette (a neighbour pixel empty) or outside the image is visible. A polyline segment is
// judged by its midpoint. The neighbourhood and the tolerance keep lines that lie on the surface,
// or bridge a hollow just outside it, from flickering between visible and hidden.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/core/phong.h>
#include <tapeline/core/vec2.h>
#include <tapeline/core/vec3.h>
#include <tapeline/draw/canvas.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace tapeline::draw {

using Vec3 = vec3::Vec3;
using MeshTriangles = std::vector<std::array<std::uint32_t, 3>>;

/// An orthographic projection onto picture millimetres (see the file comment).
struct OrthoView {
    Vec3 right{1, 0, 0};          ///< model direction drawn to the right
    Vec3 up{0, 1, 0};             ///< model direction drawn upwards
    Vec3 toward_viewer{0, 0, 1};  ///< model direction pointing at the viewer
    double scale = 1;             ///< picture mm per model unit
    double u_min = 0;             ///< p·right drawn at view-local x = 0
    double v_max = 0;             ///< p·up drawn at view-local y = 0
    Vec2 offset_mm{0, 0};         ///< where view-local (0, 0) sits on the page

    /// View-local picture millimetres of model point p (y down).
    Vec2 local(const Vec3& p) const {
        return {scale * (vec3::dot(p, right) - u_min), scale * (v_max - vec3::dot(p, up))};
    }
    /// Page millimetres of model point p.
    Vec2 page(const Vec3& p) const {
        const Vec2 l = local(p);
        return {offset_mm.x + l.x, offset_mm.y + l.y};
    }
    /// Distance of p towards the viewer (larger: nearer).
    double depth(const Vec3& p) const { return vec3::dot(p, toward_viewer); }
};

/// The figure facing the viewer (y up, +z towards the viewer, +x to the right).
inline OrthoView front_view() {
    return {};
}

/// Seen from +x (the figure's left when it faces +z): -z to the right.
inline OrthoView left_side_view() {
    OrthoView v;
    v.right = {0, 0, -1};
    v.toward_viewer = {1, 0, 0};
    return v;
}

/// Lambert shading in one colour: shade = ambient + diffuse max(0, n·l), the light l towards the
/// viewer, moved by `light_right` along the view's right and `light_up` along its up.
struct MeshShading {
    Rgb colour{0.86, 0.84, 0.82};  ///< base colour
    double ambient = 0.32;         ///< light everywhere
    double diffuse = 0.68;         ///< weight of n·l
    double light_right = -0.35;    ///< light direction offset along the view's right
    double light_up = 0.45;        ///< light direction offset along the view's up
};

/// A rendered view: the shaded mesh (transparent where there is none) and its depth buffer
/// (−infinity where there is none).
struct RenderedView {
    OrthoView view;            ///< the projection used
    double pixels_per_mm = 1;  ///< resolution
    RgbaImage image;           ///< the shaded mesh
    std::vector<float> depth;  ///< per pixel, row-major like `image`

    /// Whether p is no more than `tolerance` behind the surface seen around its pixel (see the
    /// file comment).
    bool visible(const Vec3& p, double tolerance) const {
        const Vec2 l = view.local(p);
        const long x = long(std::floor(l.x * pixels_per_mm));
        const long y = long(std::floor(l.y * pixels_per_mm));
        const double d = view.depth(p);
        double nearest = std::numeric_limits<double>::infinity();
        for (long yy = y - 1; yy <= y + 1; ++yy) {
            for (long xx = x - 1; xx <= x + 1; ++xx) {
                if (xx < 0 || yy < 0 || xx >= long(image.width) || yy >= long(image.height)) {
                    return true;
                }
                nearest = std::min(nearest,
                                   double(depth[std::size_t(yy) * image.width + std::size_t(xx)]));
            }
        }
        return !(nearest > -std::numeric_limits<double>::infinity()) || d >= nearest - tolerance;
    }

    /// The visible runs of a polyline in space (closed: its last point joins its first), in page
    /// millimetres; a segment is visible when its midpoint is.
    std::vector<std::vector<Vec2>> visible_runs(const std::vector<Vec3>& pts, bool closed,
                                                double tolerance) const {
        std::vector<std::vector<Vec2>> runs;
        const std::size_t n = pts.size();
        const std::size_t segs = n == 0 ? 0 : closed ? n : n - 1;
        std::vector<Vec2> run;
        for (std::size_t i = 0; i < segs; ++i) {
            const Vec3& a = pts[i];
            const Vec3& b = pts[(i + 1) % n];
            const Vec3 mid{0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2])};
            if (visible(mid, tolerance)) {
                if (run.empty()) {
                    run.push_back(view.page(a));
                }
                run.push_back(view.page(b));
            } else if (!run.empty()) {
                runs.push_back(std::move(run));
                run.clear();
            }
        }
        if (!run.empty()) {
            runs.push_back(std::move(run));
        }
        return runs;
    }
};

namespace internal {

/// p / |p| (divided, not multiplied by the reciprocal: the pictures' bytes depend on it), or zero.
inline Vec3 unit(const Vec3& p) {
    const double len = vec3::norm(p);
    return len > 0 ? Vec3{p[0] / len, p[1] / len, p[2] / len} : Vec3{0, 0, 0};
}

}  // namespace internal

/// Throws InvalidInput, naming `where`, for the first triangle that names a point at or beyond
/// `points`.
inline void check_triangles(std::size_t points, const MeshTriangles& tris,
                            const std::string& where) {
    for (std::size_t f = 0; f < tris.size(); ++f) {
        for (std::uint32_t v : tris[f]) {
            if (v >= points) {
                throw InvalidInput(where + ": face " + std::to_string(f) + " references vertex " +
                                   std::to_string(v) + " of " + std::to_string(points));
            }
        }
    }
}

/// Area-weighted vertex normals (tapeline/core/phong.h).
using tapeline::vertex_normals;

/// The mesh z-buffered and shaded in `view` over the view-local box width_mm × height_mm at
/// `pixels_per_mm` (see the file comment). `normals`: one per point (vertex_normals). Throws
/// InvalidInput for a triangle that names a point beyond `pts` (check_triangles) or a normal list
/// of another size.
///
/// \throws InvalidInput for a triangle naming a point beyond `pts`, or a normal count that
///         is not the point count.
inline RenderedView render_mesh(const OrthoView& view, double width_mm, double height_mm,
                                double pixels_per_mm, const std::vector<Vec3>& pts,
                                const MeshTriangles& tris, const std::vector<Vec3>& normals,
                                const MeshShading& shading = {}) {
    if (normals.size() != pts.size()) {
        throw InvalidInput("render_mesh: " + std::to_string(normals.size()) + " normals for " +
                           std::to_string(pts.size()) + " points");
    }
    check_triangles(pts.size(), tris, "render_mesh");
    RenderedView rv;
    rv.view = view;
    rv.pixels_per_mm = pixels_per_mm;
    const double r = pixels_per_mm;
    const std::size_t w = std::size_t(std::ceil(width_mm * r)) + 1;
    const std::size_t h = std::size_t(std::ceil(height_mm * r)) + 1;
    rv.image = RgbaImage::filled(w, h, 0);
    rv.depth.assign(w * h, -std::numeric_limits<float>::infinity());
    const Vec3& t = view.toward_viewer;
    const Vec3 light = internal::unit(
        {t[0] + shading.light_up * view.up[0] + shading.light_right * view.right[0],
         t[1] + shading.light_up * view.up[1] + shading.light_right * view.right[1],
         t[2] + shading.light_up * view.up[2] + shading.light_right * view.right[2]});
    const Rgb base = shading.colour;
    for (const auto& tri : tris) {
        Vec2 q[3];
        double d[3];
        for (int k = 0; k < 3; ++k) {
            const Vec2 l = view.local(pts[tri[k]]);
            q[k] = {l.x * r, l.y * r};
            d[k] = view.depth(pts[tri[k]]);
        }
        const double area =
            (q[1].x - q[0].x) * (q[2].y - q[0].y) - (q[1].y - q[0].y) * (q[2].x - q[0].x);
        if (area == 0 || !std::isfinite(area)) {
            continue;
        }
        const long x0 = std::max(0L, long(std::floor(std::min({q[0].x, q[1].x, q[2].x}))));
        const long x1 = std::min(long(w) - 1, long(std::ceil(std::max({q[0].x, q[1].x, q[2].x}))));
        const long y0 = std::max(0L, long(std::floor(std::min({q[0].y, q[1].y, q[2].y}))));
        const long y1 = std::min(long(h) - 1, long(std::ceil(std::max({q[0].y, q[1].y, q[2].y}))));
        for (long y = y0; y <= y1; ++y) {
            for (long x = x0; x <= x1; ++x) {
                const double px = x + 0.5, py = y + 0.5;
                double b[3];
                for (int k = 0; k < 3; ++k) {
                    const Vec2& a = q[(k + 1) % 3];
                    const Vec2& c = q[(k + 2) % 3];
                    b[k] = ((c.x - a.x) * (py - a.y) - (c.y - a.y) * (px - a.x)) / area;
                }
                if (b[0] < 0 || b[1] < 0 || b[2] < 0) {
                    continue;
                }
                const double z = b[0] * d[0] + b[1] * d[1] + b[2] * d[2];
                float& zb = rv.depth[std::size_t(y) * w + std::size_t(x)];
                if (z <= zb) {
                    continue;
                }
                zb = float(z);
                Vec3 n{0, 0, 0};
                for (int k = 0; k < 3; ++k) {
                    for (int c = 0; c < 3; ++c) {
                        n[c] += b[k] * normals[tri[k]][c];
                    }
                }
                n = internal::unit(n);
                if (vec3::dot(n, t) < 0) {
                    n = {-n[0], -n[1], -n[2]};  // seen through a hole: light it as a front face
                }
                const double shade =
                    shading.ambient + shading.diffuse * std::max(0.0, vec3::dot(n, light));
                std::uint8_t* p = &rv.image.rgba[4 * (std::size_t(y) * w + std::size_t(x))];
                p[0] = std::uint8_t(std::lround(255 * base.r * shade));
                p[1] = std::uint8_t(std::lround(255 * base.g * shade));
                p[2] = std::uint8_t(std::lround(255 * base.b * shade));
                p[3] = 255;
            }
        }
    }
    return rv;
}

}  // namespace tapeline::draw
