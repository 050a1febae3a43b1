// `tapeline wrinkles buckling --test foundation|cylinder --bending LIST [--fabric NAME|file.json]
// [--resolution MM] [--foundation K] [--radius R] [--height H] [--strain E] [--report r.json]
// [--picture p.png] [--profile q.png] [--threads N]`: virtual buckling experiments that check the
// wrinkle wavelength law λ = 2π(B/K)^{1/4} on the cloth solver over a list of bending
// rigidities, and the log–log slope of the measured wavelength against B
// (wrinkles/buckling_tests.h).
#include "commands.h"
#include "output.h"

#include <tapeline/core/atomic_write.h>
#include <tapeline/core/errors.h>
#include <tapeline/draw/png.h>
#include <tapeline/garment/fabric.h>
#include <tapeline/wrinkles/buckling_tests.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace tapeline::app {
namespace {

namespace tw = tapeline::wrinkles;

struct BucklingArgs {
    std::string test, fabric = "cotton_jersey", report, picture, profile;
    std::vector<double> bending;
    double resolution = 0;  // 0: the test's default
    double foundation = 5000;
    double radius = 40;
    double height = 0;  // 0: four times the radius
    double strain = 0;  // 0: the test's default
    int threads = 1;
};

std::string num(const char* f, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, v);
    return buf;
}

void run_buckling(const BucklingArgs& a) {
    if (a.test != "foundation" && a.test != "cylinder") {
        throw InvalidInput("--test '" + a.test + "': expected foundation or cylinder");
    }
    if (a.bending.size() < 2) {
        throw InvalidInput("--bending: give two or more rigidities (µN·m), e.g. 0.5,1,2,5");
    }
    for (std::size_t i = 0; i < a.bending.size(); ++i) {
        if (!(std::isfinite(a.bending[i]) && a.bending[i] > 0 && a.bending[i] <= 1e4)) {
            throw InvalidInput("--bending: value " + std::to_string(i + 1) +
                               " must be within 0 and 10000 µN·m, got " +
                               std::to_string(a.bending[i]));
        }
    }
    if (!a.report.empty() && extension_of(a.report) != ".json") {
        throw InvalidInput("--report " + a.report + ": expected a .json file");
    }
    for (const std::string* p : {&a.picture, &a.profile}) {
        if (!p->empty() && extension_of(*p) != ".png") {
            throw InvalidInput((p == &a.picture ? "--picture " : "--profile ") + *p +
                               ": expected a .png file");
        }
    }
    if (!(std::isfinite(a.foundation) && a.foundation > 0)) {
        throw InvalidInput("--foundation must be finite and > 0 N/m³, got " +
                           std::to_string(a.foundation));
    }
    if (!(std::isfinite(a.height) && a.height >= 0)) {
        throw InvalidInput("--height must be finite and > 0 mm, got " + std::to_string(a.height));
    }
    if (!(std::isfinite(a.radius) && a.radius > 0)) {
        throw InvalidInput("--radius must be finite and > 0 mm, got " + std::to_string(a.radius));
    }
    OutputFiles outputs({a.report, a.picture, a.profile});
    const garment::FabricParams fabric = garment::fabric_from(a.fabric);
    tw::BucklingOptions o;
    const bool tube = a.test == "cylinder";
    o.resolution_mm = a.resolution > 0 ? a.resolution : (tube ? 1.5 : 2.5);
    o.strain = a.strain > 0 ? a.strain : (tube ? 0.02 : 0.01);
    o.foundation_n_m3 = a.foundation;
    o.radius_mm = a.radius;
    o.height_mm = a.height > 0 ? a.height : 4 * a.radius;
    o.threads = a.threads;
    o.progress = [](const std::string& line) { std::cerr << line << '\n'; };
    const tw::ScalingSweep s = tw::scaling_sweep(a.test, fabric, a.bending, o);

    nlohmann::ordered_json j;
    j["test"] = a.test;
    j["fabric"] = fabric.name;
    j["law"] = tube ? "lambda = 2 pi (B R^2 / Y)^(1/4)" : "lambda = 2 pi (B / K)^(1/4)";
    j["resolution_mm"] = o.resolution_mm;
    j["strain"] = o.strain;
    j["first_strain"] = o.first_strain;
    j["imperfection_mm"] = o.imperfection_mm;
    j["seed"] = o.seed;
    j["threads"] = o.threads;
    if (tube) {
        j["radius_mm"] = o.radius_mm;
        j["height_mm"] = o.height_mm;
        j["hoop_stiffness_n_m"] = fabric.stretch_weft_n_m;
    } else {
        j["length_mm"] = o.length_mm;
        j["width_mm"] = o.width_mm;
        j["foundation_n_m3"] = o.foundation_n_m3;
    }
    j["slope"] = s.slope;
    j["predicted_slope"] = s.predicted_slope;
    j["fitted_wavelength_at_1_un_m_mm"] = s.intercept_mm;
    j["max_abs_error_percent"] = s.max_abs_error_percent;
    j["seconds"] = s.seconds;
    nlohmann::ordered_json pts = nlohmann::ordered_json::array();
    std::cout
        << "| B (µN·m) | predicted λ (mm) | measured λ (mm) | error % | peak share | pattern |\n"
        << "|---:|---:|---:|---:|---:|:---|\n";
    for (const tw::BucklingResult& r : s.points) {
        nlohmann::ordered_json p;
        p["bending_un_m"] = r.bending_un_m;
        p["foundation_n_m3"] = r.foundation_n_m3;
        p["predicted_wavelength_mm"] = r.predicted_wavelength_mm;
        p["measured_wavelength_mm"] = r.measured_wavelength_mm;
        p["error_percent"] = r.error_percent;
        p["peak_share"] = r.peak_share;
        p["amplitude_mm"] = r.amplitude_mm;
        p["critical_strain"] = r.critical_strain;
        p["onset_strain"] = r.onset_strain;
        p["onset_wavelength_mm"] = r.onset_wavelength_mm;
        p["pattern"] = r.pattern;
        p["lines"] = r.lines;
        p["lines_at_record_limit"] = r.lines_at_record_limit;
        if (tube) {
            p["generator_wavelengths_mm"] = r.generator_wavelengths_mm;
            p["axisymmetric_share"] = r.axisymmetric_share;
            p["axisymmetric_wavelength_mm"] = r.axisymmetric_wavelength_mm;
            p["circumferential_lobes"] = r.circumferential_lobes;
        }
        p["vertices"] = r.vertices;
        p["triangles"] = r.triangles;
        p["edge_mm"] = r.resolution_mm;
        p["relax_iterations"] = r.relax_iterations;
        p["last_relax_converged"] = r.last_converged;
        p["seconds"] = r.seconds;
        pts.push_back(p);
        std::cout << "| " << num("%g", r.bending_un_m) << " | "
                  << num("%.2f", r.predicted_wavelength_mm) << " | "
                  << num("%.2f", r.measured_wavelength_mm) << " | " << num("%+.1f", r.error_percent)
                  << " | " << num("%.2f", r.peak_share) << " | " << r.pattern
                  << (tube ? " (axisymmetric share " + num("%.2f", r.axisymmetric_share) + ", " +
                                 num("%.1f", r.circumferential_lobes) + " lobes)"
                           : std::string())
                  << (2 * r.lines_at_record_limit > r.lines
                          ? "; peak at the record's longest wavelength: a dent, no period"
                          : "")
                  << " |\n";
    }
    j["points"] = pts;
    std::cout << "\nlog-log slope " << num("%.3f", s.slope) << " (law 0.25), largest error "
              << num("%.1f", s.max_abs_error_percent) << " %, " << num("%.0f", s.seconds) << " s\n";
    if (!a.report.empty()) {
        outputs.write(a.report, [&](std::ostream& out) { out << j.dump(1) << '\n'; });
    }
    if (!a.picture.empty()) {
        const draw::RgbaImage img = tw::scaling_picture(
            s, (tube ? "Tube under axial compression, " : "Strip on a foundation, ") + fabric.name);
        outputs.write(
            a.picture, [&](std::ostream& out) { draw::write_png(out, img, 1); }, true);
    }
    if (!a.profile.empty()) {
        const tw::BucklingResult& r = s.points.front();
        const draw::RgbaImage img = tw::profile_picture(
            r, (tube ? "First generator, B = " : "Centre line, B = ") + num("%g", r.bending_un_m) +
                   " uN m, strain " + num("%g", o.strain));
        outputs.write(
            a.profile, [&](std::ostream& out) { draw::write_png(out, img, 1); }, true);
    }
    outputs.commit();
}

}  // namespace

void register_wrinkles_buckling(CLI::App& wrinkles) {
    auto a = std::make_shared<BucklingArgs>();
    CLI::App* b = wrinkles.add_subcommand(
        "buckling",
        "Virtual buckling experiments: measured wrinkle wavelength against the law "
        "2pi (B/K)^(1/4) over a list of bending rigidities, and the log-log slope");
    b->add_option("--test", a->test, "foundation (strip on a Winkler foundation) or cylinder")
        ->required();
    b->add_option("--bending", a->bending, "Bending rigidities, µN·m, comma-separated")
        ->delimiter(',')
        ->required();
    b->add_option("--fabric", a->fabric, "Library name or a .json fabric file")
        ->capture_default_str();
    b->add_option("--resolution", a->resolution,
                  "Cloth edge length, mm (default 2.5 foundation, 1.5 cylinder)");
    b->add_option("--foundation", a->foundation, "Foundation stiffness K, N/m³ (foundation)")
        ->capture_default_str();
    b->add_option("--radius", a->radius, "Tube radius, mm (cylinder)")->capture_default_str();
    b->add_option("--height", a->height, "Tube length, mm (cylinder; default four radii)");
    b->add_option("--strain", a->strain,
                  "Final end shortening over the length (default 0.01 foundation, 0.02 cylinder)");
    b->add_option("--report", a->report, "Report (JSON) naming its figures");
    b->add_option("--picture", a->picture, "Measured and predicted wavelength against B (PNG)");
    b->add_option("--profile", a->profile, "Height profile of the first B (PNG)");
    b->add_option("--threads", a->threads, "Solver threads (0: all cores)")
        ->check(CLI::Range(0, 1024))
        ->capture_default_str();
    b->callback([a] { run_buckling(*a); });
}

}  // namespace tapeline::app
