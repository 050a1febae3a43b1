// `tapeline dress BODY --units dm PATTERN --out dressed.obj [--ply d.ply] [--report r.json]
// [--resolution MM] [--fabric NAME|fabric.json] [--without PIECE] [--threads N] [--strict]
// [--to-body --from SET [--from-set NAME] [--seed S]]`: measures the body (landmarks; with
// --to-body every measurement, and grades the pattern from SET to them first), places the pattern's
// pieces around it, sews them along geodesic strings, drapes them with the cloth solver and writes
// the welded garment in the body's own coordinates and unit, with its quality report (garment
// module).
#include "commands.h"
#include "output.h"
#include "wrinkles_dress.h"

#include <tapeline/bench/dress_run.h>
#include <tapeline/core/atomic_write.h>
#include <tapeline/core/errors.h>
#include <tapeline/core/mesh_io.h>
#include <tapeline/garment/fabric.h>
#include <tapeline/garment/garment_io.h>
#include <tapeline/garment/picture.h>
#ifdef TAPELINE_HAVE_GLTF
#include <tapeline/garment/gltf.h>
#endif
#include <tapeline/pattern/validate.h>
#include <tapeline/sizes/read_input.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace tapeline::app {
namespace {

namespace tm = tapeline::measurement;
namespace tg = tapeline::garment;

struct DressArgs {
    std::string body, units, pattern, format, db;
    std::string up = tm::BodyOptions{}.up.to_string();
    std::string front = tm::BodyOptions{}.front.to_string();
    std::string out, ply, report, glb, picture;
    std::string fabric = "cotton_jersey";
    std::vector<std::string> without;
    double resolution = tg::DressOptions{}.resolution_mm;
    int threads = 0;
    double sew_seconds = tg::SewingOptions{}.sew_seconds;
    double settle_seconds = tg::SewingOptions{}.settle_seconds;
    double gap = tg::PlacementOptions{}.gap_mm;
    double sdf_cell = tg::DressOptions{}.sdf_cell_mm;
    int substeps = tg::DressOptions{}.drape.substeps;
    bool no_self_collision = false;
    bool edge_edge = false;
    bool no_untangle = false;
    bool no_relax = false;
    bool no_fold_smoothing = false;
    bool no_waistband = false;
    double waistband_sag = tg::DressOptions{}.waistband_sag_mm;
    bool no_body_points = false;
    int fold_cycles = tg::DressOptions{}.fold_cycles;
    int relax_iterations = tg::RelaxOptions{}.max_iterations;
    int relax_settle = tg::DressOptions{}.relax_options.settle_iterations;
    int relax_again_friction = tg::DressOptions{}.relax_again_options.friction_from_iteration;
    int relax_again_releases = tg::DressOptions{}.relax_again_options.release_until_iteration;
    double relax_tolerance = tg::DressOptions{}.relax_options.tolerance_mm;
    double relax_settle_fraction = tg::DressOptions{}.relax_options.settle_fraction;
    int fold_rounds = tg::DressOptions{}.fold_options.max_rounds;
    int fold_rings = tg::DressOptions{}.fold_options.rings;
    int fold_sweeps = tg::DressOptions{}.fold_options.sweeps;
    bool strict = false;
    bool to_body = false;
    std::string from, from_set;
    /// The body the pattern was made for (with --to-body), its unit and axes.
    std::string base_body, base_units, base_up = "+Y", base_front = "+Z";
    std::uint32_t seed = 1;
    std::string wrinkles, coarse_out;
};

void run_dress(const DressArgs& a) {
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    if (extension_of(a.out) != ".obj") {
        throw InvalidInput("--out " + a.out + ": expected an .obj file");
    }
    if (!a.ply.empty() && extension_of(a.ply) != ".ply") {
        throw InvalidInput("--ply " + a.ply + ": expected a .ply file");
    }
    if (!a.report.empty() && extension_of(a.report) != ".json") {
        throw InvalidInput("--report " + a.report + ": expected a .json file");
    }
    if (a.threads < 0) {
        throw InvalidInput("--threads must be >= 0 (0: all cores)");
    }
    if (!a.glb.empty() && extension_of(a.glb) != ".glb") {
        throw InvalidInput("--glb " + a.glb + ": expected a .glb file");
    }
#ifndef TAPELINE_HAVE_GLTF
    if (!a.glb.empty()) {
        throw InvalidInput(
            "--glb: this tapeline was built without TinyGLTF (Debian package "
            "libtinygltf-dev)");
    }
#endif
    if (!a.picture.empty() && extension_of(a.picture) != ".png") {
        throw InvalidInput("--picture " + a.picture + ": expected a .png file");
    }
    if (!a.coarse_out.empty() && a.wrinkles.empty()) {
        throw InvalidInput("--coarse-out " + a.coarse_out + " is for --wrinkles");
    }
    if (!a.coarse_out.empty() && extension_of(a.coarse_out) != ".obj") {
        throw InvalidInput("--coarse-out " + a.coarse_out + ": expected an .obj file");
    }
    OutputFiles outputs({a.out, a.ply, a.report, a.glb, a.picture, a.coarse_out});
    tg::DressOptions o;
    o.resolution_mm = a.resolution;
    o.fabric = tg::fabric_from(a.fabric);
    std::optional<WrinkleDressing> wrinkles;
    if (!a.wrinkles.empty()) {
        wrinkles.emplace(a.wrinkles, o.fabric);
    }
    o.drape.threads = a.threads;
    if (!(a.sew_seconds >= 0) || !(a.settle_seconds >= 0) || !(a.gap > 0) || a.substeps < 1) {
        throw InvalidInput(
            "--sew-seconds and --settle-seconds must be >= 0, --gap > 0 and "
            "--substeps >= 1");
    }
    if (!(std::isfinite(a.sdf_cell) && a.sdf_cell > 0)) {
        throw InvalidInput("--sdf-cell must be a finite number of mm > 0");
    }
    o.sdf_cell_mm = a.sdf_cell;
    if (!(a.relax_tolerance > 0)) {  // the parser refuses what is not a finite number
        throw InvalidInput("--relax-tolerance must be a number of mm > 0");
    }
    o.sewing.sew_seconds = a.sew_seconds;
    bench::set_settle_seconds(o.sewing, a.settle_seconds);
    o.placement.gap_mm = a.gap;
    o.drape.substeps = a.substeps;
    o.drape.self_collision = !a.no_self_collision;
    o.drape.edge_edge_collision = a.edge_edge;
    o.drape.untangle = !a.no_untangle;
    o.relax = !a.no_relax;
    for (tg::RelaxOptions* r : {&o.relax_options, &o.relax_again_options}) {
        r->max_iterations = a.relax_iterations;
        r->settle_iterations = a.relax_settle;
        r->tolerance_mm = a.relax_tolerance;
        r->settle_fraction = a.relax_settle_fraction;
    }
    o.relax_again_options.friction_from_iteration = a.relax_again_friction;
    o.relax_again_options.release_until_iteration = a.relax_again_releases;
    o.smooth_folds = !a.no_fold_smoothing;
    o.waistband = !a.no_waistband;
    if (!(a.waistband_sag > 0)) {  // the parser refuses what is not a finite number
        throw InvalidInput("--waistband-sag must be a number of mm > 0");
    }
    o.waistband_sag_mm = a.waistband_sag;
    o.body_points = !a.no_body_points;
    o.fold_cycles = a.fold_cycles;
    o.fold_options.max_rounds = a.fold_rounds;
    o.fold_options.rings = a.fold_rings;
    o.fold_options.sweeps = a.fold_sweeps;
    o.without_pieces = a.without;

    const tm::BodyOptions bo = tm::parse_body_options(a.body, a.units, a.up, a.front,
                                                      tm::to_string(tm::BodyOptions{}.pose), "--");
    if (a.to_body && a.from.empty() == a.base_body.empty()) {
        throw InvalidInput(
            "--to-body needs what the pattern was made for: its measurement set (--from) or the "
            "body it was made for (--base-body), one of them");
    }
    if (!a.to_body && (!a.from.empty() || !a.from_set.empty() || !a.base_body.empty())) {
        throw InvalidInput("--from, --from-set and --base-body are for --to-body");
    }
    if (a.base_body.empty() &&
        (!a.base_units.empty() || a.base_up != "+Y" || a.base_front != "+Z")) {
        throw InvalidInput("--base-units, --base-up and --base-front describe --base-body");
    }
    pattern::Pattern pat = load_pattern(a.pattern, a.db, a.format);
    pattern::require_valid(pat);
    std::optional<sizes::MeasurementSet> from;
    if (a.to_body && !a.base_body.empty()) {
        bench::BodyBase b =
            bench::base_from_body(std::move(pat), a.base_body,
                                  tm::parse_body_options(a.base_body, a.base_units, a.base_up,
                                                         a.base_front, "A", "--base-"));
        pat = std::move(b.pattern);
        from = std::move(b.measurements);
        for (const std::string& note : b.notes) {
            std::cerr << "tapeline: binding: " << note << '\n';
        }
    } else if (a.to_body) {
        from = sizes::read_measurement_input(a.from, a.from_set);
    }

    const auto loaded = read_triangle_mesh<bench::Mesh>(a.body);
    bench::DressRun r =
        bench::dress_mesh(loaded.mesh, bo, std::move(pat), o, from ? &*from : nullptr, a.seed);
    for (const std::string& w : r.warnings) {
        std::cerr << "tapeline: warning: " << w << '\n';
    }
    for (const std::string& note : r.grading_notes) {
        std::cerr << "tapeline: grading: " << note << '\n';
    }
    // The whole command, the mesh's loading included.
    r.report.total_seconds = std::chrono::duration<double>(Clock::now() - t0).count();

    for (const tg::SeamReport& s : r.report.seams) {
        if (!s.closable) {
            std::cerr << "tapeline: warning: seam '" << s.name << "' cannot close: " << s.problem
                      << '\n';
        }
    }
    const std::string failed = bench::failed_gates(r.report);
    if (!failed.empty()) {
        if (a.strict) {
            throw SolverFailure(a.body +
                                ": the drape failed its quality gates with --strict "
                                "(nothing written): " +
                                failed);
        }
        std::cerr << "tapeline: warning: quality gates failed: " << failed << '\n';
    }
    const tm::Body& body = r.body;
    const tm::BodyFrame frame = body.frame;
    const tg::PositionMap to_body = [frame](const tg::Vec3& p) { return frame.to_input(p); };
    std::optional<DressedWrinkles> wrinkled;
    if (wrinkles) {
        if (!a.coarse_out.empty()) {
            outputs.write(a.coarse_out, [&](std::ostream& out) {
                tg::write_garment_obj(out, r.garment, to_body);
            });
        }
        wrinkled = wrinkles->apply(r.garment, body);
        std::cerr << "tapeline: " << wrinkled->summary << '\n';
        r.garment = wrinkled->garment;
        r.stretch = wrinkled->stretch;
    }
    outputs.write(a.out,
                  [&](std::ostream& out) { tg::write_garment_obj(out, r.garment, to_body); });
    if (!a.ply.empty()) {
        outputs.write(a.ply, [&](std::ostream& out) {
            tg::write_garment_ply(out, r.garment, r.stretch, to_body);
        });
    }
#ifdef TAPELINE_HAVE_GLTF
    if (!a.glb.empty()) {
        outputs.write(
            a.glb,
            [&](std::ostream& out) {
                tg::write_dressed_glb(out, body.points(), body.triangles(), r.garment, r.stretch);
            },
            true);
    }
#endif
    if (!a.picture.empty()) {
        const draw::RgbaImage img =
            tg::dressed_picture(body.points(), body.triangles(), r.garment, r.stretch, r.seam_lines,
                                std::filesystem::path(a.pattern).filename().string() + " on " +
                                    std::filesystem::path(a.body).filename().string() +
                                    (r.report.passed ? "" : " (quality gates failed)"));
        outputs.write(
            a.picture, [&](std::ostream& out) { draw::write_png(out, img, 5); }, true);
    }
    if (!a.report.empty()) {
        nlohmann::ordered_json j = bench::dress_report_json(r, a.body, a.pattern, o);
        if (wrinkled) {
            j["wrinkles"] = wrinkled->report;
        }
        outputs.write(a.report, [&](std::ostream& out) { out << j.dump(1) << '\n'; });
    }
    outputs.commit();
    const auto& q = r.report.quality;
    std::cout << a.out << ": " << r.report.garment_vertices << " vertices, "
              << r.report.boundary_loops << " openings, " << (r.report.passed ? "passed" : "FAILED")
              << " (stitch gap max " << std::fixed << std::setprecision(2) << q.stitch_gap_max_mm
              << " mm, " << q.edges_crossing_body << " edges crossing the body, "
              << q.self_intersections << " self-intersections, p95 stretch " << std::setprecision(3)
              << q.stretch_p95 << ", top " << std::setprecision(0) << q.top_drop_mm
              << " mm below its placement, " << r.report.frames << " frames, "
              << std::setprecision(1) << r.report.total_seconds << " s)\n";
}

}  // namespace

void register_dress_commands(CLI::App& app) {
    auto a = std::make_shared<DressArgs>();
    CLI::App* cmd = app.add_subcommand(
        "dress",
        "Dress a body in a pattern: place the pieces around it, sew them along geodesic strings "
        "on the body, drape them with the cloth solver; writes the garment in the body's "
        "coordinates and unit, and its quality report");
    cmd->add_option("BODY", a->body, "Body mesh (OBJ, OFF, PLY, STL)")->required();
    cmd->add_option("PATTERN", a->pattern,
                    "Pattern file (GarmentCode specification, FreeSewing JSON, tapeline JSON) or "
                    "a name in the pattern database")
        ->required();
    cmd->add_option("--units", a->units, "Length unit of the body mesh: m, dm, cm or mm");
    cmd->add_option("--up", a->up, "Up axis of the body mesh")->capture_default_str();
    cmd->add_option("--front", a->front, "Axis the body faces")->capture_default_str();
    cmd->add_option("--format", a->format, "Pattern format when the extension does not tell");
    cmd->add_option("--db", a->db, "Pattern database (SQLite file)");
    cmd->add_option("--out", a->out, "Draped garment, Wavefront OBJ (seams welded, UVs in mm)")
        ->required();
    cmd->add_option("--ply", a->ply, "Also write the garment as PLY with per-vertex stretch");
    cmd->add_option("--report", a->report, "Quality report (JSON)");
    cmd->add_option("--glb", a->glb,
                    "Also write body and garment as binary glTF (metres, +Y up, garment coloured "
                    "by stretch)");
    cmd->add_option("--picture", a->picture,
                    "Also draw front, side and back views (PNG; garment coloured by stretch, "
                    "seams drawn)");
    cmd->add_option("--resolution", a->resolution, "Cloth edge length, mm")->capture_default_str();
    cmd->add_option("--fabric", a->fabric,
                    "Fabric: a library name (tapeline fabric list) or a .json fabric file "
                    "(tapeline fabric convert)")
        ->capture_default_str();
    cmd->add_option("--without", a->without, "Leave this piece (and its seams) out; repeatable")
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    cmd->add_option("--threads", a->threads, "Solver threads (0: all cores)")
        ->check(CLI::Range(0, 1024))
        ->capture_default_str();
    cmd->add_option("--sew-seconds", a->sew_seconds,
                    "Simulated time over which the seams are pulled shut (0 with --settle-seconds "
                    "0: the placement only)")
        ->capture_default_str();
    cmd->add_option("--settle-seconds", a->settle_seconds,
                    "Simulated time of the drape after sewing (more while the cloth moves; 0: "
                    "no settling at all)")
        ->capture_default_str();
    cmd->add_option("--gap", a->gap, "Clearance of the placed pieces from the body, mm")
        ->capture_default_str();
    cmd->add_option("--sdf-cell", a->sdf_cell,
                    "Cell of the body's signed-distance grid, mm (coarser: a faster start, the "
                    "cloth kept off a smoother body)")
        ->capture_default_str();
    cmd->add_option("--substeps", a->substeps, "Solver sub-steps per frame")
        ->check(CLI::Range(1, 10000))
        ->capture_default_str();
    cmd->add_flag("--no-self-collision", a->no_self_collision, "Skip cloth-cloth collisions");
    cmd->add_flag("--edge-edge", a->edge_edge,
                  "Cloth-cloth pairs of edges too, not only vertex-triangle (slower)");
    cmd->add_flag("--no-untangle", a->no_untangle,
                  "Keep cloth that has cut through cloth as it is (default: pull it back through "
                  "every frame)");
    cmd->add_flag("--no-relax", a->no_relax,
                  "End with the drape's last frame instead of solving for the static equilibrium");
    cmd->add_option("--relax-iterations", a->relax_iterations,
                    "Newton iterations of the static solve at most (it stops when converged; "
                    "friction acts from iteration " +
                        std::to_string(tg::RelaxOptions{}.friction_from_iteration) +
                        " on, so fewer leave it out)")
        ->check(CLI::Range(1, 100000))
        ->capture_default_str();
    cmd->add_option("--relax-settle", a->relax_settle,
                    "Stop the static solve once this many steps in a row (after its releases) "
                    "moved at most 0.1 % of the vertices more than 0.3 mm; 0: only at its "
                    "tolerance or its iteration limit")
        ->check(CLI::Range(0, 100000))
        ->capture_default_str();
    cmd->add_option("--relax-tolerance", a->relax_tolerance,
                    "The static solve has converged when a whole Newton step moved no vertex "
                    "more than this, mm")
        ->capture_default_str();
    cmd->add_option("--relax-settle-fraction", a->relax_settle_fraction,
                    "The fraction of the vertices --relax-settle lets move more than 0.3 mm in a "
                    "step that still counts as settled")
        ->check(CLI::Range(0.0, 1.0))
        ->capture_default_str();
    cmd->add_option("--relax-again-friction", a->relax_again_friction,
                    "The static solves after a flattening of fold-overs: friction acts from "
                    "this iteration on (the first solve's schedule is the one "
                    "--relax-iterations describes)")
        ->check(CLI::Range(0, 100000))
        ->capture_default_str();
    cmd->add_option("--relax-again-releases", a->relax_again_releases,
                    "The static solves after a flattening of fold-overs: contact points may "
                    "leave the body until this iteration")
        ->check(CLI::Range(0, 100000))
        ->capture_default_str();
    cmd->add_flag("--no-body-points", a->no_body_points,
                  "Hold the cloth against the body's distance grid only in the static solve "
                  "(default: above every body vertex too, so that a bump narrower than the "
                  "cloth's edges cannot poke through it)");
    cmd->add_flag("--no-waistband", a->no_waistband,
                  "Let the open waist of skirts and trousers slide (default: the edges the "
                  "pattern labels as its waist are held at their height, as a waistband holds "
                  "them)");
    cmd->add_option("--waistband-sag", a->waistband_sag,
                    "How firmly the waistband holds: it alone would carry the garment's weight "
                    "this far below the height it holds, mm")
        ->capture_default_str();
    cmd->add_flag("--no-fold-smoothing", a->no_fold_smoothing,
                  "Keep cloth folded over itself as the drape left it (default: flatten each "
                  "fold-over and solve again)");
    cmd->add_option(
           "--fold-cycles", a->fold_cycles,
           "Static solves at most, each after flattening the fold-overs the one before left")
        ->check(CLI::Range(1, 100))
        ->capture_default_str();
    cmd->add_option("--fold-rounds", a->fold_rounds,
                    "Find-and-smooth rounds of each flattening at most (0: find the fold-overs "
                    "only)")
        ->check(CLI::Range(0, 100000))
        ->capture_default_str();
    cmd->add_option("--fold-rings", a->fold_rings,
                    "Rings of neighbours smoothed around each fold-over at first (one more every "
                    "five rounds)")
        ->check(CLI::Range(0, 1000))
        ->capture_default_str();
    cmd->add_option("--fold-sweeps", a->fold_sweeps, "Smoothing sweeps per round")
        ->check(CLI::Range(1, 100000))
        ->capture_default_str();
    cmd->add_flag("--to-body", a->to_body,
                  "First measure the body and grade the pattern to it (measure, grade, dress in "
                  "one command; needs --from or --base-body)");
    cmd->add_option("--from", a->from,
                    "With --to-body: the measurement set the pattern was drafted for (.json, "
                    ".vit, a FreeSewing sets file with --from-set)");
    cmd->add_option("--from-set", a->from_set, "Set name inside a FreeSewing sets file");
    cmd->add_option("--base-body", a->base_body,
                    "With --to-body: the body the pattern was made for, measured and the "
                    "pattern laid on it to find its girth bindings (for patterns without them)");
    cmd->add_option("--base-units", a->base_units,
                    "Unit of --base-body: m, dm, cm or mm (default: inferred from its height)");
    cmd->add_option("--base-up", a->base_up, "Up axis of --base-body")->capture_default_str();
    cmd->add_option("--base-front", a->base_front, "Front axis of --base-body")
        ->capture_default_str();
    cmd->add_option("--wrinkles", a->wrinkles,
                    "Add fine wrinkles to the drape from a wrinkle database of its fabric "
                    "(tapeline wrinkles train); --out is then the wrinkled garment");
    cmd->add_option("--coarse-out", a->coarse_out,
                    "With --wrinkles: also write the drape without them (OBJ)");
    cmd->add_option("--seed", a->seed, "Random seed of the grading (with --to-body)")
        ->capture_default_str();
    cmd->add_flag("--strict", a->strict,
                  "Exit non-zero, writing nothing, when a quality gate fails");
    cmd->callback([a] { run_dress(*a); });
}

}  // namespace tapeline::app
