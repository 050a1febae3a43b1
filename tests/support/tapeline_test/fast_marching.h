// Test facade for fast marching (DESIGN.md §5): plain functions compiled once in
// tapeline_test_support_geodesic (support/geodesic_fast_marching.cpp); test files include gtest
// and this. Meshes, sources and surface points are the plain types of tapeline_test/geodesic.h.
#pragma once

#include <tapeline/geodesic/geodesic_types.h>
#include <tapeline_test/geodesic.h>

#include <cstddef>
#include <vector>

namespace tapeline_test::geodesic {

using tapeline::geodesic::FastMarchingOptions;
using tapeline::geodesic::FastMarchingReport;

struct FastMarchingField {
    std::vector<double> d;  ///< per soup vertex
    FastMarchingReport report;
};

/// The one-shot free function fast_marching_distances.
FastMarchingField fast_marching(const Soup& soup, const Sources& sources,
                                const FastMarchingOptions& options = {},
                                MeshKind kind = MeshKind::surface_mesh);

/// One FastMarchingSolver, several queries (in order); its report carries the preparation.
std::vector<FastMarchingField> fast_marching_queries(const Soup& soup,
                                                     const std::vector<Sources>& queries,
                                                     const FastMarchingOptions& options = {});

}  // namespace tapeline_test::geodesic
