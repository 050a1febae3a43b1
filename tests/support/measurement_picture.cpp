// The measurement picture (compiled once here: picture.h includes CGAL for picture_mesh).
#include <tapeline/core/mesh_io.h>
#include <tapeline/measurement/lengths.h>
#include <tapeline/measurement/measure.h>
#include <tapeline/measurement/picture.h>
#include <tapeline_test/picture.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <sstream>

namespace tapeline_test::measurement {

namespace {
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Epick::Point_3>;
namespace meas = tapeline::measurement;
}  // namespace

Picture draw_picture(const std::vector<Vec3>& points, const Triangles& triangles,
                     const MeasurementSet& set, const LandmarkSet& landmarks,
                     const PictureOptions& options) {
    Picture p;
    std::ostringstream svg;
    p.svg_report = meas::write_measurement_svg(svg, points, triangles, set, landmarks, options);
    p.svg = svg.str();
    p.image = meas::render_measurement_picture(points, triangles, set, landmarks, options,
                                               &p.image_report);
    std::ostringstream png;
    p.png_report = meas::write_measurement_png(png, points, triangles, set, landmarks, options);
    const std::string bytes = png.str();
    p.png.assign(bytes.begin(), bytes.end());
    return p;
}

PictureReport write_picture(const std::string& path, const std::vector<Vec3>& points,
                            const Triangles& triangles, const MeasurementSet& set,
                            const LandmarkSet& landmarks, const PictureOptions& options) {
    return meas::write_measurement_picture(path, points, triangles, set, landmarks, options);
}

FilePicture picture_file(const std::string& path, const BodyOptions& options,
                         const PictureOptions& picture) {
    const auto loaded = tapeline::read_triangle_mesh<SurfaceMesh>(path);
    auto m = meas::measure_body(loaded.mesh, options);
    meas::measure_skin_lengths(loaded.mesh, m.frame, m.landmarks, m.measurements);
    FilePicture out;
    out.mesh = meas::picture_mesh(loaded.mesh, m.frame);
    out.picture =
        draw_picture(out.mesh.points, out.mesh.triangles, m.measurements, m.landmarks, picture);
    out.measured.frame = m.frame;
    out.measured.landmarks = std::move(m.landmarks);
    out.measured.measurements = std::move(m.measurements);
    out.measured.report = std::move(m.report);
    return out;
}

}  // namespace tapeline_test::measurement
