// Bodies re-meshed by CGAL (tapeline/core/remesh.h), as plain soups: the tessellation changes,
// the surface does not, so every measurement must stay within ISO 20685-1 of the original's.
#pragma once

#include <tapeline_test/measurement_holes.h>

#include <cstddef>

namespace tapeline_test::measurement {

/// `soup` isotropically re-meshed to edges near `edge` (the soup's unit), 3 rounds.
Soup remeshed_soup(const Soup& soup, double edge);

/// `soup` decimated to about `vertices` vertices (Garland–Heckbert edge collapse).
Soup simplified_soup(const Soup& soup, std::size_t vertices);

}  // namespace tapeline_test::measurement
