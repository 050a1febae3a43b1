// Plain-type bodies for the body-check tests (tapeline_test/measurement_checks.h).
#include <tapeline/core/mesh_io.h>
#include <tapeline_test/measurement_checks.h>

#include "measurement_soup_mesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace tapeline_test::measurement {

Soup read_body_soup(const std::string& path) {
    using Mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;
    return soup_from_mesh(tapeline::read_triangle_mesh<Mesh>(path).mesh);
}

Soup ellipsoid(const Vec3& centre, const Vec3& semi_axes, int rings, int segments) {
    Soup s;
    const double pi = std::acos(-1.0);
    s.points.push_back({centre[0], centre[1] - semi_axes[1], centre[2]});  // bottom pole
    for (int i = 1; i < rings; ++i) {
        const double th = pi * i / rings;
        for (int j = 0; j < segments; ++j) {
            const double ph = 2 * pi * j / segments;
            s.points.push_back({centre[0] + semi_axes[0] * std::sin(th) * std::cos(ph),
                                centre[1] - semi_axes[1] * std::cos(th),
                                centre[2] + semi_axes[2] * std::sin(th) * std::sin(ph)});
        }
    }
    s.points.push_back({centre[0], centre[1] + semi_axes[1], centre[2]});  // top pole
    const auto top = static_cast<std::uint32_t>(s.points.size() - 1);
    auto at = [segments](int ring, int j) {
        return static_cast<std::uint32_t>(1 + (ring - 1) * segments + (j % segments));
    };
    for (int j = 0; j < segments; ++j) {
        s.triangles.push_back({0, at(1, j + 1), at(1, j)});
        for (int i = 1; i + 1 < rings; ++i) {
            s.triangles.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1)});
            s.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i + 1, j)});
        }
        s.triangles.push_back({at(rings - 1, j), at(rings - 1, j + 1), top});
    }
    return s;
}

}  // namespace tapeline_test::measurement
