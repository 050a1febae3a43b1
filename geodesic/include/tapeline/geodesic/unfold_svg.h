// An unfolded path strip (unfold.h) as an SVG picture: the faces, the path mapped into the plane
// and the straight segment between its unfolded end points, with their lengths.
//
// No CGAL; write to a file with tapeline::write_file_atomically (core/atomic_write.h) so that a
// failure leaves no half-written picture.
#pragma once

#include <tapeline/core/xml_escape.h>
#include <tapeline/geodesic/unfold_types.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <ostream>
#include <string>

namespace tapeline::geodesic {

namespace internal {

inline std::string svg_escape(const std::string& text) {
    return xml_escape(text);
}

inline std::string svg_number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3f", v);
    return buf;
}

}  // namespace internal

/// Writes the strip as a standalone SVG document: faces (grey), the traced path (blue, through the
/// unfolded points), the straight segment between the unfolded end points (red, dashed), and a
/// caption with `title`, the traced and the straight lengths. `width`: picture width in pixels.
inline void write_unfold_svg(std::ostream& out, const UnfoldedPath& u,
                             const std::string& title = "", double width = 1200) {
    using internal::svg_number;
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
    auto X = [&](double x) { return svg_number(margin + (x - xmin) * scale); };
    auto Y = [&](double y) { return svg_number(caption + margin + (ymax - y) * scale); };
    out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << svg_number(width)
        << "\" height=\"" << svg_number(height) << "\" viewBox=\"0 0 " << svg_number(width) << ' '
        << svg_number(height) << "\">\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    const double gap = u.traced_length - u.straight_length;
    char line[256];
    std::snprintf(line, sizeof line,
                  "traced length %.12g | unfolded straight length %.12g | difference %.3e "
                  "(relative %.3e)",
                  u.traced_length, u.straight_length, gap,
                  u.straight_length > 0 ? gap / u.straight_length : 0.0);
    out << "<text x=\"" << margin << "\" y=\"22\" font-family=\"sans-serif\" font-size=\"15\">"
        << internal::svg_escape(title.empty() ? std::string("unfolded path strip") : title)
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
        out << "<polygon points=\"";
        for (int k = 0; k < 3; ++k)
            out << (k ? " " : "") << X(f.corners[k][0]) << ',' << Y(f.corners[k][1]);
        out << "\"/>\n";
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
        for (std::size_t k = 0; k < u.points.size(); ++k)
            out << (k ? " " : "") << X(u.points[k][0]) << ',' << Y(u.points[k][1]);
        out << "\"/>\n";
        for (const auto* p : {&a, &b})
            out << "<circle cx=\"" << X((*p)[0]) << "\" cy=\"" << Y((*p)[1])
                << "\" r=\"4\" fill=\"#2050c0\"/>\n";
    }
    out << "</svg>\n";
}

}  // namespace tapeline::geodesic
