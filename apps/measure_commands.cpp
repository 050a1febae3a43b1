// `tapeline measure BODY --units dm --out m.json [--vit m.vit] [--picture m.svg]`: landmarks, tape
// girths and lengths along the skin of a body mesh (measurement module), written as JSON (mm,
// ISO 8559-1 and FreeSewing names, the tape loops and paths), optionally as a Seamly2D individual
// measurement file and as a picture (front and side views with every tape, SVG or PNG).
#include "commands.h"

#include <tapeline/bench/measure_run.h>
#include <tapeline/core/atomic_write.h>
#include <tapeline/core/errors.h>
#include <tapeline/core/mesh_io.h>
#include <tapeline/measurement/measurement_json.h>
#include <tapeline/measurement/picture.h>
#include <tapeline/sizes/json_formats.h>
#include <tapeline/sizes/seamly.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <unistd.h>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace tapeline::app {
namespace {

namespace tm = tapeline::measurement;
using Json = nlohmann::ordered_json;
using MeasureMesh =
    CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;

struct MeasureArgs {
    std::string body;
    std::string units;
    std::string out;
    std::string up = tm::BodyOptions{}.up.to_string();
    std::string front = tm::BodyOptions{}.front.to_string();
    std::string pose = tm::to_string(tm::BodyOptions{}.pose);
    std::string landmarks;
    std::string vit;
    std::vector<std::string> pictures;
    bool strict = false;
    bool flat_facets = false;
};

std::string lower_extension(const std::string& path) {
    std::string e = std::filesystem::path(path).extension().string();
    for (char& c : e) {
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return e;
}

/// Refuses an output path whose extension is wrong or whose directory cannot be written, before
/// any work is done (so a run never writes one output and then fails on the next).
void check_output(const std::string& path, const std::string& ext, const std::string& option) {
    if (lower_extension(path) != ext) {
        throw InvalidInput(option + ": " + path + ": expected a " + ext + " file");
    }
    std::filesystem::path dir = std::filesystem::path(path).parent_path();
    if (dir.empty()) {
        dir = ".";
    }
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec)) {
        throw InvalidInput(option + ": " + path + ": directory " + dir.string() +
                           " does not exist");
    }
    if (::access(dir.c_str(), W_OK) != 0) {
        throw InvalidInput(option + ": " + path + ": cannot write in directory " + dir.string());
    }
}

void run_measure(const MeasureArgs& a) {
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    const tm::BodyOptions body =
        tm::parse_body_options(a.body, a.units, a.up, a.front, a.pose, "--");
    check_output(a.out, ".json", "--out");
    if (!a.vit.empty()) {
        check_output(a.vit, ".vit", "--vit");
    }
    std::vector<std::string> paths{a.out, a.vit};
    for (const std::string& picture : a.pictures) {
        tm::picture_format(picture, "--picture");  // .svg or .png, else refused before any work
        check_output(picture, lower_extension(picture), "--picture");
        paths.push_back(picture);
    }
    // Every output is written to a temporary name and all are renamed at the end: a failure
    // (a full disk, say) leaves none of them.
    OutputFiles outputs(paths);
    const tm::LandmarkOverrides overrides =
        a.landmarks.empty() ? tm::LandmarkOverrides{} : tm::read_landmark_overrides(a.landmarks);

    const auto loaded = read_triangle_mesh<MeasureMesh>(a.body);
    const auto t1 = Clock::now();
    bench::MeasureRun run = bench::measure_mesh(loaded.mesh, body, overrides, true, [&] {
        tm::MeasureOptions o;
        o.smooth_surface = !a.flat_facets;
        return o;
    }());
    tm::BodyMeasurements& r = run.result;
    const auto t2 = Clock::now();

    const Json j = bench::measure_json(run, a.body, std::chrono::duration<double>(t1 - t0).count(),
                                       std::chrono::duration<double>(t2 - t0).count());

    for (const auto& h : r.report.holes) {
        std::cerr << "tapeline: " << a.body << ": filled a hole "
                  << tm::internal::grouped_mm(h.size) << " mm across at "
                  << tm::internal::grouped_mm(h.height) << " mm height, " << h.region << " ("
                  << h.filling << ", " << h.faces_added << " faces)\n";
    }
    for (const auto& w : r.report.warnings) {
        std::cerr << "tapeline: warning: " << w << '\n';
    }
    for (const auto& w : r.warnings) {
        std::cerr << "tapeline: warning: " << w.rule << ": " << w.message << '\n';
    }
    if (a.strict && !r.warnings.empty()) {
        throw InvalidInput(a.body + ": " + std::to_string(r.warnings.size()) +
                           " self-check warning(s) with --strict (nothing written); the first: " +
                           r.warnings.front().message);
    }
    const std::string text = j.dump(1) + "\n";
    if (!a.pictures.empty()) {
        tm::PictureOptions po;
        po.title = std::filesystem::path(a.body).filename().string();
        const tm::PictureMesh pm = tm::picture_mesh(loaded.mesh, r.frame);
        for (const std::string& picture : a.pictures) {
            tm::write_measurement_picture(outputs.temporary(picture), pm.points, pm.triangles,
                                          r.measurements, r.landmarks, po);
        }
    }
    if (!a.vit.empty()) {
        outputs.write(a.vit, [&](std::ostream& out) {
            sizes::write_seamly_individual(out, tm::named_values(r.measurements), a.body);
        });
    }
    outputs.write(a.out, [&](std::ostream& out) { out << text; });
    outputs.commit();
    std::cout << a.out << ": " << r.measurements.measurements.size() << " measurements, "
              << r.measurements.missing.size() << " missing, " << r.report.landmarks_found << "/"
              << r.landmarks.landmarks.size() << " landmarks (unit " << tm::to_string(r.frame.unit)
              << (r.frame.unit_inferred ? ", inferred" : "") << ", height " << std::fixed
              << std::setprecision(1) << r.frame.height << " mm)\n";
}

}  // namespace

void register_measure_commands(CLI::App& app) {
    auto args = std::make_shared<MeasureArgs>();
    CLI::App* cmd = app.add_subcommand(
        "measure",
        "Measure a body mesh: landmarks, tape girths and lengths along the skin (mm, ISO 8559-1, "
        "FreeSewing and Seamly2D names)");
    cmd->add_option("BODY", args->body,
                    "Body mesh (OBJ, OFF, PLY, STL); holes up to 5 % of the stature across are "
                    "filled")
        ->required();
    cmd->add_option("--units", args->units,
                    "Length unit of the mesh: m, dm, cm or mm (required when the height does not "
                    "tell it)");
    cmd->add_option("--out", args->out, "Output JSON file")->required();
    cmd->add_option("--up", args->up, "Up axis of the mesh (+X, -X, +Y, -Y, +Z, -Z)")
        ->capture_default_str();
    cmd->add_option("--front", args->front, "Axis the body faces")->capture_default_str();
    cmd->add_option("--pose", args->pose, "A or T")->capture_default_str();
    cmd->add_option("--landmarks", args->landmarks, "JSON file overriding landmarks");
    cmd->add_option("--vit", args->vit, "Also write a Seamly2D individual measurement file");
    cmd->add_option("--picture", args->pictures,
                    "Also draw front and side views with every tape and label (.svg or .png; may "
                    "be given more than once)")
        ->expected(1)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    cmd->add_flag("--strict", args->strict,
                  "Exit non-zero when a self-check warns (the JSON's \"warnings\")");
    cmd->add_flag("--flat-facets", args->flat_facets,
                  "Take the girths round the mesh's flat facets, not round the smooth surface its "
                  "vertices and normals stand for (a coarse mesh then measures short)");
    cmd->callback([args] { run_measure(*args); });
}

}  // namespace tapeline::app
