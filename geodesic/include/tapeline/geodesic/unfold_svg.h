// An unfolded path strip (unfold.h) as an SVG picture: the faces, the path mapped into the plane
// and the straight segment between its unfolded end points, with their lengths.
//
// No CGAL; the SVG helpers are the drawing module's (draw/svg.h). Write to a file with
// tapeline::write_file_atomically (core/atomic_write.h) so that a failure leaves no half-written
// picture.
#pragma once

#include <tapeline/draw/svg.h>
#include <tapeline/geodesic/unfold_types.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

namespace tapeline::geodesic {

/// Writes the strip as a standalone SVG document: faces (grey), the traced path (blue, through the
/// unfolded points), the straight segment between the unfolded end points (red, dashed), and a
/// caption with `title`, the traced and the straight lengths. `width`: picture width in pixels.
inline void write_unfold_svg(std::ostream& out, const UnfoldedPath& u,
                             const std::string& title = "", double width = 1200) {
    const auto svg_number = [](double v) { return draw::svg_fixed(v, 3); };
    double xmin = std::numeric_limits<double>::infinity(), ymin = xmin;
    double xmax = -xmin, ymax = -xmin;
    auto grow = [&](const std::array<double, 2>& p) {
        xmin = std::min(xmin, p[0]);
        xmax = std::max(xmax, p[0]);
        ymin = std::min(ymin, p[1]);
        ymax = std::max(ymax, p[1]);
    };
    for (const auto& f : u.faces)
        for (const auto& c : f.corners)
            grow(c);
    for (const auto& p : u.points)
        grow(p);
    if (!(xmax >= xmin)) {
        xmin = ymin = 0;
        xmax = ymax = 1;
    }
    const double margin = 20, caption = 70;
    const double span = std::max({xmax - xmin, ymax - ymin, 1e-300});
    const double scale = (width - 2 * margin) / span;
    const double height = (ymax - ymin) * scale + 2 * margin + caption;
    // Plane y up, SVG y down.
    auto P = [&](const std::array<double, 2>& p) {
        return tapeline::Vec2{margin + (p[0] - xmin) * scale,
                              caption + margin + (ymax - p[1]) * scale};
    };
    auto X = [&](double x) { return svg_number(margin + (x - xmin) * scale); };
    auto Y = [&](double y) { return svg_number(caption + margin + (ymax - y) * scale); };
    draw::svg_open(out, svg_number(width), svg_number(height), "");
    out << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    const double gap = u.traced_length - u.straight_length;
    char line[256];
    std::snprintf(line, sizeof line,
                  "traced length %.12g | unfolded straight length %.12g | difference %.3e "
                  "(relative %.3e)",
                  u.traced_length, u.straight_length, gap,
                  u.straight_length > 0 ? gap / u.straight_length : 0.0);
    out << "<text x=\"" << margin << "\" y=\"22\" font-family=\"sans-serif\" font-size=\"15\">"
        << draw::xml_escape(title.empty() ? std::string("unfolded path strip") : title)
        << "</text>\n"
        << "<text x=\"" << margin << "\" y=\"42\" font-family=\"sans-serif\" font-size=\"13\">"
        << line << "</text>\n";
    std::snprintf(line, sizeof line,
                  "%zu faces (%zu around touched vertices), %zu path points at vertices; straight "
                  "segment %s the strip",
                  u.faces.size(), u.fan_faces, u.vertex_points,
                  u.straight_inside ? "inside" : "leaves");
    out << "<text x=\"" << margin << "\" y=\"60\" font-family=\"sans-serif\" font-size=\"13\">"
        << line << "</text>\n";
    const double stroke = 1.0;
    out << "<g fill=\"#e8ecf4\" stroke=\"#8890a0\" stroke-width=\"" << stroke * 0.5
        << "\" stroke-linejoin=\"round\">\n";
    for (const auto& f : u.faces) {
        out << "<polygon points=\""
            << draw::svg_points({P(f.corners[0]), P(f.corners[1]), P(f.corners[2])}, 3, false)
            << "\"/>\n";
    }
    out << "</g>\n";
    if (!u.points.empty()) {
        const auto& a = u.points.front();
        const auto& b = u.points.back();
        out << "<line x1=\"" << X(a[0]) << "\" y1=\"" << Y(a[1]) << "\" x2=\"" << X(b[0])
            << "\" y2=\"" << Y(b[1]) << "\" stroke=\"#d03030\" stroke-width=\"" << stroke
            << "\" stroke-dasharray=\"6 4\"/>\n";
        out << "<polyline fill=\"none\" stroke=\"#2050c0\" stroke-width=\"" << 1.5 * stroke
            << "\" points=\"";
        std::vector<tapeline::Vec2> path;
        for (const auto& p : u.points)
            path.push_back(P(p));
        out << draw::svg_points(path, 3, false) << "\"/>\n";
        for (const auto* p : {&a, &b})
            out << "<circle cx=\"" << X((*p)[0]) << "\" cy=\"" << Y((*p)[1])
                << "\" r=\"4\" fill=\"#2050c0\"/>\n";
    }
    out << "</svg>\n";
}

}  // namespace tapeline::geodesic
