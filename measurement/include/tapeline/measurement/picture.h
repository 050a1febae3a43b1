// A picture of a measured body (SVG or PNG): front and side orthographic views of the body with
// every tape loop, every path along the skin and every landmark drawn, and each measurement
// labelled with its name and value beside the figure, a leader line pointing at its tape.
//
// Views. Front: the figure faces the viewer, as a tailor sees a client (the body's right hand is on
// the picture's left; canonical +x, the body's left, to the right). Side: seen from the body's
// left, next to the front view (canonical -z to the right, so the figure faces left and its back is
// towards the right-hand labels). Both are orthographic at `scale` picture mm per body mm, floors
// aligned.
//
// Body. Rendered by the drawing module's mesh renderer (draw/mesh_render.h: a z-buffer, so no
// painter's-order artefacts where arms cross the torso; Gouraud-interpolated vertex normals and
// Lambert shading in grey, lit from the viewer's upper left). The PNG draws it at its resolution;
// the SVG embeds it per view as a small PNG image (a few tens of kB where the 26k triangles as
// vector paths would be megabytes), everything else in the SVG is vector: tapes, leaders, labels
// (escaped with core's xml_escape) and landmarks.
//
// Tapes. Every segment is tested against the z-buffer at its midpoint (the renderer's hidden-line
// test): farther than hidden_tolerance_mm behind the skin seen in a 3 × 3 pixel neighbourhood
// counts as hidden.
// Each path is drawn whole, thin, dashed and faint, and its visible runs solid over it. Each
// measurement is labelled once, in the view where its tape is longest and most visible (front
// view: in the column on the side of the body its tape lies; side view: to the right); labels of a
// column are sorted by height and spread so that they do not overlap.
//
// SVG structure, for programs: one <g class="measurement" data-name=... data-value-mm=...> per
// measurement, holding per view one <polygon> (loops) or <polyline> (paths) with
// class="tape" data-measurement=... data-view="front"|"side" and one point per measurement point,
// the visible runs (class="tape-visible"), the leader (class="leader") and the label
// (class="label"). Landmarks are <circle class="landmark" data-landmark=... data-view=...>.
#pragma once

#include <tapeline/core/atomic_write.h>
#include <tapeline/core/errors.h>
#include <tapeline/core/vec2.h>
#include <tapeline/draw/canvas.h>
#include <tapeline/draw/mesh_render.h>
#include <tapeline/draw/png.h>
#include <tapeline/draw/svg.h>
#include <tapeline/measurement/body.h>
#include <tapeline/measurement/measurement_types.h>
#include <tapeline/measurement/picture_types.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace tapeline::measurement {

namespace internal::pic {

using Point = tapeline::Vec2;
using draw::mix;
using draw::Rgb;
using draw::svg_colour;
using draw::xml_escape;

inline double vdot(const Vec3& a, const Vec3& b) {
    return vec3::dot(a, b);
}

inline Rgb palette(std::size_t i) {
    static const Rgb colours[] = {{0.84, 0.10, 0.10}, {0.10, 0.40, 0.85}, {0.05, 0.55, 0.20},
                                  {0.90, 0.45, 0.00}, {0.55, 0.20, 0.75}, {0.00, 0.55, 0.60},
                                  {0.80, 0.10, 0.55}, {0.45, 0.33, 0.10}, {0.20, 0.20, 0.60},
                                  {0.50, 0.50, 0.00}};
    return colours[i % (sizeof colours / sizeof colours[0])];
}

/// A number for SVG attributes: two decimals, trailing zeros dropped.
inline std::string num(double v) {
    return draw::svg_number(v, 2);
}

/// One view: what the report says of it and its rendering (projection from body mm to picture
/// mm, the z-buffered body at r pixels per picture mm, transparent where no body).
struct ViewRender {
    PictureView view;
    draw::RenderedView render;

    Point local(const Vec3& p) const { return render.view.local(p); }
    Point page(const Vec3& p) const { return render.view.page(p); }
    /// Whether p is no more than `tol` body mm behind the skin seen around its pixel.
    bool visible(const Vec3& p, double tol) const { return render.visible(p, tol); }
};

/// A measurement as drawn: per view its whole path and its visible runs (page mm), its label.
struct Drawn {
    const Measurement* m = nullptr;
    Rgb colour{0, 0, 0};
    std::array<std::vector<Point>, 2> path;
    std::array<std::vector<std::vector<Point>>, 2> visible_runs;
    PictureLabel label;
    int view = 0, column = 0;
    Vec3 anchor{0, 0, 0};
};

struct DrawnLandmark {
    const Landmark* l = nullptr;
    std::array<Point, 2> at;
    std::array<bool, 2> visible{true, true};
};

/// Everything placed on the page, ready for either writer.
struct Scene {
    PictureReport report;
    std::array<ViewRender, 2> views;
    std::vector<Drawn> drawn;
    std::vector<DrawnLandmark> landmarks;
    double scale_bar_mm = 0, scale_bar_body_mm = 0;
    Point scale_bar_at{0, 0};
    std::array<Point, 2> caption_at{};
    std::array<std::string, 2> captions{"front", "side (from the body's left)"};
    Point title_at{0, 0};
    std::string title;
};

inline std::string label_text(const Measurement& m) {
    char s[64];
    if (m.kind == MeasurementKind::angle) {
        std::snprintf(s, sizeof s, " %.1f deg", m.value);
    } else {
        std::snprintf(s, sizeof s, " %.1f mm", m.value);
    }
    return m.name + s;
}

inline bool finite_points(const std::vector<Vec3>& pts) {
    for (const auto& p : pts) {
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
            return false;
        }
    }
    return !pts.empty();
}

/// Lays out the page and renders the body at `r` pixels per picture mm; positions snap to that
/// pixel grid so that a PNG page can take the view images as they are.
inline Scene make_scene(const std::vector<Vec3>& pts, const PictureTriangles& tris,
                        const MeasurementSet& set, const LandmarkSet& landmarks,
                        const PictureOptions& o, double r) {
    const auto positive = [](double v) { return v > 0 && std::isfinite(v); };
    if (!positive(o.scale) || !positive(o.font_size_mm) || !positive(r) || !(o.margin_mm >= 0) ||
        !(o.hidden_tolerance_mm >= 0)) {
        throw InvalidInput(
            "measurement picture: scale, font size and resolution must be positive, margin and "
            "hidden tolerance not negative");
    }
    if (pts.empty() || tris.empty()) {
        throw InvalidInput("measurement picture: empty body mesh (" + std::to_string(pts.size()) +
                           " vertices, " + std::to_string(tris.size()) + " triangles)");
    }
    draw::check_triangles(pts.size(), tris, "measurement picture");
    Scene s;
    s.title = o.title;
    const double fs = o.font_size_mm, line_h = 1.45 * fs;
    const auto snap = [r](double mm) { return std::round(mm * r) / r; };

    s.views[0].view.name = "front";
    s.views[0].view.right = draw::front_view().right;
    s.views[0].view.toward_viewer = draw::front_view().toward_viewer;
    s.views[1].view.name = "side";
    s.views[1].view.right = draw::left_side_view().right;
    s.views[1].view.toward_viewer = draw::left_side_view().toward_viewer;
    // Bounds of everything drawn, per view.
    std::array<double, 2> u_min{}, u_max{};
    double y_max = 0;
    for (int k = 0; k < 2; ++k) {
        u_min[k] = std::numeric_limits<double>::infinity();
        u_max[k] = -u_min[k];
    }
    const auto extend = [&](const Vec3& p) {
        for (int k = 0; k < 2; ++k) {
            const double u = vdot(p, s.views[k].view.right);
            u_min[k] = std::min(u_min[k], u);
            u_max[k] = std::max(u_max[k], u);
        }
        y_max = std::max(y_max, p[1]);
    };
    for (const auto& p : pts) {
        extend(p);
    }
    for (const auto& m : set.measurements) {
        if (finite_points(m.points)) {
            for (const auto& p : m.points) {
                extend(p);
            }
        }
    }
    if (!std::isfinite(u_min[0]) || !std::isfinite(u_max[1]) || !std::isfinite(y_max)) {
        throw InvalidInput("measurement picture: the body mesh has non-finite coordinates");
    }
    std::array<draw::OrthoView, 2> ortho;
    for (int k = 0; k < 2; ++k) {
        ViewRender& v = s.views[k];
        ortho[k].right = v.view.right;
        ortho[k].toward_viewer = v.view.toward_viewer;
        ortho[k].scale = o.scale;
        ortho[k].u_min = u_min[k];
        ortho[k].v_max = y_max;
        v.view.width_mm = o.scale * (u_max[k] - u_min[k]);
        v.view.height_mm = o.scale * y_max;
    }
    for (const auto& v : s.views) {
        const double px = (v.view.width_mm * r + 1) * (v.view.height_mm * r + 1);
        if (!(px <= o.max_megapixels * 1e6)) {
            throw InvalidInput("measurement picture: the " + v.view.name + " view would be " +
                               std::to_string(long(px / 1e6)) + " Mpx, over the limit of " +
                               std::to_string(o.max_megapixels) +
                               " Mpx; lower the resolution or the scale");
        }
    }
    const std::vector<Vec3> normals = draw::vertex_normals(pts, tris);
    for (int k = 0; k < 2; ++k) {
        ViewRender& v = s.views[k];
        v.render =
            draw::render_mesh(ortho[k], v.view.width_mm, v.view.height_mm, r, pts, tris, normals);
    }

    // Which view and column each measurement is labelled in, and its anchor.
    const double front_mid = 0.5 * (u_min[0] + u_max[0]);
    for (const auto& m : set.measurements) {
        if (!finite_points(m.points)) {
            continue;
        }
        Drawn d;
        d.m = &m;
        d.colour = palette(s.drawn.size());
        const std::size_t n = m.points.size();
        const std::size_t segs = m.closed ? n : n - 1;
        double best = -1;
        for (int k = 0; k < 2; ++k) {
            double len = 0, seen = 0;
            for (std::size_t i = 0; i < segs; ++i) {
                const Vec3& a = m.points[i];
                const Vec3& b = m.points[(i + 1) % n];
                const Point pa = s.views[k].local(a), pb = s.views[k].local(b);
                const double l = distance(pa, pb);
                const Vec3 mid{0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2])};
                len += l;
                seen += s.views[k].visible(mid, o.hidden_tolerance_mm) ? l : 0;
            }
            const double score = len * (0.25 + (len > 0 ? seen / len : 1.0));
            if (score > best * 1.05) {  // ties stay in the front view
                best = score;
                d.view = k;
            }
        }
        const ViewRender& v = s.views[d.view];
        std::vector<Vec3> candidates;
        for (const auto& p : m.points) {
            if (v.visible(p, o.hidden_tolerance_mm)) {
                candidates.push_back(p);
            }
        }
        if (candidates.empty()) {
            candidates = m.points;
        }
        double mean_u = 0;
        for (const auto& p : candidates) {
            mean_u += vdot(p, v.view.right) / double(candidates.size());
        }
        d.column = d.view == 1 ? 2 : (mean_u < front_mid ? 0 : 1);
        if (m.kind == MeasurementKind::height) {
            d.anchor = m.points.back();
        } else {
            d.anchor = candidates.front();
            for (const auto& p : candidates) {
                const double u = vdot(p, v.view.right), ua = vdot(d.anchor, v.view.right);
                if (d.column == 0 ? u < ua : u > ua) {
                    d.anchor = p;
                }
            }
        }
        d.label.measurement = m.name;
        d.label.text = label_text(m);
        d.label.view = v.view.name;
        s.drawn.push_back(std::move(d));
    }

    // Columns and views from left to right.
    std::array<double, 3> col_w{0, 0, 0};
    std::array<std::size_t, 3> col_n{0, 0, 0};
    for (const auto& d : s.drawn) {
        col_w[std::size_t(d.column)] =
            std::max(col_w[std::size_t(d.column)], draw::Canvas::text_width_mm(d.label.text, fs));
        ++col_n[std::size_t(d.column)];
    }
    const double leader = 12;  // room for the leader's slanted part
    for (int c = 0; c < 3; ++c) {
        col_w[c] = col_n[c] ? col_w[c] + leader + 2 : 10;
    }
    const double title_h = o.title.empty() ? 0 : 2.4 * fs;
    const double top = snap(o.margin_mm + title_h + 2.2 * fs);
    double x = o.margin_mm;
    std::array<double, 3> col_x{};
    col_x[0] = x;
    x += col_w[0];
    s.views[0].view.left_mm = snap(x);
    x = s.views[0].view.left_mm + s.views[0].view.width_mm;
    col_x[1] = x;
    x += col_w[1];
    s.views[1].view.left_mm = snap(x);
    x = s.views[1].view.left_mm + s.views[1].view.width_mm;
    col_x[2] = x;
    x += col_w[2];
    const double page_w = x + o.margin_mm;
    for (auto& v : s.views) {
        v.view.top_mm = top;
        v.view.origin_x_mm = v.view.left_mm - o.scale * v.render.view.u_min;
        v.view.origin_y_mm = v.view.top_mm + o.scale * v.render.view.v_max;
        v.render.view.offset_mm = {v.view.left_mm, v.view.top_mm};
    }
    const double view_h = s.views[0].view.height_mm;
    double bottom = top + view_h;

    // Labels: sorted by anchor height per column, pushed apart to line_h, kept inside the page.
    for (int c = 0; c < 3; ++c) {
        std::vector<Drawn*> col;
        for (auto& d : s.drawn) {
            if (d.column == c) {
                col.push_back(&d);
            }
        }
        for (Drawn* d : col) {
            const Point a = s.views[d->view].page(d->anchor);
            d->label.anchor_x_mm = a.x;
            d->label.anchor_y_mm = a.y;
        }
        std::stable_sort(col.begin(), col.end(), [](const Drawn* a, const Drawn* b) {
            return a->label.anchor_y_mm < b->label.anchor_y_mm;
        });
        const double lo = top + fs;
        double y = lo - line_h;
        for (Drawn* d : col) {
            y = std::max(y + line_h, d->label.anchor_y_mm + 0.35 * fs);
            d->label.y_mm = y;
        }
        const double hi = std::max(bottom, lo + line_h * double(col.size()));
        double limit = hi;
        for (auto it = col.rbegin(); it != col.rend(); ++it) {
            (*it)->label.y_mm = std::min((*it)->label.y_mm, limit);
            limit = (*it)->label.y_mm - line_h;
        }
        for (Drawn* d : col) {
            bottom = std::max(bottom, d->label.y_mm);
            d->label.x_mm = c == 0 ? col_x[0] + col_w[0] - leader : col_x[std::size_t(c)] + leader;
        }
    }

    // Paths, visible runs and landmarks in page millimetres.
    for (auto& d : s.drawn) {
        const Measurement& m = *d.m;
        for (int k = 0; k < 2; ++k) {
            const ViewRender& v = s.views[k];
            for (const auto& p : m.points) {
                d.path[k].push_back(v.page(p));
            }
            d.visible_runs[k] = v.render.visible_runs(m.points, m.closed, o.hidden_tolerance_mm);
        }
        s.report.labels.push_back(d.label);
    }
    for (const auto& l : landmarks.landmarks) {
        if (!l.available() || !finite_points({l.point})) {
            continue;
        }
        DrawnLandmark dl;
        dl.l = &l;
        for (int k = 0; k < 2; ++k) {
            dl.at[k] = s.views[k].page(l.point);
            dl.visible[k] = s.views[k].visible(l.point, o.hidden_tolerance_mm);
        }
        s.landmarks.push_back(dl);
    }

    // Scale bar under the front view, captions above the views, title at the top.
    s.scale_bar_body_mm = 100;
    for (double len : {200.0, 500.0, 1000.0}) {
        if (o.scale * len <= std::max(s.views[0].view.width_mm, 30.0)) {
            s.scale_bar_body_mm = len;
        }
    }
    s.scale_bar_mm = o.scale * s.scale_bar_body_mm;
    s.scale_bar_at = {s.views[0].view.left_mm, bottom + 2.5 * fs};
    bottom = s.scale_bar_at.y + 2 * fs;
    for (int k = 0; k < 2; ++k) {
        s.caption_at[k] = {s.views[k].view.left_mm + 0.5 * s.views[k].view.width_mm,
                           top - 0.8 * fs};
    }
    s.title_at = {o.margin_mm, o.margin_mm + 1.6 * fs};

    PictureReport& rep = s.report;
    rep.width_mm = std::ceil(page_w);
    rep.height_mm = std::ceil(bottom + o.margin_mm);
    rep.scale = o.scale;
    rep.views = {s.views[0].view, s.views[1].view};
    rep.measurements_drawn = s.drawn.size();
    rep.landmarks_drawn = s.landmarks.size();
    return s;
}

inline std::string points_attr(const std::vector<Point>& pts) {
    return draw::svg_points(pts, 2);
}

/// Leader from the label's end to the tape: horizontal stub, then straight to the anchor.
inline std::vector<Point> leader_points(const Drawn& d, double fs) {
    const PictureLabel& l = d.label;
    const double y = l.y_mm - 0.35 * fs;
    const bool left = d.column == 0;
    const double x0 = left ? l.x_mm + 1 : l.x_mm - 1;
    const double x1 = left ? l.x_mm + 4 : l.x_mm - 4;
    return {{x0, y}, {x1, y}, {l.anchor_x_mm, l.anchor_y_mm}};
}

}  // namespace internal::pic

/// The picture as SVG (see the file comment); points and triangles are the body in canonical mm.
///
/// \throws InvalidInput when a scale, font size or resolution is not positive, a margin or
///         the hidden tolerance is negative, the mesh is empty or has non-finite
///         coordinates, a triangle names a missing point, or a view would exceed
///         `o.max_megapixels`.
inline PictureReport write_measurement_svg(std::ostream& out, const std::vector<Vec3>& points,
                                           const PictureTriangles& triangles,
                                           const MeasurementSet& set, const LandmarkSet& landmarks,
                                           const PictureOptions& o = {}) {
    using namespace internal::pic;
    const Scene s = make_scene(points, triangles, set, landmarks, o, o.svg_shading_pixels_per_mm);
    const double fs = o.font_size_mm;
    std::ostringstream svg;
    draw::svg_open(svg, num(s.report.width_mm), num(s.report.height_mm), "mm",
                   " xmlns:xlink=\"http://www.w3.org/1999/xlink\"", " font-family=\"sans-serif\"");
    svg << "<title>" << xml_escape(o.title.empty() ? "body measurements" : o.title) << "</title>\n";
    svg << "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
    if (!s.title.empty()) {
        svg << "<text class=\"title\" x=\"" << num(s.title_at.x) << "\" y=\"" << num(s.title_at.y)
            << "\" font-size=\"" << num(1.6 * fs) << "\">" << xml_escape(s.title) << "</text>\n";
    }
    svg << "<g id=\"views\">\n";
    for (int k = 0; k < 2; ++k) {
        const ViewRender& v = s.views[k];
        svg << "<text class=\"caption\" x=\"" << num(s.caption_at[k].x) << "\" y=\""
            << num(s.caption_at[k].y) << "\" font-size=\"" << num(1.25 * fs)
            << "\" text-anchor=\"middle\">" << xml_escape(s.captions[k]) << "</text>\n";
        svg << "<image class=\"body\" data-view=\"" << v.view.name << "\" x=\""
            << num(v.view.left_mm) << "\" y=\"" << num(v.view.top_mm) << "\" width=\""
            << num(double(v.render.image.width) / v.render.pixels_per_mm) << "\" height=\""
            << num(double(v.render.image.height) / v.render.pixels_per_mm)
            << "\" preserveAspectRatio=\"none\" xlink:href=\""
            << draw::png_data_uri(v.render.image, v.render.pixels_per_mm) << "\"/>\n";
    }
    svg << "</g>\n<g id=\"measurements\" fill=\"none\" stroke-linejoin=\"round\" "
           "stroke-linecap=\"round\">\n";
    for (const Drawn& d : s.drawn) {
        const Measurement& m = *d.m;
        const std::string c = svg_colour(d.colour);
        char value[32];
        std::snprintf(value, sizeof value, "%.2f", m.value);
        svg << "<g class=\"measurement\" id=\"m-" << xml_escape(m.name) << "\" data-name=\""
            << xml_escape(m.name) << "\" data-kind=\"" << to_string(m.kind) << "\" data-value"
            << (m.kind == MeasurementKind::angle ? "-degrees" : "-mm") << "=\"" << value
            << "\">\n<title>" << xml_escape(d.label.text) << "</title>\n";
        for (int k = 0; k < 2; ++k) {
            const char* view = k == 0 ? "front" : "side";
            svg << '<' << (m.closed ? "polygon" : "polyline")
                << " class=\"tape\" data-measurement=\"" << xml_escape(m.name) << "\" data-view=\""
                << view << "\" stroke=\"" << svg_colour(mix(d.colour, {1, 1, 1}, 0.35))
                << "\" stroke-width=\"0.3\" stroke-dasharray=\"1.2,0.9\" points=\""
                << points_attr(d.path[k]) << "\"/>\n";
            for (const auto& run : d.visible_runs[k]) {
                svg << "<polyline class=\"tape-visible\" data-view=\"" << view << "\" stroke=\""
                    << c << "\" stroke-width=\"0.6\" points=\"" << points_attr(run) << "\"/>\n";
            }
        }
        svg << "<polyline class=\"leader\" stroke=\"" << c << "\" stroke-width=\"0.2\" points=\""
            << points_attr(leader_points(d, fs)) << "\"/>\n";
        svg << "<text class=\"label\" x=\"" << num(d.label.x_mm) << "\" y=\"" << num(d.label.y_mm)
            << "\" font-size=\"" << num(fs) << "\" fill=\""
            << svg_colour(mix(d.colour, {0, 0, 0}, 0.3)) << "\" stroke=\"none\""
            << (d.column == 0 ? " text-anchor=\"end\"" : "") << '>' << xml_escape(d.label.text)
            << "</text>\n</g>\n";
    }
    svg << "</g>\n<g id=\"landmarks\" stroke=\"none\">\n";
    for (const DrawnLandmark& l : s.landmarks) {
        for (int k = 0; k < 2; ++k) {
            svg << "<circle class=\"landmark\" data-landmark=\"" << xml_escape(l.l->name)
                << "\" data-view=\"" << (k == 0 ? "front" : "side") << "\" cx=\"" << num(l.at[k].x)
                << "\" cy=\"" << num(l.at[k].y) << "\" r=\"" << (l.visible[k] ? "0.8" : "0.55")
                << "\" fill=\"" << (l.visible[k] ? "#990000" : "#e8a0a0") << "\"><title>"
                << xml_escape(l.l->name) << "</title></circle>\n";
        }
    }
    svg << "</g>\n";
    svg << "<rect class=\"scale-bar\" x=\"" << num(s.scale_bar_at.x) << "\" y=\""
        << num(s.scale_bar_at.y - 1.2) << "\" width=\"" << num(s.scale_bar_mm)
        << "\" height=\"1.2\" fill=\"#000000\"/>\n<text x=\""
        << num(s.scale_bar_at.x + s.scale_bar_mm + 2) << "\" y=\"" << num(s.scale_bar_at.y)
        << "\" font-size=\"" << num(fs) << "\">" << num(s.scale_bar_body_mm)
        << " mm (scale 1:" << num(1 / o.scale) << ")</text>\n";
    svg << "</svg>\n";
    const std::string text = svg.str();
    out << text;
    PictureReport rep = s.report;
    rep.format = PictureFormat::svg;
    rep.bytes = text.size();
    return rep;
}

/// The picture as an RGBA image at o.pixels_per_mm (see the file comment).
///
/// \throws InvalidInput when a scale, font size or resolution is not positive, a margin or
///         the hidden tolerance is negative, the mesh is empty or has non-finite
///         coordinates, a triangle names a missing point, or a view would exceed
///         `o.max_megapixels`.
inline draw::RgbaImage render_measurement_picture(
    const std::vector<Vec3>& points, const PictureTriangles& triangles, const MeasurementSet& set,
    const LandmarkSet& landmarks, const PictureOptions& o = {}, PictureReport* report = nullptr) {
    using namespace internal::pic;
    const double r = o.pixels_per_mm;
    const Scene s = make_scene(points, triangles, set, landmarks, o, r);
    const double w = std::ceil(s.report.width_mm * r), h = std::ceil(s.report.height_mm * r);
    if (w * h > o.max_megapixels * 1e6) {
        throw InvalidInput("measurement picture: " + std::to_string(long(w)) + " × " +
                           std::to_string(long(h)) + " pixels is over the limit of " +
                           std::to_string(o.max_megapixels) +
                           " Mpx; lower the resolution or the scale");
    }
    draw::RgbaImage img = draw::RgbaImage::filled(std::size_t(w), std::size_t(h), 255);
    draw::Canvas cv(img, r);
    const double fs = o.font_size_mm;
    const Rgb black{0, 0, 0};
    if (!s.title.empty()) {
        cv.text(s.title, s.title_at, 1.6 * fs, draw::TextAnchor::start, black);
    }
    for (int k = 0; k < 2; ++k) {
        const ViewRender& v = s.views[k];
        cv.text(s.captions[k], s.caption_at[k], 1.25 * fs, draw::TextAnchor::middle, black);
        cv.paste(v.render.image, std::lround(v.view.left_mm * r), std::lround(v.view.top_mm * r));
    }
    for (const Drawn& d : s.drawn) {
        for (int k = 0; k < 2; ++k) {
            std::vector<Point> all = d.path[k];
            if (d.m->closed && !all.empty()) {
                all.push_back(all.front());
            }
            cv.polyline(all, 0.3, mix(d.colour, {1, 1, 1}, 0.35), 1.2, 0.9);
            for (const auto& run : d.visible_runs[k]) {
                cv.polyline(run, 0.6, d.colour);
            }
        }
    }
    for (const DrawnLandmark& l : s.landmarks) {
        for (int k = 0; k < 2; ++k) {
            cv.disc(l.at[k], l.visible[k] ? 0.8 : 0.55,
                    l.visible[k] ? Rgb{0.6, 0, 0} : Rgb{0.91, 0.63, 0.63});
        }
    }
    for (const Drawn& d : s.drawn) {
        cv.polyline(leader_points(d, fs), 0.2, d.colour);
        cv.text(d.label.text, {d.label.x_mm, d.label.y_mm}, fs,
                d.column == 0 ? draw::TextAnchor::end : draw::TextAnchor::start,
                mix(d.colour, {0, 0, 0}, 0.3));
    }
    cv.fill_rect({s.scale_bar_at.x, s.scale_bar_at.y - 1.2},
                 {s.scale_bar_at.x + s.scale_bar_mm, s.scale_bar_at.y}, black);
    cv.text(num(s.scale_bar_body_mm) + " mm (scale 1:" + num(1 / o.scale) + ")",
            {s.scale_bar_at.x + s.scale_bar_mm + 2, s.scale_bar_at.y}, fs, draw::TextAnchor::start,
            black);
    if (report) {
        *report = s.report;
        report->format = PictureFormat::png;
        report->width_px = img.width;
        report->height_px = img.height;
    }
    return img;
}

/// The picture as PNG bytes written to `out`.
///
/// \throws InvalidInput as render_measurement_picture.
inline PictureReport write_measurement_png(std::ostream& out, const std::vector<Vec3>& points,
                                           const PictureTriangles& triangles,
                                           const MeasurementSet& set, const LandmarkSet& landmarks,
                                           const PictureOptions& o = {}) {
    PictureReport rep;
    rep.bytes =
        draw::write_png(out, render_measurement_picture(points, triangles, set, landmarks, o, &rep),
                        o.pixels_per_mm);
    return rep;
}

/// Writes the picture to `path` atomically, SVG or PNG by its extension (picture_format).
///
/// \throws InvalidInput on an extension other than .svg or .png, as render_measurement_picture,
///         or naming `path` when it cannot be written; `path` is left untouched then.
inline PictureReport write_measurement_picture(
    const std::string& path, const std::vector<Vec3>& points, const PictureTriangles& triangles,
    const MeasurementSet& set, const LandmarkSet& landmarks, const PictureOptions& o = {}) {
    const PictureFormat format = picture_format(path, "measurement picture");
    PictureReport rep;
    write_file_atomically(
        path,
        [&](std::ostream& out) {
            rep = format == PictureFormat::svg
                      ? write_measurement_svg(out, points, triangles, set, landmarks, o)
                      : write_measurement_png(out, points, triangles, set, landmarks, o);
        },
        format == PictureFormat::png);
    return rep;
}

/// Same for a measured Body; throws as the overload above.
inline PictureReport write_measurement_picture(const std::string& path, const Body& body,
                                               const MeasurementSet& set,
                                               const LandmarkSet& landmarks,
                                               const PictureOptions& o = {}) {
    return write_measurement_picture(path, body.points(), body.triangles(), set, landmarks, o);
}

/// A CGAL triangle mesh (FaceListGraph; named parameter vertex_point_map) in the canonical frame
/// it was measured in: the picture functions' input. Faces with other than three vertices are a
/// TopologyError, as in make_body.
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `VertexListGraph` with dynamic vertex and
///         face properties (CGAL::Surface_mesh, CGAL::Polyhedron_3, ...).
/// \tparam NamedParameters a sequence of CGAL named parameters; accepted: `vertex_point_map`
///         (a `ReadablePropertyMap` vertex_descriptor -> a point with x(), y(), z()).
/// \throws TopologyError when a face does not have three vertices.
/// \throws InvalidInput when the mesh is beyond 32-bit indices.
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
PictureMesh picture_mesh(const TriangleMesh& tm, const BodyFrame& frame,
                         const NamedParameters& np = CGAL::parameters::default_values()) {
    auto [points, tris] = internal::triangle_soup(tm, "measurement picture", np);
    PictureMesh out;
    out.points = std::move(points);
    for (Vec3& p : out.points) {
        p = frame.to_canonical(p);
    }
    out.triangles = std::move(tris);
    return out;
}

}  // namespace tapeline::measurement
