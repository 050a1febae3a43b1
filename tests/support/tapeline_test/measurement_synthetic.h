// Test facade: the lengths along the skin of the synthetic body (compiled once in
// support/measurement_synthetic_lengths.cpp; DESIGN.md §5), for analytic-truth tests.
#pragma once

#include <tapeline_test/measurement.h>

#include <array>
#include <string>
#include <vector>

namespace tapeline_test::measurement {

/// One geodesic segment of a skin length on the synthetic body: its end points (canonical mm,
/// the surface points the measurement walked between), the curvature-flow length the measurement
/// used and, when asked for, the exact (MMP) polyhedral distance between the same points.
struct SyntheticSegment {
    std::string measurement;
    Vec3 from{}, to{};
    double gcf = 0, exact = -1, euclidean = 0;
};

struct SyntheticLengths {
    Result result;  ///< girths, landmarks and the skin lengths, cross seam, shoulder slope
    std::vector<SyntheticSegment> segments;
};

/// The synthetic body as a Surface_mesh<Epick>, measure_body, then everything
/// measure_skin_lengths does (lengths.h). `connected`: the body's closed parts merged into one
/// skin first (CGAL corefinement union; the same surface outside the overlaps), so that paths
/// can cross from part to part. `exact`: also run exact MMP on every segment (of the lengths
/// named in `exact_only`, when it is not empty).
SyntheticLengths measure_synthetic_lengths(const SyntheticBodyOptions& synthetic,
                                           bool connected = true, bool exact = false,
                                           const std::vector<std::string>& exact_only = {});

}  // namespace tapeline_test::measurement
