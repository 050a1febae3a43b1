// Bodies with holes measured through make_body's hole filling (tapeline_test/measurement_holes.h).
#include <tapeline/core/mesh_io.h>
#include <tapeline/measurement/lengths.h>
#include <tapeline/measurement/measure.h>
#include <tapeline_test/measurement_holes.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <chrono>

namespace tapeline_test::measurement {
namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Epick::Point_3>;
namespace meas = tapeline::measurement;

}  // namespace

Soup canonical_soup(const std::string& path, const BodyOptions& options) {
    const auto loaded = tapeline::read_triangle_mesh<SurfaceMesh>(path);
    const meas::Body body = meas::make_body(loaded.mesh, options);
    return {body.mesh.points, body.mesh.triangles};
}

Result measure_soup_with_skin_lengths(const Soup& soup, const std::string& name, Pose pose) {
    const meas::Body body = meas::make_body(soup.points, soup.triangles,
                                            body_options(name, meas::LengthUnit::mm, pose));
    const auto t0 = std::chrono::steady_clock::now();
    auto m = meas::measure_body(body);
    // The soup has no CGAL mesh of its own: the body's (filled) mesh is the input.
    meas::measure_skin_lengths(body, meas::filled_input_mesh(body), m.landmarks, m.measurements);
    return to_result(std::move(m),
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
}

FilledSoup fill_soup(const Soup& soup, const std::string& name) {
    const meas::Body body =
        meas::make_body(soup.points, soup.triangles, body_options(name, meas::LengthUnit::mm));
    FilledSoup out;
    out.faces = body.mesh.triangles.size();
    for (std::size_t f = 0; f < out.faces; ++f) {
        out.filled_faces += body.mesh.is_filled(f) ? 1 : 0;
    }
    out.holes = body.holes;
    return out;
}

}  // namespace tapeline_test::measurement
