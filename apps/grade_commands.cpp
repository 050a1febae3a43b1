// `tapeline grade PATTERN --from BASE --to TARGET --out graded.json`: resize a pattern to a target
// measurement set (grading/grade.h). Everything is computed in memory first; each output is then
// written to a temporary name and renamed, so a failure leaves no half-written file.
#include "commands.h"

#include <tapeline/core/errors.h>
#include <tapeline/pattern/pattern.h>
#include <tapeline/sizes/measurement_set.h>

#include <CLI/CLI.hpp>

#ifdef TAPELINE_HAVE_GRADING
#include <tapeline/bench/dress_run.h>
#include <tapeline/bench/grade_run.h>
#include <tapeline/core/atomic_write.h>
#include <tapeline/grading/compare.h>
#include <tapeline/grading/freesewing_bindings.h>
#include <tapeline/grading/grade.h>
#include <tapeline/grading/output.h>
#include <tapeline/pattern/database.h>
#include <tapeline/pattern/dxf.h>
#include <tapeline/pattern/freesewing_designs.h>
#include <tapeline/pattern/io_detect.h>
#include <tapeline/pattern/io_freesewing.h>
#include <tapeline/pattern/io_garmentcode.h>
#include <tapeline/pattern/io_json.h>
#include <tapeline/pattern/svg.h>
#include <tapeline/pattern/validate.h>
#include <tapeline/sizes/read_input.h>

#include <nlohmann/json.hpp>

#include <sys/stat.h>
#include <algorithm>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#endif

#include <string>
#include <utility>
#include <vector>

namespace tapeline::app {

#ifdef TAPELINE_HAVE_GRADING
namespace {

namespace tp = tapeline::pattern;
namespace tgr = tapeline::grading;

struct GradeArgs {
    std::string pattern, format = "auto", db, from, to, from_set, to_set;
    std::string out, svg, dxf, pareto, rules, rul, report, fit_table, compare;
    std::string base_body, base_units, base_up = "+Y", base_front = "+Z", bindings, bindings_out;
    // Defaults read from the library's options.
    std::string ease = tgr::to_string(tgr::GradingOptions{}.ease);
    bool store = false, replace = false, no_polish = !tgr::GradingOptions{}.ceres_polish;
    bool no_fs_bindings = false;
    bool fs_seams_only = false;
    std::uint32_t seed = tgr::GradingOptions{}.seed;
    std::size_t population = tgr::GradingOptions{}.population;
    std::size_t generations = tgr::GradingOptions{}.generations;
    std::size_t threads = tgr::GradingOptions{}.threads;
    double max_target_ratio = tgr::GradingOptions{}.max_target_ratio;
};

std::string extension(const std::string& path) {
    const auto dot = path.find_last_of('.');
    const auto slash = path.find_last_of('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) {
        return "";
    }
    std::string e = path.substr(dot);
    for (char& c : e) {
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return e;
}

tp::Pattern load_pattern(const GradeArgs& a) {
    if (is_file(a.pattern)) {
        return tp::read_pattern_file(a.pattern, a.format, nullptr);
    }
    const std::string path = a.db.empty() ? tp::default_pattern_database_path() : a.db;
    if (!is_file(path)) {
        throw InvalidInput(a.pattern + ": no such pattern file, and no pattern database at " +
                           path);
    }
    tp::DatabaseOptions o;
    o.read_only = true;
    o.create = false;
    return tp::PatternDatabase(path, o).load(a.pattern);
}

void run_grade(const GradeArgs& a) {
    // Everything is read and checked before anything is computed or written.
    const std::string out_ext = extension(a.out);
    if (out_ext != ".json" && out_ext != ".svg" && out_ext != ".dxf") {
        throw InvalidInput("--out " + a.out + ": unknown extension '" + out_ext +
                           "' (expected .json, .svg or .dxf)");
    }
    if (a.ease != "proportional" && a.ease != "keep_mm") {
        throw InvalidInput("--ease: unknown mode '" + a.ease + "' (proportional or keep_mm)");
    }
    if (a.base_body.empty() == a.from.empty()) {
        throw InvalidInput(
            "give the pattern's base measurements either as a set (--from) or as a body to lay "
            "the pattern on (--base-body), not both");
    }
    if (a.base_body.empty() &&
        (!a.base_units.empty() || a.base_up != "+Y" || a.base_front != "+Z")) {
        throw InvalidInput("--base-units, --base-up and --base-front describe --base-body");
    }
    if (!a.bindings_out.empty() && extension(a.bindings_out) != ".json") {
        throw InvalidInput("--bindings-out " + a.bindings_out + ": expected a .json file");
    }
    OutputFiles outputs(
        {a.out, a.svg, a.dxf, a.pareto, a.rules, a.rul, a.report, a.fit_table, a.bindings_out});
    tp::Pattern base = load_pattern(a);
    tp::require_valid(base);
    sizes::MeasurementSet from;
    std::vector<std::string> inferred;  // how each inferred binding was found
    // Where each measurement's binding came from, for the report.
    std::map<std::string, std::string> origin;
    for (const tp::MeasurementBinding& b : base.bindings) {
        origin[b.measurement] = "pattern";
    }
    if (!a.base_body.empty()) {
        // The base measurements are the body's; the girth bindings are found by laying the
        // pattern on it (garment/bindings.h).
        bench::BodyBase b = bench::base_from_body(
            std::move(base), a.base_body,
            measurement::parse_body_options(a.base_body, a.base_units, a.base_up, a.base_front, "A",
                                            "--base-"));
        base = std::move(b.pattern);
        from = std::move(b.measurements);
        inferred = std::move(b.notes);
        origin.clear();
        for (const tp::MeasurementBinding& x : base.bindings) {
            origin[x.measurement] = "found on the body";
        }
    } else {
        from = sizes::read_measurement_input(a.from, a.from_set);
    }
    if (!a.bindings.empty()) {
        for (const std::string& name : tp::apply_bindings_file(base, a.bindings)) {
            origin[name] = "bindings file";
        }
        inferred.push_back("bindings of " + a.bindings + " given");
    }
    const sizes::MeasurementSet to = sizes::read_measurement_input(a.to, a.to_set);
    for (const sizes::MeasurementSet* set : {&std::as_const(from), &to}) {
        for (const auto& [name, why] : set->left_out) {
            std::cerr << "tapeline: warning: " << why << "; '" << name << "' left out\n";
        }
    }
    tgr::GradingOptions o;
    o.seed = a.seed;
    o.population = a.population;
    o.generations = a.generations;
    o.threads = a.threads;
    o.max_target_ratio = a.max_target_ratio;
    o.ceres_polish = !a.no_polish;
    o.ease = a.ease == "keep_mm" ? tgr::EaseMode::keep_mm : tgr::EaseMode::proportional;
    tgr::GradeResult g =
        bench::grade_as_tool(base, from, to, o, !a.no_fs_bindings, !a.fs_seams_only);
    // What grading added (FreeSewing's table), then one line per origin.
    std::map<std::string, std::vector<std::string>> by_origin;
    for (const tgr::FitRow& row : g.report.fit) {
        const std::string& o = origin.emplace(row.measurement, "FreeSewing table").first->second;
        auto& names = by_origin[o];
        if (std::find(names.begin(), names.end(), row.measurement) == names.end()) {
            names.push_back(row.measurement);
        }
    }
    for (const auto& [o, names] : by_origin) {
        std::string line = "origin: " + o + ": ";
        for (std::size_t i = 0; i < names.size(); ++i) {
            line += (i ? ", " : "") + names[i];
        }
        inferred.push_back(line);
    }
    for (const std::string& line : inferred) {
        g.report.notes.push_back("binding: " + line);
    }
    // The report's fit rows say where their binding came from.
    const auto report_with_origins = [&] {
        nlohmann::json rep = tgr::report_json(g.report);
        for (nlohmann::json& row : rep["fit"]) {
            row["origin"] = origin.at(row["measurement"].get<std::string>());
        }
        return rep;
    };

    // Render every output in memory, then write each atomically.
    std::vector<std::pair<std::string, std::string>> files;
    auto render = [&](const std::string& path, const std::string& ext) {
        std::ostringstream s;
        if (ext == ".json") {
            tp::write_pattern_json(g.pattern, s);
        } else if (ext == ".svg") {
            s << tp::to_svg(g.pattern);
        } else {
            tp::write_dxf(g.pattern, s);
        }
        files.push_back({path, s.str()});
    };
    render(a.out, out_ext);
    if (!a.svg.empty()) {
        render(a.svg, ".svg");
    }
    if (!a.dxf.empty()) {
        render(a.dxf, ".dxf");
    }
    if (!a.pareto.empty()) {
        const std::vector<std::uint8_t> png = tgr::pareto_png(g.report);
        files.push_back({a.pareto, std::string(png.begin(), png.end())});
    }
    if (!a.rules.empty()) {
        files.push_back({a.rules, tgr::rules_json(g, from.name, to.name).dump(1) + "\n"});
    }
    if (!a.rul.empty()) {
        files.push_back({a.rul, tgr::rul_table(g, from.name, to.name)});
    }
    if (!a.report.empty()) {
        files.push_back({a.report, report_with_origins().dump(1) + "\n"});
    }
    if (!a.compare.empty()) {
        // Validation against a reference draft of the target size (benchmarks/run_grading.sh):
        // the graded pieces, the unchanged base pieces, and each base piece scaled uniformly by
        // the ratio of the reference perimeter to its own (an oracle: it needs the answer).
        GradeArgs ra = a;
        ra.pattern = a.compare;
        const tp::Pattern ref = load_pattern(ra);
        nlohmann::json c = nlohmann::json::array();
        for (const tp::Piece& rp : ref.pieces) {
            const tp::Piece* bp = tp::find_piece(base, rp.name);
            const tp::Piece* gp = tp::find_piece(g.pattern, rp.name);
            if (!bp || !gp) {
                continue;
            }
            const double s = tp::length(rp.outline) / tp::length(bp->outline);
            const tgr::PieceDeviation dg = tgr::outline_deviation(rp.outline, gp->outline);
            const tgr::PieceDeviation du = tgr::outline_deviation(rp.outline, bp->outline);
            const tgr::PieceDeviation ds =
                tgr::outline_deviation(rp.outline, tgr::scaled_piece(*bp, s).outline);
            c.push_back({{"piece", rp.name},
                         {"graded_mean_mm", dg.mean_mm},
                         {"graded_max_mm", dg.max_mm},
                         {"unchanged_mean_mm", du.mean_mm},
                         {"unchanged_max_mm", du.max_mm},
                         {"uniform_oracle_mean_mm", ds.mean_mm},
                         {"uniform_oracle_max_mm", ds.max_mm}});
        }
        nlohmann::json rep = report_with_origins();
        rep["comparison"] = c;
        rep["pattern"] = base.name;
        rep["from"] = from.name;
        rep["to"] = to.name;
        std::cout << "comparison: " << c.dump() << '\n';
        if (!a.report.empty()) {
            files.back().second = rep.dump(1) + "\n";  // the report is the last file so far
        }
    }
    if (!a.fit_table.empty()) {
        files.push_back({a.fit_table, tgr::fit_table(g.report)});
    }
    if (!a.bindings_out.empty()) {
        // The bindings graded with (inferred, given, or the pattern's own and FreeSewing's
        // table), on the base pattern's points.
        tp::Pattern bound = base;
        if (!a.no_fs_bindings && !a.fs_seams_only && bound.designer == "FreeSewing") {
            tgr::add_freesewing_bindings(bound);
        }
        files.push_back({a.bindings_out, tp::bindings_file_json(bound).dump(1) + "\n"});
    }
    for (const auto& file : files) {
        const std::string& text = file.second;
        outputs.write(
            file.first,
            [&](std::ostream& s) { s.write(text.data(), std::streamsize(text.size())); }, true);
    }
    outputs.commit();
    if (a.store) {
        const std::string path = a.db.empty() ? tp::default_pattern_database_path() : a.db;
        tp::PatternDatabase database(path, {});
        database.store(g.pattern, {a.replace});
    }
    for (const std::string& line : inferred) {
        std::cout << "binding: " << line << '\n';
    }
    std::cout << "graded " << base.name << " from " << from.name << " to " << to.name << ": "
              << g.report.fit.size() << " bindings, " << g.report.seams.size() << " seams, "
              << g.report.front.size() << " candidates, " << g.report.timings.total_s << " s\n"
              << tgr::fit_table(g.report) << "chosen: " << g.report.chosen << " ("
              << g.report.chosen_why << ")\nstyle: max angle change "
              << g.report.style.max_angle_change_deg << " deg, max curve change "
              << g.report.style.max_curve_change << ", proportion spread "
              << g.report.style.proportion_spread << '\n';
    if (!g.report.within_tolerance) {
        std::cerr << "tapeline: warning: not every binding and seam is within tolerance (worst "
                  << g.report.max_fit_error_mm << " mm fit, " << g.report.max_seam_mismatch_mm
                  << " mm seam)\n";
    }
}

}  // namespace
#endif

void register_grade_commands(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand(
        "grade", "Resize a pattern to a target measurement set, keeping its style");
#ifdef TAPELINE_HAVE_GRADING
    auto a = std::make_shared<GradeArgs>();
    cmd->add_option("pattern", a->pattern,
                    "Pattern file (FreeSewing, GarmentCode, tapeline JSON) "
                    "or a name in the database")
        ->required();
    cmd->add_option("--from", a->from,
                    "Base measurement set (.json flat/FreeSewing/measure, .vit); or --base-body");
    cmd->add_option("--base-body", a->base_body,
                    "Body the pattern was made for (.obj, .ply, .off, .stl): measured for the "
                    "base set, and the pattern laid on it to find its girth bindings");
    cmd->add_option("--base-units", a->base_units,
                    "Unit of --base-body: m, dm, cm or mm (default: inferred from its height)");
    cmd->add_option("--base-up", a->base_up, "Up axis of --base-body")->capture_default_str();
    cmd->add_option("--base-front", a->base_front, "Front axis of --base-body")
        ->capture_default_str();
    cmd->add_option("--bindings", a->bindings,
                    "Bindings file (tapeline-bindings JSON, e.g. from --bindings-out, edited): "
                    "its bindings replace those of the same measurement");
    cmd->add_option("--bindings-out", a->bindings_out,
                    "Write the bindings graded with, and the points they use (JSON)");
    cmd->add_option("--to", a->to, "Target measurement set (same formats)")->required();
    cmd->add_option("--from-set", a->from_set, "Set name inside a FreeSewing sets file");
    cmd->add_option("--to-set", a->to_set, "Set name inside a FreeSewing sets file");
    cmd->add_option("--out", a->out, "Graded pattern (.json, .svg or .dxf)")->required();
    cmd->add_option("--svg", a->svg, "Also write the graded pattern as SVG");
    cmd->add_option("--dxf", a->dxf, "Also write the graded pattern as AAMA DXF");
    cmd->add_option("--pareto", a->pareto, "Pareto front plot (PNG)");
    cmd->add_option("--rules", a->rules, "Grade rules, per point base → graded (JSON)");
    cmd->add_option("--rul", a->rul, "Grade rules as a .RUL-like delta table");
    cmd->add_option("--report", a->report, "Grading report (JSON)");
    cmd->add_option("--fit-table", a->fit_table, "Fit table (text)");
    cmd->add_option("--compare", a->compare,
                    "Reference draft of the target size: outline deviation in the report");
    cmd->add_option("--seed", a->seed, "Random seed (NSGA-II)")->capture_default_str();
    cmd->add_option("--population", a->population, "NSGA-II population")
        ->check(CLI::Range(0, 100000))
        ->capture_default_str();
    cmd->add_option("--generations", a->generations, "NSGA-II generations (0: Ceres only)")
        ->check(CLI::Range(0, 100000))
        ->capture_default_str();
    cmd->add_option("--threads", a->threads, "Threads (0: all)")->check(CLI::Range(0, 1024));
    cmd->add_option("--ease", a->ease, "Ease mode: proportional or keep_mm")->capture_default_str();
    cmd->add_option("--max-target-ratio", a->max_target_ratio,
                    "Refuse a target more than this many times its base value, or less than its "
                    "base value divided by it (0: no limit)")
        ->check(CLI::Range(0.0, 1000.0))
        ->capture_default_str();
    cmd->add_flag("--no-polish", a->no_polish, "Do not polish the front members with Ceres");
    cmd->add_flag("--no-freesewing-bindings", a->no_fs_bindings,
                  "Only the importer's bindings (no FreeSewing point-name bindings or seams)");
    cmd->add_flag("--freesewing-seams-only", a->fs_seams_only,
                  "FreeSewing's seam rules but no point-name bindings (with --base-body: only "
                  "the bindings found on the body)")
        ->excludes("--no-freesewing-bindings");
    cmd->add_option("--format", a->format, "Pattern format: auto, freesewing, garmentcode, json");
    cmd->add_option("--db", a->db, "Pattern database (SQLite file)");
    cmd->add_flag("--store", a->store, "Store the graded pattern in the database");
    cmd->add_flag("--replace", a->replace, "With --store: overwrite a pattern of the same name");
    cmd->callback([a] { run_grade(*a); });
#else
    cmd->allow_extras();
    cmd->callback([] {
        throw InvalidInput(
            "grade: this tapeline was built without Ceres or pagmo "
            "(install libceres-dev and libpagmo-dev)");
    });
#endif
}

}  // namespace tapeline::app
