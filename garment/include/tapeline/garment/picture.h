// A picture of the dressed body: front, left side and back views side by side, the body shaded in
// skin colour, the garment shaded and coloured by its stretch against the pattern (blue: none,
// green ≤ 3 %, yellow ≤ 5 %, orange ≤ 10 %, red beyond), the seams drawn as dark lines where they
// are seen. Drawn through the drawing module's z-buffer renderer; the views are composited by
// depth so that body and garment hide each other correctly.
#pragma once

#include <tapeline/draw/canvas.h>
#include <tapeline/draw/mesh_render.h>
#include <tapeline/draw/png.h>
#include <tapeline/garment/quality.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace tapeline::garment {

/// Colour class of a stretch value (see the file comment).
inline draw::Rgb stretch_class_colour(double s) {
    if (s <= 1.01) {
        return {0.35, 0.55, 0.9};
    }
    if (s <= 1.03) {
        return {0.4, 0.8, 0.4};
    }
    if (s <= 1.05) {
        return {0.95, 0.85, 0.3};
    }
    if (s <= 1.10) {
        return {0.95, 0.55, 0.2};
    }
    return {0.9, 0.2, 0.2};
}

/// Front, left side and back views of `body` (may be empty) and the garment `g`, each garment
/// triangle shaded in `colours[triangle_class[f]]` (a class outside `colours`, or a triangle
/// beyond `triangle_class`, in the first colour), `seams` (polylines, canonical mm) drawn over
/// the garment where they are seen. At `pixels_per_mm` on a page where 1 mm of the body is
/// `scale` mm of picture. `legend`: a label per colour, drawn as a row of swatches under the
/// views (empty: none).
inline draw::RgbaImage garment_views_picture(
    const std::vector<Vec3>& body_points, const std::vector<Tri>& body_tris, const GarmentMesh& g,
    const std::vector<int>& triangle_class, const std::vector<draw::Rgb>& colours,
    const std::vector<std::vector<Vec3>>& seams, const std::string& title, double scale = 0.12,
    double pixels_per_mm = 5, const std::vector<std::string>& legend = {}) {
    std::vector<draw::OrthoView> views(3);
    views[1] = draw::left_side_view();
    views[2].right = {-1, 0, 0};
    views[2].toward_viewer = {0, 0, -1};
    const double margin = 6, title_h = 10;
    double x = margin, page_h = 0;
    std::vector<std::pair<double, double>> size(3);
    for (std::size_t k = 0; k < 3; ++k) {
        draw::OrthoView& v = views[k];
        v.scale = scale;
        double umin = 1e300, umax = -1e300, vmin = 1e300, vmax = -1e300;
        for (const auto* pts : {&body_points, &g.positions}) {
            for (const Vec3& p : *pts) {
                umin = std::min(umin, vec3::dot(p, v.right));
                umax = std::max(umax, vec3::dot(p, v.right));
                vmin = std::min(vmin, vec3::dot(p, v.up));
                vmax = std::max(vmax, vec3::dot(p, v.up));
            }
        }
        v.u_min = umin;
        v.v_max = vmax;
        v.offset_mm = {x, margin + title_h};
        size[k] = {(umax - umin) * scale, (vmax - vmin) * scale};
        x += size[k].first + margin;
        page_h = std::max(page_h, size[k].second);
    }
    const double page_w = x;
    const double legend_h = legend.empty() ? 0 : 8;
    page_h += 2 * margin + title_h + legend_h;
    draw::RgbaImage page =
        draw::RgbaImage::filled(std::size_t(std::ceil(page_w * pixels_per_mm)),
                                std::size_t(std::ceil(page_h * pixels_per_mm)), 255);
    draw::Canvas canvas(page, pixels_per_mm);
    canvas.text(title, {margin, margin + 5}, 4.5, draw::TextAnchor::start, {0.1, 0.1, 0.1});
    double lx = margin;
    const double ly = page_h - margin - 4;
    for (std::size_t k = 0; k < legend.size() && k < colours.size(); ++k) {
        canvas.fill_rect({lx, ly}, {lx + 4, ly + 4}, colours[k]);
        canvas.text(legend[k], {lx + 5.5, ly + 3.5}, 3.5, draw::TextAnchor::start, {0.1, 0.1, 0.1});
        lx += 8 + 2.2 * double(legend[k].size());
    }
    // Garment triangles grouped by colour class: one render per class.
    std::vector<draw::MeshTriangles> classes(std::max<std::size_t>(1, colours.size()));
    for (std::size_t f = 0; f < g.triangles.size(); ++f) {
        const int c = f < triangle_class.size() ? triangle_class[f] : 0;
        classes[c >= 0 && std::size_t(c) < classes.size() ? std::size_t(c) : 0].push_back(
            g.triangles[f]);
    }
    const auto body_normals = draw::vertex_normals(body_points, body_tris);
    const auto cloth_normals = draw::vertex_normals(g.positions, g.triangles);
    for (std::size_t k = 0; k < 3; ++k) {
        const draw::OrthoView& v = views[k];
        draw::OrthoView local = v;
        local.offset_mm = {0, 0};
        std::vector<draw::RenderedView> layers;
        draw::MeshShading skin;
        skin.colour = {0.87, 0.76, 0.68};
        layers.push_back(draw::render_mesh(local, size[k].first, size[k].second, pixels_per_mm,
                                           body_points, body_tris, body_normals, skin));
        for (std::size_t c = 0; c < classes.size(); ++c) {
            if (classes[c].empty()) {
                continue;
            }
            draw::MeshShading cloth;
            cloth.colour = c < colours.size() ? colours[c] : draw::Rgb{0.6, 0.6, 0.6};
            layers.push_back(draw::render_mesh(local, size[k].first, size[k].second, pixels_per_mm,
                                               g.positions, classes[c], cloth_normals, cloth));
        }
        // Composite by depth into the first layer.
        draw::RenderedView& out = layers[0];
        for (std::size_t l = 1; l < layers.size(); ++l) {
            for (std::size_t i = 0; i < out.depth.size(); ++i) {
                if (layers[l].depth[i] > out.depth[i]) {
                    out.depth[i] = layers[l].depth[i];
                    std::copy_n(&layers[l].image.rgba[4 * i], 4, &out.image.rgba[4 * i]);
                }
            }
        }
        const std::size_t ox = std::size_t(std::lround(v.offset_mm.x * pixels_per_mm));
        const std::size_t oy = std::size_t(std::lround(v.offset_mm.y * pixels_per_mm));
        for (std::size_t y = 0; y < out.image.height; ++y) {
            for (std::size_t xx = 0; xx < out.image.width; ++xx) {
                const std::uint8_t* p = out.image.pixel(xx, y);
                if (p[3] == 0 || oy + y >= page.height || ox + xx >= page.width) {
                    continue;
                }
                std::copy_n(p, 4, &page.rgba[4 * ((oy + y) * page.width + ox + xx)]);
            }
        }
        out.view = v;  // page coordinates for the seam runs
        for (const auto& seam : seams) {
            for (const auto& run : out.visible_runs(seam, false, 3.0)) {
                canvas.polyline(run, 0.35, {0.15, 0.15, 0.2});
            }
        }
    }
    return page;
}

/// The dressed body (see the file comment) at `pixels_per_mm` on a page where 1 mm of the body
/// is `scale` mm of picture; the garment coloured by `triangle_stretch` (stretch_class_colour).
/// `seams`: polylines (canonical mm) drawn over the garment.
inline draw::RgbaImage dressed_picture(const std::vector<Vec3>& body_points,
                                       const std::vector<Tri>& body_tris, const GarmentMesh& g,
                                       const std::vector<double>& triangle_stretch,
                                       const std::vector<std::vector<Vec3>>& seams,
                                       const std::string& title, double scale = 0.12,
                                       double pixels_per_mm = 5) {
    const double class_stretch[5] = {1.0, 1.02, 1.04, 1.08, 1.2};
    std::vector<draw::Rgb> colours;
    for (double s : class_stretch) {
        colours.push_back(stretch_class_colour(s));
    }
    std::vector<int> cls(g.triangles.size(), 0);
    for (std::size_t f = 0; f < g.triangles.size(); ++f) {
        const double s = f < triangle_stretch.size() ? triangle_stretch[f] : 1.0;
        cls[f] = s <= 1.01 ? 0 : s <= 1.03 ? 1 : s <= 1.05 ? 2 : s <= 1.10 ? 3 : 4;
    }
    return garment_views_picture(body_points, body_tris, g, cls, colours, seams, title, scale,
                                 pixels_per_mm);
}

}  // namespace tapeline::garment
