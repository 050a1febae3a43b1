// `tapeline wrinkles classify GARMENT.obj --fabric NAME|fabric.json [--units auto|mm|cm|dm|m]
// [--report r.json] [--triangles t.json] [--picture p.png]` and `tapeline wrinkles compare
// COARSE.obj FINE.obj [--fabric ...] [--report r.json] [--windows w.json]` (compare.h): the wrinkle
// class of every triangle of a draped garment (as `tapeline dress` writes it: positions in the
// body's unit, pattern coordinates in mm, the grain per piece) and the wavelength and amplitude the
// buckling law predicts there (wrinkles/classify.h). The `buckling` experiments are in
// wrinkles_buckling.cpp.
#include "commands.h"
#include "output.h"
#include "wrinkles_io.h"

#include <tapeline/core/errors.h>
#include <tapeline/core/units.h>
#include <tapeline/draw/png.h>
#include <tapeline/garment/fabric.h>
#include <tapeline/garment/garment_io.h>
#include <tapeline/wrinkles/classify.h>
#include <tapeline/wrinkles/compare.h>
#include <tapeline/wrinkles/picture.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace tapeline::app {
namespace {

namespace tg = tapeline::garment;
namespace tw = tapeline::wrinkles;
using wrinkles_io::cell;
using wrinkles_io::garment_in_mm;
using wrinkles_io::units_option;

struct ClassifyArgs {
    std::string garment, fabric = "cotton_jersey", units = "auto", report, triangles, picture;
    tw::ClassifyOptions options;
};

void run_classify(const ClassifyArgs& a) {
    if (!a.report.empty() && extension_of(a.report) != ".json") {
        throw InvalidInput("--report " + a.report + ": expected a .json file");
    }
    if (!a.triangles.empty() && extension_of(a.triangles) != ".json") {
        throw InvalidInput("--triangles " + a.triangles + ": expected a .json file");
    }
    if (!a.picture.empty() && extension_of(a.picture) != ".png") {
        throw InvalidInput("--picture " + a.picture + ": expected a .png file");
    }
    const std::optional<LengthUnit> given = units_option(a.units);
    OutputFiles outputs({a.report, a.triangles, a.picture});
    const tg::FabricParams fabric = tg::fabric_from(a.fabric);
    LengthUnit unit = LengthUnit::mm;
    const tg::GarmentMesh g = garment_in_mm(a.garment, given, unit);
    const tw::WrinkleField w = tw::classify_wrinkles(g, fabric, a.options);
    const tw::WrinkleReport& r = w.report;
    std::printf("%s: %zu triangles, positions in %s, fabric %s\n", a.garment.c_str(), r.triangles,
                to_string(unit), fabric.name.c_str());
    std::printf("%-12s %9s %7s %12s %12s\n", "class", "triangles", "area_%", "lambda_mm",
                "amplitude_mm");
    for (std::size_t c = 0; c < tw::kWrinkleClasses; ++c) {
        std::printf("%-12s %9zu %7.1f %s %s\n", tw::to_string(tw::WrinkleClass(c)), r.count[c],
                    r.area_percent[c], cell(r.median_wavelength_mm[c]).c_str(),
                    cell(r.median_amplitude_mm[c]).c_str());
    }
    if (r.no_foundation > 0) {
        std::printf(
            "%zu compressed triangles have no foundation (no tension along the crests, or "
            "a flat surface): no wavelength predicted\n",
            r.no_foundation);
    }
    if (!a.report.empty()) {
        nlohmann::ordered_json j;
        j["garment"] = a.garment;
        j["units"] = to_string(unit);
        j["fabric"] = fabric.name;
        j["options"] = {{"compression_threshold", a.options.compression_threshold},
                        {"tension_threshold", a.options.tension_threshold},
                        {"shear_threshold_deg", a.options.shear_threshold_deg},
                        {"bias_window_deg", a.options.bias_window_deg},
                        {"tension_length_mm", a.options.tension_length_mm}};
        j["report"] = tw::wrinkle_report_json(r);
        outputs.write(a.report, [&](std::ostream& out) { out << j.dump(1) << '\n'; });
    }
    if (!a.triangles.empty()) {
        outputs.write(a.triangles, [&](std::ostream& out) {
            out << tw::wrinkle_triangles_json(w).dump() << '\n';
        });
    }
    if (!a.picture.empty()) {
        const std::string name = a.garment.substr(a.garment.find_last_of('/') + 1);
        const draw::RgbaImage img =
            tw::wrinkle_picture(g, w, name + ": wrinkle classes (" + fabric.name + ")");
        outputs.write(
            a.picture, [&](std::ostream& out) { draw::write_png(out, img, 5); }, true);
    }
    outputs.commit();
}

struct CompareArgs {
    std::string coarse, fine, fabric = "cotton_jersey", units = "auto", report, windows, picture;
    tw::ClassifyOptions classify;
    tw::CompareOptions compare;
};

void run_compare(const CompareArgs& a) {
    for (const std::string* f : {&a.report, &a.windows}) {
        if (!f->empty() && extension_of(*f) != ".json") {
            throw InvalidInput(*f + ": expected a .json file");
        }
    }
    if (!a.picture.empty() && extension_of(a.picture) != ".png") {
        throw InvalidInput("--picture " + a.picture + ": expected a .png file");
    }
    const std::optional<LengthUnit> given = units_option(a.units);
    OutputFiles outputs({a.report, a.windows, a.picture});
    const tg::FabricParams fabric = tg::fabric_from(a.fabric);
    LengthUnit uc = LengthUnit::mm, uf = LengthUnit::mm;
    const tg::GarmentMesh coarse = garment_in_mm(a.coarse, given, uc);
    const tg::GarmentMesh fine = garment_in_mm(a.fine, given, uf);
    const tw::WrinkleField field = tw::classify_wrinkles(coarse, fabric, a.classify);
    const tw::Comparison c = tw::compare_wrinkles(coarse, field, fine, a.compare);
    const tw::ComparisonReport& r = c.report;
    std::printf("coarse %s (%zu triangles, %s), fine %s (%zu triangles, %s), fabric %s\n",
                a.coarse.c_str(), coarse.triangles.size(), to_string(uc), a.fine.c_str(),
                fine.triangles.size(), to_string(uf), fabric.name.c_str());
    std::printf("fine over coarse: rms height %.2f mm, fine outline up to %.2f mm outside\n",
                r.rms_height_mm, r.max_outside_mm);
    std::printf("%-12s %8s %9s %16s %16s\n", "class", "windows", "measured", "lambda_err_%",
                "amplitude_err_%");
    std::array<std::size_t, tw::kWrinkleClasses> windows{};
    for (const auto& w : c.windows) {
        ++windows[std::size_t(w.cls)];
    }
    for (std::size_t k = 1; k < tw::kWrinkleClasses; ++k) {
        std::printf("%-12s %8zu %9zu %s %s\n", tw::to_string(tw::WrinkleClass(k)), windows[k],
                    r.measured_per_class[k], cell(r.median_wavelength_error_percent[k], 16).c_str(),
                    cell(r.median_amplitude_error_percent[k], 16).c_str());
    }
    std::printf("%-12s %8zu %9zu %s %s\n", "all", r.windows, r.measured,
                cell(r.median_wavelength_error_percent_all, 16).c_str(),
                cell(r.median_amplitude_error_percent_all, 16).c_str());
    std::printf("median measured / predicted wavelength: %s\n",
                std::isfinite(r.median_wavelength_ratio)
                    ? std::to_string(r.median_wavelength_ratio).c_str()
                    : "- (no window measured)");
    if (!a.report.empty()) {
        nlohmann::ordered_json j;
        j["coarse"] = a.coarse;
        j["fine"] = a.fine;
        j["fabric"] = fabric.name;
        j["classes"] = tw::wrinkle_report_json(field.report);
        j["comparison"] = tw::comparison_report_json(r);
        outputs.write(a.report, [&](std::ostream& out) { out << j.dump(1) << '\n'; });
    }
    if (!a.windows.empty()) {
        nlohmann::ordered_json arr = nlohmann::ordered_json::array();
        for (const auto& w : c.windows) {
            arr.push_back({{"triangle", w.triangle},
                           {"class", tw::to_string(w.cls)},
                           {"predicted_wavelength_mm", w.predicted_wavelength_mm},
                           {"measured_wavelength_mm", w.measured_wavelength_mm},
                           {"predicted_amplitude_mm", w.predicted_amplitude_mm},
                           {"measured_amplitude_mm", w.measured_amplitude_mm},
                           {"peak_share", w.peak_share},
                           {"fine_vertices", w.fine_vertices},
                           {"measured", w.measured}});
        }
        outputs.write(a.windows, [&](std::ostream& out) { out << arr.dump() << '\n'; });
    }
    if (!a.picture.empty()) {
        const std::string name = a.fine.substr(a.fine.find_last_of('/') + 1);
        const draw::RgbaImage img = tw::comparison_picture(coarse, field, fine, c.embedding, name);
        outputs.write(
            a.picture, [&](std::ostream& out) { draw::write_png(out, img, 5); }, true);
    }
    outputs.commit();
}

}  // namespace

void register_wrinkles_commands(CLI::App& app) {
    CLI::App* wr = app.add_subcommand(
        "wrinkles", "Wrinkles on a draped garment: classes, predicted wavelengths, experiments");
    wr->require_subcommand(1);
    CLI::App* cl = wr->add_subcommand(
        "classify",
        "Wrinkle class (tension, shear, compression, none) of every triangle of a draped garment "
        "OBJ (tapeline dress) and the wavelength and amplitude the buckling law predicts");
    auto ca = std::make_shared<ClassifyArgs>();
    cl->add_option("GARMENT", ca->garment, "Draped garment OBJ with pattern coordinates (vt, mm)")
        ->required();
    cl->add_option("--fabric", ca->fabric, "Library fabric name or a .json fabric file")
        ->capture_default_str();
    cl->add_option("--units", ca->units,
                   "Unit of the OBJ positions: auto (from the pattern coordinates), mm, cm, dm, m")
        ->capture_default_str();
    cl->add_option("--report", ca->report, "Report (JSON): classes, areas, median wavelengths");
    cl->add_option(
        "--triangles", ca->triangles,
        "Per-triangle JSON: class, wavelength, amplitude, stretches, tension, curvature");
    cl->add_option("--picture", ca->picture, "Picture (PNG): the garment coloured by class");
    cl->add_option("--compression-threshold", ca->options.compression_threshold,
                   "Compressed when the smallest stretch is below 1 - this")
        ->capture_default_str();
    cl->add_option("--tension-threshold", ca->options.tension_threshold,
                   "Tension wrinkles when the largest stretch is above 1 + this")
        ->capture_default_str();
    cl->add_option("--shear-threshold", ca->options.shear_threshold_deg,
                   "Shear wrinkles above this shear angle, degrees")
        ->capture_default_str();
    cl->add_option("--tension-length", ca->options.tension_length_mm,
                   "Length L of the tension term T(pi/L)^2 of the foundation, mm (0: off)")
        ->capture_default_str();
    cl->callback([ca] { run_classify(*ca); });

    CLI::App* cmp = wr->add_subcommand(
        "compare",
        "A fine drape against the wrinkles predicted on a coarse drape of the same pattern: "
        "dominant wavelength and amplitude of the fine height field around every compressed "
        "coarse triangle");
    auto ka = std::make_shared<CompareArgs>();
    cmp->add_option("COARSE", ka->coarse, "Coarse drape OBJ (tapeline dress)")->required();
    cmp->add_option("FINE", ka->fine, "Fine drape OBJ of the same pattern")->required();
    cmp->add_option("--fabric", ka->fabric, "Library fabric name or a .json fabric file")
        ->capture_default_str();
    cmp->add_option("--units", ka->units, "Unit of both OBJs' positions: auto, mm, cm, dm, m")
        ->capture_default_str();
    cmp->add_option("--report", ka->report, "Report (JSON): classes and errors per class");
    cmp->add_option("--windows", ka->windows, "Per-window JSON: predicted and measured");
    cmp->add_option("--picture", ka->picture,
                    "Picture (PNG): the coarse drape by class above the fine one by height");
    cmp->add_option("--periods", ka->compare.periods, "Window length in predicted wavelengths")
        ->capture_default_str();
    cmp->add_option("--tension-length", ka->classify.tension_length_mm,
                    "Length L of the tension term T(pi/L)^2 of the foundation, mm (0: off)")
        ->capture_default_str();
    cmp->callback([ka] { run_compare(*ka); });
    register_wrinkles_buckling(*wr);
    register_wrinkles_synthesis(*wr);
}

}  // namespace tapeline::app
