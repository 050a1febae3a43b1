// Options and report of the measurement picture (picture.h): front and side views of a body with
// its tape loops, skin paths and landmarks (DESIGN.md §3: a light header without CGAL).
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/measurement/body_types.h>

#include <array>
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace tapeline::measurement {

/// Triangles as three point indices each.
using PictureTriangles = std::vector<std::array<std::uint32_t, 3>>;

/// A body mesh in canonical millimetres, as the picture functions take it.
struct PictureMesh {
    std::vector<Vec3> points;    ///< canonical mm
    PictureTriangles triangles;  ///< indices into `points`
};

/// File format of a picture.
enum class PictureFormat { svg, png };

/// The format a picture path asks for by its extension (.svg or .png, any case); anything else is
/// InvalidInput naming `where` (e.g. "--picture") and the path, so a tool can refuse it before
/// doing any work.
///
/// \throws InvalidInput when the extension is neither .svg nor .png.
inline PictureFormat picture_format(const std::string& path, const std::string& where) {
    const std::size_t dot = path.find_last_of('.');
    const std::size_t slash = path.find_last_of('/');
    std::string ext;
    if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) {
        ext = path.substr(dot);
    }
    for (char& c : ext) {
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    if (ext == ".svg") {
        return PictureFormat::svg;
    }
    if (ext == ".png") {
        return PictureFormat::png;
    }
    throw InvalidInput(where + ": " + path + ": expected a .svg or .png file");
}

/// Scale, page, fonts and limits of the body picture.
struct PictureOptions {
    double scale = 0.2;         ///< picture mm per body mm (1:5: a 1.7 m body is 340 mm tall)
    double margin_mm = 8;       ///< around the page
    double font_size_mm = 3.2;  ///< labels (captions and title are larger)
    double pixels_per_mm = 5;   ///< PNG resolution (picture mm)
    double svg_shading_pixels_per_mm = 2;  ///< the body's shading embedded in the SVG as a PNG
    double max_megapixels = 60;            ///< refuse larger PNGs
    /// A tape point more than this (body mm) behind the skin seen at its pixel is drawn as hidden
    /// (dashed, lighter). Tape loops lie on the skin or, bridging hollows, outside it.
    double hidden_tolerance_mm = 8;
    std::string title;  ///< drawn at the top left; empty: none
};

/// One orthographic view. A canonical point p (mm) is drawn at picture millimetres
/// (origin_x_mm + scale * dot(p, right), origin_y_mm - scale * p[1]) (y down, as in SVG).
struct PictureView {
    std::string name;  ///< "front" or "side"
    /// The body's box.
    ///@{
    double left_mm = 0, top_mm = 0, width_mm = 0, height_mm = 0;  ///< the body's box
    ///@}
    /// Where the canonical origin is drawn.
    ///@{
    double origin_x_mm = 0, origin_y_mm = 0;
    ///@}
    Vec3 right{1, 0, 0};          ///< canonical direction drawn to the right
    Vec3 toward_viewer{0, 0, 1};  ///< canonical direction pointing at the viewer
};

/// One measurement label: which view it is drawn beside, its text, where its leader ends.
struct PictureLabel {
    std::string measurement;  ///< measurement name
    std::string text;         ///< "waist_girth 712.3 mm"
    std::string view;         ///< "front" or "side"
    /// Text anchor (baseline).
    ///@{
    double x_mm = 0, y_mm = 0;  ///< text anchor (baseline)
    ///@}
    /// The point of the tape the leader points at.
    ///@{
    double anchor_x_mm = 0, anchor_y_mm = 0;  ///< the point of the tape the leader points at
    ///@}
};

/// What a picture function drew.
struct PictureReport {
    PictureFormat format = PictureFormat::svg;  ///< format written
    /// Page size, and picture mm per body mm.
    ///@{
    double width_mm = 0, height_mm = 0, scale = 0;
    ///@}
    std::vector<PictureView> views;    ///< front, then side
    std::vector<PictureLabel> labels;  ///< one per measurement drawn
    /// Counts of what was drawn.
    ///@{
    std::size_t measurements_drawn = 0, landmarks_drawn = 0;
    ///@}
    /// Image size of a PNG.
    ///@{
    std::size_t width_px = 0, height_px = 0;  ///< PNG
    ///@}
    std::size_t bytes = 0;  ///< written to the stream or file
};

}  // namespace tapeline::measurement
