// The JSON writers of the geodesic Options and Reports: every field of a default-constructed
// struct appears under its C++ name with the struct's value, and nothing else does. The field
// lists are written by hand and checked against the struct's member count, so a field added
// without a writer line fails here.
#include <tapeline/geodesic/curvature_flow_json.h>
#include <tapeline/geodesic/exact_mmp_json.h>
#include <tapeline/geodesic/geodesic_json.h>
#include <tapeline/geodesic/point_cloud_json.h>
#include <tapeline/geodesic/unfold_json.h>

#include <tapeline_test/json_fields.h>

#include <gtest/gtest.h>

#include <string>

namespace {

using namespace tapeline::geodesic;
using nlohmann::json;
using Fields = tapeline::test::JsonFields;
using tapeline::test::expect_fields;

#define FIELD TAPELINE_JSON_FIELD

Fields distance_report_fields(const DistanceReport& r) {
    return {FIELD(r, method),          FIELD(r, vertices),      FIELD(r, faces),
            FIELD(r, sources),         FIELD(r, unreachable),   FIELD(r, components),
            FIELD(r, prepare_seconds), FIELD(r, query_seconds), FIELD(r, seconds),
            FIELD(r, status),          FIELD(r, message)};
}

Fields concat(Fields a, const Fields& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

TEST(OptionsJson, DistanceReport) {
    DistanceReport r;
    r.method = "heat";
    r.unreachable = 3;
    r.status = "stopped";
    const Fields f = distance_report_fields(r);
    EXPECT_EQ(tapeline::test::field_count<DistanceReport>(), f.size());
    expect_fields(json(r), f, "DistanceReport");
    EXPECT_EQ(json(r)["unreachable"], 3);
}

TEST(OptionsJson, BaselineOptions) {
    const HeatOptions h;
    const Fields fh = {FIELD(h, intrinsic_delaunay), FIELD(h, multi_source),
                       FIELD(h, degenerate_face_tolerance), FIELD(h, reject_degenerate_faces)};
    EXPECT_EQ(tapeline::test::field_count<HeatOptions>(), fh.size());
    expect_fields(json(h), fh, "HeatOptions");
    EXPECT_EQ(json(h)["multi_source"], "min_of_single_sources");  // enums by name
    EXPECT_EQ(tapeline::test::field_count<ExactCgalOptions>(), 0u);
    EXPECT_EQ(json(ExactCgalOptions{}), json::object());
    EXPECT_EQ(tapeline::test::field_count<DijkstraOptions>(), 0u);
    EXPECT_EQ(json(DijkstraOptions{}), json::object());
}

TEST(OptionsJson, ExactMmp) {
    const ExactMmpOptions o;
    const Fields fo = {FIELD(o, max_distance), FIELD(o, target_vertices),
                       FIELD(o, prune_with_vertex_distances), FIELD(o, keep_windows),
                       FIELD(o, max_propagated_windows)};
    EXPECT_EQ(tapeline::test::field_count<ExactMmpOptions>(), fo.size());
    expect_fields(json(o), fo, "ExactMmpOptions");

    ExactMmpReport r;
    r.windows_created = 7;
    r.prepare_seconds = 0.5;
    const Fields fr = {FIELD(r, windows_created),
                       FIELD(r, windows_propagated),
                       FIELD(r, windows_pruned),
                       FIELD(r, windows_kept),
                       FIELD(r, windows_peak),
                       FIELD(r, pseudo_sources),
                       FIELD(r, saddle_or_boundary_vertices),
                       FIELD(r, peak_bytes),
                       FIELD(r, stopped_at)};
    EXPECT_EQ(tapeline::test::field_count<ExactMmpReport>(), 1 + fr.size());  // 1: the base
    expect_fields(json(r), concat(distance_report_fields(r), fr), "ExactMmpReport");
}

Fields flow_fields(const CurvatureFlowOptions& o) {
    return {FIELD(o, sample_spacing),
            FIELD(o, sample_count),
            FIELD(o, step),
            FIELD(o, tolerance),
            FIELD(o, update_tolerance),
            FIELD(o, max_iterations),
            FIELD(o, endpoint_weight),
            FIELD(o, solver),
            FIELD(o, ceres_linear_solver),
            FIELD(o, straighten),
            FIELD(o, interpolate_normals)};
}

TEST(OptionsJson, CurvatureFlow) {
    const CurvatureFlowOptions o;
    const Fields fo = flow_fields(o);
    EXPECT_EQ(tapeline::test::field_count<CurvatureFlowOptions>(), fo.size());
    expect_fields(json(o), fo, "CurvatureFlowOptions");
    EXPECT_EQ(json(o)["solver"], "eigen_normal_ldlt");

    const CurvatureFlowReport r;
    const Fields fr = {FIELD(r, vertices),
                       FIELD(r, faces),
                       FIELD(r, samples),
                       FIELD(r, iterations),
                       FIELD(r, initial_length),
                       FIELD(r, max_geodesic_curvature),
                       FIELD(r, scaled_max_geodesic_curvature),
                       FIELD(r, residual),
                       FIELD(r, max_update),
                       FIELD(r, trace_fallbacks),
                       FIELD(r, traced_length),
                       FIELD(r, straightened),
                       FIELD(r, straighten_flips),
                       FIELD(r, straighten_bends),
                       FIELD(r, on_mesh_from_initial),
                       FIELD(r, init_seconds),
                       FIELD(r, flow_seconds),
                       FIELD(r, seconds),
                       FIELD(r, status),
                       FIELD(r, solver)};
    EXPECT_EQ(tapeline::test::field_count<CurvatureFlowReport>(), fr.size());
    expect_fields(json(r), fr, "CurvatureFlowReport");
}

TEST(OptionsJson, CurvatureFlowDistances) {
    const CurvatureFlowDistanceOptions o;
    const Fields fo = {FIELD(o, window),
                       FIELD(o, sample_spacing),
                       FIELD(o, smooth_length),
                       FIELD(o, polyhedral_length),
                       FIELD(o, shortest_parent),
                       FIELD(o, cut_locus_guard),
                       FIELD(o, repair_tolerance),
                       FIELD(o, repair_rounds),
                       FIELD(o, repair_flow_iterations),
                       FIELD(o, repair_steiner_points),
                       FIELD(o, repair_graph_margin),
                       FIELD(o, anchor),
                       FIELD(o, near_source_samples),
                       FIELD(o, anchor_slides),
                       FIELD(o, flow),
                       FIELD(o, window_max_iterations)};
    // The base (FlowPropagationOptions) counts as one member of the aggregate; its fields are in
    // fo.
    EXPECT_EQ(tapeline::test::field_count<CurvatureFlowDistanceOptions>() - 1 +
                  tapeline::test::field_count<FlowPropagationOptions>(),
              fo.size());
    const json j = o;
    expect_fields(j, fo, "CurvatureFlowDistanceOptions");
    expect_fields(j["flow"], flow_fields(o.flow), "CurvatureFlowDistanceOptions.flow");
    EXPECT_EQ(j["anchor"], "field");
    EXPECT_EQ(j["flow"]["tolerance"], 1e-7);  // the distance flow's own default, not the path's

    const CurvatureFlowDistanceReport r;
    const Fields fr = {FIELD(r, reached),
                       FIELD(r, flows),
                       FIELD(r, iterations),
                       FIELD(r, converged),
                       FIELD(r, stalled),
                       FIELD(r, max_iterations),
                       FIELD(r, solver_failures),
                       FIELD(r, stored_samples),
                       FIELD(r, epsilon),
                       FIELD(r, max_faces),
                       FIELD(r, error_bound),
                       FIELD(r, repair_checked),
                       FIELD(r, repair_improved),
                       FIELD(r, repair_graph_flagged),
                       FIELD(r, repair_graph_seconds),
                       FIELD(r, repair_seconds),
                       FIELD(r, sample_spacing)};
    EXPECT_EQ(tapeline::test::field_count<CurvatureFlowDistanceReport>(), 1 + fr.size());
    expect_fields(json(r), concat(distance_report_fields(r), fr), "CurvatureFlowDistanceReport");
}

TEST(OptionsJson, PointCloud) {
    const PointCloudDistanceOptions o;
    const Fields fo = {FIELD(o, cell_size),
                       FIELD(o, neighbours),
                       FIELD(o, window),
                       FIELD(o, manifold_dimension),
                       FIELD(o, projection),
                       FIELD(o, knn),
                       FIELD(o, sample_spacing),
                       FIELD(o, cut_locus_guard),
                       FIELD(o, near_source_samples),
                       FIELD(o, anchor_slides),
                       FIELD(o, flow),
                       FIELD(o, path_flow)};
    EXPECT_EQ(tapeline::test::field_count<PointCloudDistanceOptions>() - 1 +
                  tapeline::test::field_count<FlowPropagationOptions>(),
              fo.size());
    const json j = o;
    expect_fields(j, fo, "PointCloudDistanceOptions");
    expect_fields(j["path_flow"], flow_fields(o.path_flow), "PointCloudDistanceOptions.path_flow");
    EXPECT_EQ(j["projection"], "mls");
    EXPECT_EQ(j["knn"], "automatic");

    const PointCloudDistanceReport r;
    const Fields fr = {FIELD(r, points),
                       FIELD(r, dimension),
                       FIELD(r, manifold_dimension),
                       FIELD(r, manifold_dimension_estimated),
                       FIELD(r, neighbours),
                       FIELD(r, cell_size),
                       FIELD(r, sample_spacing),
                       FIELD(r, nodes),
                       FIELD(r, node_edges),
                       FIELD(r, bridged_components),
                       FIELD(r, window),
                       FIELD(r, projection),
                       FIELD(r, knn),
                       FIELD(r, reached_nodes),
                       FIELD(r, reached),
                       FIELD(r, flows),
                       FIELD(r, iterations),
                       FIELD(r, converged),
                       FIELD(r, stalled),
                       FIELD(r, max_iterations),
                       FIELD(r, solver_failures),
                       FIELD(r, charts),
                       FIELD(r, knn_seconds),
                       FIELD(r, grid_seconds),
                       FIELD(r, propagate_seconds),
                       FIELD(r, interpolate_seconds)};
    EXPECT_EQ(tapeline::test::field_count<PointCloudDistanceReport>(), 1 + fr.size());
    expect_fields(json(r), concat(distance_report_fields(r), fr), "PointCloudDistanceReport");
}

TEST(OptionsJson, Unfold) {
    const UnfoldOptions o;
    const Fields fo = {FIELD(o, tolerance)};
    EXPECT_EQ(tapeline::test::field_count<UnfoldOptions>(), fo.size());
    expect_fields(json(o), fo, "UnfoldOptions");
}

// A writer that forgot a field, or wrote a default instead of the value, is caught: the values
// here differ from every default.
TEST(OptionsJson, WritesValuesNotDefaults) {
    CurvatureFlowDistanceOptions o;
    o.window = 5;
    o.cut_locus_guard = false;
    o.repair_tolerance = -1;
    o.anchor = WindowAnchor::prefix;
    o.flow.max_iterations = 17;
    const json j = o;
    EXPECT_EQ(j["window"], 5);
    EXPECT_EQ(j["cut_locus_guard"], false);
    EXPECT_EQ(j["repair_tolerance"], -1.0);
    EXPECT_EQ(j["anchor"], "prefix");
    EXPECT_EQ(j["flow"]["max_iterations"], 17);
}

}  // namespace
