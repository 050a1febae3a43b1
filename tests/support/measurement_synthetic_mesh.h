// Support-internal (not a test facade: it includes CGAL): the synthetic body as a
// Surface_mesh<Epick>, shared by the support files that measure it.
#pragma once

#include <tapeline/measurement/synthetic_body.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

namespace tapeline_test::measurement {

using SyntheticSurfaceMesh =
    CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;

/// The synthetic body's triangles as one Surface_mesh; `connected`: its closed parts merged into
/// one skin first (CGAL corefinement union, slivers collapsed), so that geodesic paths can cross
/// from part to part.
SyntheticSurfaceMesh synthetic_surface_mesh(const tapeline::measurement::SyntheticBodyOptions& o,
                                            bool connected);

}  // namespace tapeline_test::measurement
