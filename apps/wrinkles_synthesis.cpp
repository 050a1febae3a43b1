// `tapeline wrinkles refine COARSE.obj --body BODY --out FINE.obj` (refine.h: a fine drape
// started from a coarse one, the training data), `tapeline wrinkles train --fabric F --out DB.json
// COARSE FINE [COARSE FINE ...]` (synthesis.h: the database), and `tapeline wrinkles apply
// COARSE.obj --db DB.json --out FINE.obj [--body BODY] [--against SIM.obj]` (synthesis and its
// check). Garment OBJs are as `tapeline dress` writes them: positions in the body's coordinates and
// unit, pattern coordinates in mm. With a body, everything happens in the body's canonical frame
// (measurement/body.h: millimetres, holes filled) and is written back in the input's.
#include "commands.h"
#include "output.h"
#include "wrinkles_dress.h"
#include "wrinkles_io.h"

#include <tapeline/bench/methods.h>
#include <tapeline/core/atomic_write.h>
#include <tapeline/core/errors.h>
#include <tapeline/core/json_read.h>
#include <tapeline/core/mesh_io.h>
#include <tapeline/core/progress.h>
#include <tapeline/draw/png.h>
#include <tapeline/garment/collider.h>
#include <tapeline/garment/fabric.h>
#include <tapeline/garment/garment_io.h>
#include <tapeline/measurement/body.h>
#include <tapeline/wrinkles/classify.h>
#include <tapeline/wrinkles/picture.h>
#include <tapeline/wrinkles/refine.h>
#include <tapeline/wrinkles/synthesis.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace tapeline::app {
namespace {

namespace tg = tapeline::garment;
namespace tm = tapeline::measurement;
namespace tw = tapeline::wrinkles;
using wrinkles_io::cell;
using wrinkles_io::garment_in_mm;
using wrinkles_io::garment_unit;
using wrinkles_io::units_option;

/// A body read for the wrinkle commands: canonical millimetres, holes filled, closed.
struct LoadedBody {
    tm::Body body;
    std::unique_ptr<tg::SignedDistanceGrid> sdf;
};

LoadedBody load_body(const std::string& path, const std::string& units) {
    const auto loaded = read_triangle_mesh<bench::Mesh>(path);
    LoadedBody b{
        tm::make_body(loaded.mesh,
                      tm::parse_body_options(path, units == "auto" ? "" : units, "+Y", "+Z", "A")),
        nullptr};
    b.sdf = std::make_unique<tg::SignedDistanceGrid>(b.body.points(), b.body.triangles(),
                                                     tg::ColliderOptions{});
    return b;
}

/// A garment OBJ in the canonical frame of `body` (it must be in the body's input frame and
/// unit, as `tapeline dress` writes it): refuses one whose unit, found from its pattern
/// coordinates, is not the body's.
tg::GarmentMesh garment_on_body(const std::string& path, const LoadedBody& b) {
    tg::GarmentMesh g = tg::read_garment_obj(path);
    const LengthUnit found = garment_unit(g, path);
    if (found != b.body.frame.unit) {
        throw InvalidInput(path + ": its positions are in " + to_string(found) +
                           " (from its pattern coordinates), the body's in " +
                           to_string(b.body.frame.unit) +
                           ": a garment must be in its body's coordinates and unit");
    }
    for (tg::Vec3& p : g.positions) {
        p = b.body.frame.to_canonical(p);
    }
    return g;
}

std::string file_name(const std::string& path) {
    return std::filesystem::path(path).filename().string();
}

void expect_extension(const std::string& path, const char* option, const char* ext) {
    if (!path.empty() && extension_of(path) != ext) {
        throw InvalidInput(std::string(option) + " " + path + ": expected a " + ext + " file");
    }
}

// --- refine ---------------------------------------------------------------------------------

struct RefineArgs {
    std::string coarse, body, units = "auto", fabric = "cotton_jersey", out, report;
    tw::RefineOptions options;
    int relax_iterations = 80;
    int threads = 0;
};

void run_refine(const RefineArgs& a) {
    expect_extension(a.out, "--out", ".obj");
    expect_extension(a.report, "--report", ".json");
    OutputFiles outputs({a.out, a.report});
    const tg::FabricParams fabric = tg::fabric_from(a.fabric);
    const LoadedBody b = load_body(a.body, a.units);
    const tg::GarmentMesh coarse = garment_on_body(a.coarse, b);
    tw::RefineOptions o = a.options;
    o.relax_options = tg::RelaxOptions::proportional(a.relax_iterations);
    o.drape.threads = a.threads;
    o.collider.threads = a.threads;
    const tw::RefineResult r =
        tw::refine_drape(coarse, b.body.points(), b.body.triangles(), fabric, o);
    const tw::RefineReport& rep = r.report;
    std::printf(
        "%s: %zu vertices -> %zu vertices, %zu triangles (median edge %.1f mm), fabric %s\n",
        a.coarse.c_str(), rep.coarse_vertices, rep.fine_vertices, rep.fine_triangles,
        rep.median_edge_mm, fabric.name.c_str());
    std::printf("%zu frames, static solve %d iterations (%s, last move %.3f mm), %.1f s\n",
                rep.frames, rep.relax.iterations,
                rep.relax.converged ? "converged" : "not converged", rep.relax.last_max_move_mm,
                rep.seconds);
    std::printf(
        "before/after: %zu/%zu vertices inside the body, %zu/%zu self-intersections, p95 "
        "stretch %.3f/%.3f\n",
        rep.quality_before.vertices_inside_body, rep.quality_after.vertices_inside_body,
        rep.quality_before.self_intersections, rep.quality_after.self_intersections,
        rep.quality_before.stretch_p95, rep.quality_after.stretch_p95);
    const tm::BodyFrame frame = b.body.frame;
    const tg::PositionMap to_input = [frame](const tg::Vec3& p) { return frame.to_input(p); };
    outputs.write(a.out, [&](std::ostream& out) { tg::write_garment_obj(out, r.fine, to_input); });
    if (!a.report.empty()) {
        nlohmann::ordered_json j;
        j["coarse"] = a.coarse;
        j["body"] = a.body;
        j["fabric"] = fabric.name;
        j["levels"] = o.levels;
        j["seed"] = o.seed;
        j["noise_mm"] = o.noise_mm;
        j["coarse_vertices"] = rep.coarse_vertices;
        j["fine_vertices"] = rep.fine_vertices;
        j["fine_triangles"] = rep.fine_triangles;
        j["median_edge_mm"] = rep.median_edge_mm;
        j["frames"] = rep.frames;
        j["relax_iterations"] = rep.relax.iterations;
        j["relax_converged"] = rep.relax.converged;
        j["seconds"] = rep.seconds;
        j["solve_seconds"] = rep.solve_seconds;
        for (const auto& [name, q] :
             {std::pair<const char*, const tg::QualityFigures*>{"before", &rep.quality_before},
              {"after", &rep.quality_after}}) {
            j["quality"][name] = {{"vertices_inside_body", q->vertices_inside_body},
                                  {"edges_crossing_body", q->edges_crossing_body},
                                  {"self_intersections", q->self_intersections},
                                  {"stretch_p95", q->stretch_p95}};
        }
        outputs.write(a.report, [&](std::ostream& out) { out << j.dump(1) << '\n'; });
    }
    outputs.commit();
}

// --- train ----------------------------------------------------------------------------------

struct TrainArgs {
    std::vector<std::string> pairs, bodies;
    std::string fabric = "cotton_jersey", units = "auto", out;
    tw::TrainOptions options;
};

void run_train(const TrainArgs& a) {
    expect_extension(a.out, "--out", ".json");
    if (a.pairs.empty() || a.pairs.size() % 2 != 0) {
        throw InvalidInput("wrinkles train: give pairs COARSE.obj FINE.obj (got " +
                           std::to_string(a.pairs.size()) + " files)");
    }
    const std::size_t n = a.pairs.size() / 2;
    if (!a.bodies.empty() && a.bodies.size() != n) {
        throw InvalidInput("wrinkles train: --bodies names " + std::to_string(a.bodies.size()) +
                           " bodies for " + std::to_string(n) + " pairs (one per pair)");
    }
    OutputFiles outputs({a.out});
    const tg::FabricParams fabric = tg::fabric_from(a.fabric);
    const auto t0 = std::chrono::steady_clock::now();
    tw::WrinkleDatabase db;
    db.options = a.options;
    Progress progress("wrinkles train", n);
    for (std::size_t i = 0; i < n; ++i) {
        const std::string& cp = a.pairs[2 * i];
        const std::string& fp = a.pairs[2 * i + 1];
        std::optional<LoadedBody> body;
        tg::GarmentMesh coarse, fine;
        if (!a.bodies.empty()) {
            body = load_body(a.bodies[i], a.units);
            coarse = garment_on_body(cp, *body);
            fine = garment_on_body(fp, *body);
        } else {
            const std::optional<LengthUnit> given = units_option(a.units);
            LengthUnit u1 = LengthUnit::mm, u2 = LengthUnit::mm;
            coarse = garment_in_mm(cp, given, u1);
            fine = garment_in_mm(fp, given, u2);
        }
        const std::size_t added = tw::add_training_pair(
            db,
            {&coarse, &fine, body ? body->sdf.get() : nullptr,
             file_name(cp) + " / " + file_name(fp) +
                 (a.bodies.empty() ? std::string() : " on " + file_name(a.bodies[i]))},
            fabric);
        progress.note(file_name(cp) + ": " + std::to_string(added) + " samples");
        progress.advance();
    }
    progress.finish();
    tw::finish_database(db);
    std::size_t waves = 0;
    for (double x : db.amplitude_mm) {
        waves += x > 0 ? 1 : 0;
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::string text;
    outputs.write(a.out, [&](std::ostream& out) {
        text = tw::wrinkle_database_json(db).dump() + "\n";
        out << text;
    });
    outputs.commit();
    std::printf(
        "%s: %zu samples from %zu pairs (%zu with a dominant wave), fabric %s%s, %.1f kB, "
        "%.1f s\n",
        a.out.c_str(), db.features.size(), n, waves, db.fabric.c_str(),
        db.uses_body ? ", with the body distance" : "", double(text.size()) / 1024.0, seconds);
}

// --- apply ----------------------------------------------------------------------------------

struct ApplyArgs {
    std::string coarse, db, fabric, body, units = "auto", out, report, against, picture;
    tw::SynthesisOptions options;
};

void run_apply(const ApplyArgs& a) {
    expect_extension(a.out, "--out", ".obj");
    expect_extension(a.report, "--report", ".json");
    expect_extension(a.picture, "--picture", ".png");
    OutputFiles outputs({a.out, a.report, a.picture});
    const tw::WrinkleDatabase db =
        tw::wrinkle_database_from_json(json::parse_json_file(a.db), a.db);
    const tg::FabricParams fabric = tg::fabric_from(a.fabric.empty() ? db.fabric : a.fabric);
    std::optional<LoadedBody> body;
    tg::GarmentMesh coarse, simulated;
    LengthUnit unit = LengthUnit::mm;
    if (!a.body.empty()) {
        body = load_body(a.body, a.units);
        coarse = garment_on_body(a.coarse, *body);
        if (!a.against.empty()) {
            simulated = garment_on_body(a.against, *body);
        }
        unit = body->body.frame.unit;
    } else {
        const std::optional<LengthUnit> given = units_option(a.units);
        coarse = garment_in_mm(a.coarse, given, unit);
        if (!a.against.empty()) {
            LengthUnit u2 = unit;
            simulated = garment_in_mm(a.against, given, u2);
        }
    }
    tw::BodySurface surface;
    if (body) {
        surface = {&body->body.points(), &body->body.triangles(), body->sdf.get()};
    }
    const tw::Synthesis s = tw::synthesize_wrinkles(coarse, db, fabric, surface, a.options);
    const tw::SynthesisReport& r = s.report;
    std::printf(
        "%s: %zu triangles -> %zu vertices, %zu triangles; database %s (%zu samples, "
        "fabric %s)\n",
        a.coarse.c_str(), r.coarse_triangles, r.fine_vertices, r.fine_triangles, a.db.c_str(),
        r.database_samples, db.fabric.c_str());
    std::printf("%-12s %11s %14s %18s\n", "class", "with_waves", "amplitude_mm",
                "pattern_lambda_mm");
    for (std::size_t c = 0; c < tw::kWrinkleClasses; ++c) {
        std::printf("%-12s %11zu %s %s\n", tw::to_string(tw::WrinkleClass(c)), r.with_wrinkles[c],
                    cell(r.median_amplitude_mm[c], 14).c_str(),
                    cell(r.median_wavelength_mm[c], 18).c_str());
    }
    std::printf("heights: rms %.2f mm, max %.2f mm, %zu vertices displaced; synthesis %.3f s\n",
                r.rms_height_mm, r.max_height_mm, r.displaced, r.synthesis_seconds);
    std::printf(
        "self-check (%.2f s): %zu vertices damped in %d rounds; new crossings left %zu, "
        "new body contacts left %s\n",
        r.fix_seconds, r.damped_vertices, r.fix_rounds_used, r.new_self_crossings_left,
        r.body_checked ? std::to_string(r.new_body_contacts_left).c_str()
                       : "not checked (no --body)");
    if (r.check_seconds > 0) {
        std::printf(
            "before/after (exact): %zu/%zu vertices inside the body, %zu/%zu edges through "
            "it, %zu/%zu self-intersections, p95 stretch %.3f/%.3f\n",
            r.quality_before.vertices_inside_body, r.quality_after.vertices_inside_body,
            r.quality_before.edges_crossing_body, r.quality_after.edges_crossing_body,
            r.quality_before.self_intersections, r.quality_after.self_intersections,
            r.quality_before.stretch_p95, r.quality_after.stretch_p95);
    }
    std::optional<tw::SynthesisCheck> check;
    if (!a.against.empty()) {
        check = tw::check_synthesis(coarse, s, db, simulated);
        std::printf("against %s: rms height %.2f mm simulated, %.2f mm synthesised\n",
                    a.against.c_str(), check->simulated_rms_height_mm,
                    check->synthesised_rms_height_mm);
        std::printf("%-12s %8s %10s %6s %14s %16s %8s\n", "class", "windows", "sim_waves", "both",
                    "lambda_err_%", "amplitude_err_%", "r");
        const auto row = [](const char* name, const tw::SynthesisCheckRow& x) {
            std::printf(
                "%-12s %8zu %10zu %6zu %s %s %s\n", name, x.windows, x.simulated, x.both,
                cell(x.median_wavelength_error_percent, 14).c_str(),
                cell(x.median_amplitude_error_percent, 16).c_str(),
                std::isfinite(x.pearson_r)
                    ? (std::string(4, ' ') + std::to_string(x.pearson_r).substr(0, 5)).c_str()
                    : "       -");
        };
        for (std::size_t c = 1; c < tw::kWrinkleClasses; ++c) {
            row(tw::to_string(tw::WrinkleClass(c)), check->per_class[c]);
        }
        row("compressed", check->all);
    }
    const tg::PositionMap to_output = [&](const tg::Vec3& p) {
        if (body) {
            return body->body.frame.to_input(p);
        }
        return vec3::scale(p, 1.0 / millimetres_per(unit));
    };
    outputs.write(a.out, [&](std::ostream& out) { tg::write_garment_obj(out, s.fine, to_output); });
    if (!a.report.empty()) {
        nlohmann::ordered_json j;
        j["coarse"] = a.coarse;
        j["database"] = a.db;
        j["fabric"] = fabric.name;
        j["body"] =
            a.body.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(a.body);
        j["levels"] = a.options.levels;
        j["neighbours"] = a.options.neighbours;
        j["synthesis"] = tw::synthesis_report_json(r);
        if (check) {
            j["against"] = a.against;
            j["check"] = tw::synthesis_check_json(*check);
        }
        outputs.write(a.report, [&](std::ostream& out) { out << j.dump(1) << '\n'; });
    }
    if (!a.picture.empty()) {
        const tw::WrinkleField field = tw::classify_wrinkles(coarse, fabric, db.options.classify);
        const std::string name = file_name(a.coarse);
        std::vector<draw::RgbaImage> parts;
        const std::vector<tg::Vec3> no_points;
        const std::vector<tg::Tri> no_tris;
        parts.push_back(tw::wrinkle_picture(coarse, field, name + ": coarse, by class"));
        parts.push_back(
            tw::height_picture(s.fine, s.height_mm, "synthesised: height over coarse", 0.5));
        if (check) {
            const tw::Embedding e = tw::embed_fine_in_coarse(coarse, simulated);
            std::vector<double> h(simulated.positions.size(), 0.0);
            for (std::size_t v = 0; v < h.size(); ++v) {
                h[v] = e.vertices[v].height_mm;
            }
            parts.push_back(tw::height_picture(simulated, h, "simulated: height over coarse", 0.5));
        }
        const draw::RgbaImage img = tw::stacked(parts);
        outputs.write(
            a.picture, [&](std::ostream& out) { draw::write_png(out, img, 5); }, true);
    }
    outputs.commit();
}

}  // namespace

struct WrinkleDressing::Impl {
    tw::WrinkleDatabase db;
    tg::FabricParams fabric;
    std::string path;
};

WrinkleDressing::WrinkleDressing(const std::string& path, const garment::FabricParams& fabric) {
    auto impl = std::make_shared<Impl>();
    impl->db = tw::wrinkle_database_from_json(json::parse_json_file(path), path);
    if (impl->db.fabric != fabric.name) {
        throw InvalidInput(path + ": a wrinkle database of fabric '" + impl->db.fabric +
                           "', the garment is of '" + fabric.name + "'");
    }
    impl->fabric = fabric;
    impl->path = path;
    impl_ = std::move(impl);
}

DressedWrinkles WrinkleDressing::apply(const garment::GarmentMesh& g,
                                       const measurement::Body& body) const {
    const tg::SignedDistanceGrid sdf(body.points(), body.triangles(), tg::ColliderOptions{});
    const tw::Synthesis s = tw::synthesize_wrinkles(g, impl_->db, impl_->fabric,
                                                    {&body.points(), &body.triangles(), &sdf}, {});
    const tw::SynthesisReport& r = s.report;
    DressedWrinkles out;
    out.garment = s.fine;
    out.stretch = tg::triangle_stretch(s.fine.positions, s.fine.triangles, s.fine.uv);
    out.report = tw::synthesis_report_json(r);
    out.report["database"] = impl_->path;
    char buf[400];
    std::snprintf(buf, sizeof buf,
                  "wrinkles from %s: %zu vertices, rms height %.2f mm, max %.2f mm, %.2f s; "
                  "inside the body %zu -> %zu, self-intersections %zu -> %zu",
                  impl_->path.c_str(), r.fine_vertices, r.rms_height_mm, r.max_height_mm,
                  r.synthesis_seconds, r.quality_before.vertices_inside_body,
                  r.quality_after.vertices_inside_body, r.quality_before.self_intersections,
                  r.quality_after.self_intersections);
    out.summary = buf;
    return out;
}

void register_wrinkles_synthesis(CLI::App& wr) {
    CLI::App* rf = wr.add_subcommand(
        "refine",
        "A fine drape started from a coarse one: the coarse drape subdivided, perturbed and "
        "brought to the cloth solver's equilibrium on the body (training data for synthesis)");
    auto ra = std::make_shared<RefineArgs>();
    rf->add_option("COARSE", ra->coarse, "Coarse drape OBJ (tapeline dress)")->required();
    rf->add_option("--body", ra->body, "The body it was draped on (its file)")->required();
    rf->add_option("--units", ra->units, "Unit of the body and garment: auto, mm, cm, dm, m")
        ->capture_default_str();
    rf->add_option("--fabric", ra->fabric, "Library fabric name or a .json fabric file")
        ->capture_default_str();
    rf->add_option("--out", ra->out, "The fine drape (OBJ)")->required();
    rf->add_option("--report", ra->report, "Report (JSON)");
    rf->add_option("--levels", ra->options.levels, "Subdivision levels (each halves the edges)")
        ->capture_default_str();
    rf->add_option("--frames", ra->options.frames, "Solver frames before the static solve")
        ->capture_default_str();
    rf->add_option("--noise", ra->options.noise_mm, "Seeded noise along the normals, mm")
        ->capture_default_str();
    rf->add_option("--seed", ra->options.seed, "Seed of the noise")->capture_default_str();
    rf->add_option("--relax-iterations", ra->relax_iterations, "Static solve iterations at most")
        ->capture_default_str();
    rf->add_option("--threads", ra->threads, "Solver threads (0: all cores)")
        ->capture_default_str();
    rf->callback([ra] { run_refine(*ra); });

    CLI::App* tr = wr.add_subcommand(
        "train",
        "A wrinkle database for a fabric from pairs of coarse and fine drapes of the same garment "
        "(features of each coarse triangle -> the fine drape's wave there)");
    auto ta = std::make_shared<TrainArgs>();
    tr->add_option("PAIRS", ta->pairs, "COARSE.obj FINE.obj, one or more pairs")->required();
    tr->add_option("--fabric", ta->fabric, "Library fabric name or a .json fabric file")
        ->capture_default_str();
    tr->add_option("--units", ta->units, "Unit of the OBJs (and bodies): auto, mm, cm, dm, m")
        ->capture_default_str();
    tr->add_option("--bodies", ta->bodies,
                   "The body of each pair (one per pair): adds the distance-to-body feature");
    tr->add_option("--out", ta->out, "The database (JSON)")->required();
    tr->add_option("--window-length", ta->options.window_length_mm,
                   "Window length along the compression axis, pattern mm")
        ->capture_default_str();
    tr->add_option("--window-width", ta->options.window_width_mm, "Window width, pattern mm")
        ->capture_default_str();
    tr->callback([ta] { run_train(*ta); });

    CLI::App* ap = wr.add_subcommand(
        "apply",
        "Fine wrinkles on a coarse drape from a wrinkle database: subdivided, displaced along the "
        "normal by the waves the database's look-alike regions show, checked for new "
        "self-intersections and body contacts");
    auto aa = std::make_shared<ApplyArgs>();
    ap->add_option("COARSE", aa->coarse, "Coarse drape OBJ (tapeline dress)")->required();
    ap->add_option("--db", aa->db, "Wrinkle database (tapeline wrinkles train)")->required();
    ap->add_option("--out", aa->out, "The wrinkled garment (OBJ)")->required();
    ap->add_option("--fabric", aa->fabric,
                   "The garment's fabric (default: the database's; must be the database's)");
    ap->add_option("--body", aa->body,
                   "The body it was draped on: distance feature and the body check");
    ap->add_option("--units", aa->units, "Unit of the OBJs (and body): auto, mm, cm, dm, m")
        ->capture_default_str();
    ap->add_option("--levels", aa->options.levels, "Subdivision levels")->capture_default_str();
    ap->add_option("--neighbours", aa->options.neighbours, "k nearest training regions")
        ->capture_default_str();
    ap->add_option("--clearance", aa->options.body_clearance_mm,
                   "Wrinkles may not bring cloth closer to the body than this, mm")
        ->capture_default_str();
    ap->add_option("--against", aa->against,
                   "A fine simulation of the same garment: wavelength, amplitude and correlation "
                   "of the synthesis against it");
    ap->add_option("--report", aa->report, "Report (JSON)");
    ap->add_option("--picture", aa->picture,
                   "Picture (PNG): coarse by class, synthesised and simulated by height");
    ap->callback([aa] { run_apply(*aa); });
}

}  // namespace tapeline::app
