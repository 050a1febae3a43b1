// Test facade for the measurement picture (measurement/picture.h, DESIGN.md §5): plain functions
// compiled once in tapeline_test_support_measurement (support/measurement_picture.cpp).
#pragma once

#include <tapeline/draw/canvas.h>
#include <tapeline/measurement/picture_types.h>
#include <tapeline_test/measurement.h>

#include <cstdint>
#include <string>
#include <vector>

namespace tapeline_test::measurement {

/// One drawing as SVG text, as an RGBA image and as PNG bytes, with the reports.
struct Picture {
    std::string svg;
    PictureReport svg_report;
    tapeline::draw::RgbaImage image;
    PictureReport image_report;
    std::vector<std::uint8_t> png;
    PictureReport png_report;
};

/// write_measurement_svg, render_measurement_picture and write_measurement_png on a canonical
/// body mesh (throws as the library does).
Picture draw_picture(const std::vector<Vec3>& points, const Triangles& triangles,
                     const MeasurementSet& set, const LandmarkSet& landmarks,
                     const PictureOptions& options = {});

/// write_measurement_picture(path, ...): SVG or PNG by extension, atomically.
PictureReport write_picture(const std::string& path, const std::vector<Vec3>& points,
                            const Triangles& triangles, const MeasurementSet& set,
                            const LandmarkSet& landmarks, const PictureOptions& options = {});

/// A mesh file measured as `tapeline measure` does (Surface_mesh<Epick>: landmarks, girths,
/// lengths along the skin), its canonical mesh from picture_mesh(tm, frame), and the drawing.
struct FilePicture {
    Result measured;
    PictureMesh mesh;
    Picture picture;
};
FilePicture picture_file(const std::string& path, const BodyOptions& options,
                         const PictureOptions& picture = {});

}  // namespace tapeline_test::measurement
