// Test facade for the body checks and self-checks (measurement/body_checks.h, self_checks.h):
// bodies as plain points and triangles, to rotate, combine and cut in the tests.
#pragma once

#include <tapeline_test/measurement.h>

#include <string>
#include <vector>

namespace tapeline_test::measurement {

/// read_triangle_mesh of a body file, as points and triangles in its file's coordinates.
Soup read_body_soup(const std::string& path);

/// A closed ellipsoid (UV sphere scaled by the semi-axes), centred at `centre`.
Soup ellipsoid(const Vec3& centre, const Vec3& semi_axes, int rings = 32, int segments = 48);

}  // namespace tapeline_test::measurement
