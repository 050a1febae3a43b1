// `tapeline fabric list | show NAME | convert --kes k.json|--fast f.json --out fabric.json |
// test NAME --test cantilever|tensile|bias|cusick [--resolution MM] [--report r.json]
// [--picture p.png]`: the fabric library, lab records (KES-F, SiroFAST) converted to the cloth
// solver's parameters, and the virtual lab tests that simulate a fabric (garment module,
// fabric_lab.h and fabric_tests.h).
#include "commands.h"
#include "output.h"

#include <tapeline/core/atomic_write.h>
#include <tapeline/core/errors.h>
#include <tapeline/core/json_read.h>
#include <tapeline/draw/png.h>
#include <tapeline/garment/fabric.h>
#include <tapeline/garment/fabric_lab.h>
#include <tapeline/garment/fabric_tests.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace tapeline::app {
namespace {

namespace tg = tapeline::garment;

std::string fmt(const char* f, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, v);
    return buf;
}

void run_list() {
    std::printf("%-20s %8s %9s %9s %8s %8s %8s  %s\n", "name", "g/m2", "C_warp_mm", "C_weft_mm",
                "G_N/m", "k_warp", "k_weft", "source");
    for (const tg::Fabric& f : tg::fabric_library()) {
        const tg::FabricParams& p = f.params;
        std::printf("%-20s %8.0f %9.1f %9.1f %8.1f %8.0f %8.0f  %s\n", p.name.c_str(),
                    p.density_g_m2, tg::bending_length_mm(p.bending_un_m, p.density_g_m2),
                    tg::bending_length_mm(tg::bending_weft_of(p), p.density_g_m2), p.shear_n_m,
                    p.stretch_warp_n_m, p.stretch_weft_n_m, f.source.substr(0, 60).c_str());
    }
}

struct ConvertArgs {
    std::string kes, fast, out, name;
};

void run_convert(const ConvertArgs& a) {
    if (a.kes.empty() == a.fast.empty()) {
        throw InvalidInput("fabric convert: give exactly one of --kes and --fast");
    }
    if (extension_of(a.out) != ".json") {
        throw InvalidInput("--out " + a.out + ": expected a .json file");
    }
    OutputFiles outputs({a.out});
    const std::string& in = a.kes.empty() ? a.fast : a.kes;
    const nlohmann::json j = tapeline::json::parse_json_file(in);
    tg::Fabric f = a.kes.empty() ? tg::fabric_from_fast(j, in) : tg::fabric_from_kes(j, in);
    if (!a.name.empty()) {
        f.params.name = a.name;
    }
    outputs.write(a.out, [&](std::ostream& o) { o << tg::fabric_json(f).dump(1) << '\n'; });
    outputs.commit();
    std::cout << a.out << ": " << f.params.name << ", bending length "
              << fmt("%.1f", tg::bending_length_mm(f.params.bending_un_m, f.params.density_g_m2))
              << " / "
              << fmt("%.1f",
                     tg::bending_length_mm(tg::bending_weft_of(f.params), f.params.density_g_m2))
              << " mm (warp / weft), shear " << fmt("%.1f", f.params.shear_n_m) << " N/m\n";
}

struct TestArgs {
    std::string fabric, test, report, picture;
    double resolution = 10;
    double perturbation = 0;
    int repeats = 1;
    int threads = 1;
    bool no_static_solve = false;
};

void run_test(const TestArgs& a) {
    if (!a.report.empty() && extension_of(a.report) != ".json") {
        throw InvalidInput("--report " + a.report + ": expected a .json file");
    }
    if (!a.picture.empty() && extension_of(a.picture) != ".png") {
        throw InvalidInput("--picture " + a.picture + ": expected a .png file");
    }
    if (!a.picture.empty() && (a.test == "tensile" || a.test == "bias")) {
        throw InvalidInput("--picture: the " + a.test +
                           " test has no picture (cantilever and cusick have)");
    }
    if (a.repeats < 1 || a.repeats > 100) {
        throw InvalidInput("--repeats must be within 1 and 100");
    }
    OutputFiles outputs({a.report, a.picture});
    const tg::Fabric fabric = tg::fabric_record_from(a.fabric);
    tg::FabricTestOptions o;
    o.resolution_mm = a.resolution;
    o.perturbation_mm = a.perturbation;
    o.threads = a.threads;
    o.static_solve = !a.no_static_solve;
    nlohmann::ordered_json j;
    j["fabric"] = fabric.params.name;
    j["test"] = a.test;
    j["resolution_mm"] = a.resolution;
    draw::RgbaImage picture;
    double ppmm = 1;
    auto pct = [](double v) { return fmt("%+.2f %%", v); };
    if (a.test == "cantilever") {
        std::vector<tg::CantileverResult> rs;
        for (bool weft : {false, true}) {
            rs.push_back(tg::cantilever_test(fabric.params, weft, o));
            const tg::CantileverResult& r = rs.back();
            const std::string d = r.direction;
            j["bending_length_" + d + "_mm"] = r.bending_length_mm;
            j["target_bending_length_" + d + "_mm"] = r.target_mm;
            j["error_" + d + "_pct"] = r.error_pct;
            j["overhang_" + d + "_mm"] = r.overhang_mm;
            j["tip_angle_" + d + "_deg"] = r.tip_angle_deg;
            j["runs_" + d] = r.runs;
            j["substeps_" + d] = r.substeps;
            j["settled_" + d] = r.settled;
            j["seconds_" + d] = r.seconds;
            std::cout << fabric.params.name << " cantilever " << d << ": bending length "
                      << fmt("%.2f", r.bending_length_mm) << " mm, target "
                      << fmt("%.2f", r.target_mm) << " mm (" << pct(r.error_pct) << ")"
                      << (r.settled ? "" : ", NOT at rest") << '\n';
        }
        if (!a.picture.empty()) {
            ppmm = 6;
            picture = tg::cantilever_picture(rs, fabric.params.name, ppmm);
        }
    } else if (a.test == "tensile") {
        for (bool weft : {false, true}) {
            const tg::TensileResult r = tg::tensile_test(fabric, weft, o);
            const std::string d = r.direction;
            j["measured_curve"] = r.measured_curve;
            for (const tg::TensilePoint& p : r.points) {
                const std::string at = d + "_at_" + fmt("%.0f", p.load_gf_cm) + "_gf_cm";
                j["strain_" + at + "_pct"] = p.simulated_pct;
                j["target_strain_" + at + "_pct"] = p.target_pct;
                j["error_" + at + "_pct"] = p.error_pct;
                j["linear_strain_" + at + "_pct"] = p.linear_pct;
                j["linear_error_" + at + "_pct"] = p.linear_error_pct;
                std::cout << fabric.params.name << " tensile " << d << " at "
                          << fmt("%.0f", p.load_gf_cm) << " gf/cm: strain "
                          << fmt("%.3f", p.simulated_pct) << " %, target "
                          << fmt("%.3f", p.target_pct) << " % (" << pct(p.error_pct)
                          << "); single stiffness " << fmt("%.3f", p.linear_pct) << " % ("
                          << pct(p.linear_error_pct) << ")\n";
            }
            j["substeps_" + d] = r.substeps;
            j["settled_" + d] = r.settled;
            j["seconds_" + d] = r.seconds;
        }
    } else if (a.test == "bias") {
        const tg::BiasResult r = tg::bias_test(fabric, o);
        j["load_gf_cm"] = r.load_gf_cm;
        j["shear_rigidity_n_m"] = r.simulated_shear_n_m;
        j["target_shear_rigidity_n_m"] = r.target_shear_n_m;
        j["error_pct"] = r.error_pct;
        j["shear_angle_deg"] = r.shear_angle_deg;
        j["bias_extension_pct"] = r.bias_extension_pct;
        j["target_bias_extension_pct"] = r.target_bias_extension_pct;
        j["substeps"] = r.substeps;
        j["settled"] = r.settled;
        j["seconds"] = r.seconds;
        std::cout << fabric.params.name << " bias at 5 gf/cm: shear angle "
                  << fmt("%.2f", r.shear_angle_deg) << " deg, G "
                  << fmt("%.2f", r.simulated_shear_n_m) << " N/m, target "
                  << fmt("%.2f", r.target_shear_n_m) << " N/m (" << pct(r.error_pct)
                  << "); bias extension " << fmt("%.2f", r.bias_extension_pct)
                  << " % (FAST EB5 of G: " << fmt("%.2f", r.target_bias_extension_pct) << " %)"
                  << (r.settled ? "" : ", NOT at rest") << '\n';
    } else if (a.test == "cusick") {
        std::vector<double> dcs;
        std::vector<int> nodes;
        tg::CusickResult first;
        bool settled = true, equilibrium = true;
        int relax_iterations = 0;
        double residual = 0;
        double seconds = 0;
        for (int k = 0; k < a.repeats; ++k) {
            o.seed = static_cast<std::uint32_t>(k + 1);
            tg::CusickResult r = tg::cusick_test(fabric.params, o);
            dcs.push_back(100 * r.drape_coefficient);
            nodes.push_back(r.nodes);
            settled = settled && r.settled;
            equilibrium = equilibrium && o.static_solve && r.relax.converged;
            relax_iterations = std::max(relax_iterations, r.relax.iterations);
            residual = std::max(residual, r.relax.max_residual_of_weight);
            seconds += r.seconds;
            if (k == 0) {
                first = std::move(r);
            }
        }
        double mean = 0;
        for (double d : dcs) {
            mean += d;
        }
        mean /= dcs.size();
        const double lo = *std::min_element(dcs.begin(), dcs.end());
        const double hi = *std::max_element(dcs.begin(), dcs.end());
        const tg::FabricParams& p = fabric.params;
        const double c = std::sqrt(tg::bending_length_mm(p.bending_un_m, p.density_g_m2) *
                                   tg::bending_length_mm(tg::bending_weft_of(p), p.density_g_m2));
        j["drape_coefficient_pct"] = mean;
        j["drape_coefficient_min_pct"] = lo;
        j["drape_coefficient_max_pct"] = hi;
        j["drape_coefficients_pct"] = dcs;
        j["nodes"] = nodes;
        j["perturbation_mm"] = a.perturbation;
        j["bending_length_mm"] = c;
        j["shadow_area_mm2"] = first.shadow_area_mm2;
        j["vertices"] = first.vertices;
        j["substeps"] = first.substeps;
        j["frames"] = first.frames;
        j["settled"] = settled;
        j["static_solve"] = !a.no_static_solve;
        j["equilibrium"] = equilibrium;
        j["relax_iterations_max"] = relax_iterations;
        j["relax_max_residual_of_weight"] = residual;
        j["seconds"] = seconds;
        std::cout << p.name << " cusick: DC " << fmt("%.1f", mean) << " % (" << fmt("%.1f", lo)
                  << " to " << fmt("%.1f", hi) << " over " << a.repeats << " run(s)), nodes";
        for (int n : nodes) {
            std::cout << ' ' << n;
        }
        std::cout << ", bending length " << fmt("%.1f", c) << " mm"
                  << (settled ? "" : ", NOT at rest")
                  << (equilibrium || !o.static_solve ? "" : ", static solve NOT converged") << '\n';
        if (!a.picture.empty()) {
            ppmm = 2;
            picture = tg::cusick_picture(first, p.name, ppmm);
        }
    } else {
        throw InvalidInput("--test '" + a.test + "': expected cantilever, tensile, bias or cusick");
    }
    if (!a.report.empty()) {
        outputs.write(a.report, [&](std::ostream& out) { out << j.dump(1) << '\n'; });
    }
    if (!a.picture.empty()) {
        outputs.write(
            a.picture, [&](std::ostream& out) { draw::write_png(out, picture, ppmm); }, true);
    }
    outputs.commit();
}

}  // namespace

void register_fabric_commands(CLI::App& app) {
    CLI::App* fabric = app.add_subcommand(
        "fabric",
        "Fabrics: the library, KES-F and FAST records converted to the cloth solver's "
        "parameters, and virtual lab tests (cantilever, tensile, bias, Cusick)");
    fabric->require_subcommand(1);

    CLI::App* list = fabric->add_subcommand("list", "The library's fabrics, one per line");
    list->callback([] { run_list(); });

    auto show_name = std::make_shared<std::string>();
    CLI::App* show = fabric->add_subcommand(
        "show", "A library fabric or a fabric file as JSON (parameters, source, lab figures)");
    show->add_option("NAME", *show_name, "Library name or a .json fabric file")->required();
    show->callback([show_name] {
        std::cout << tg::fabric_json(tg::fabric_record_from(*show_name)).dump(1) << '\n';
    });

    auto ca = std::make_shared<ConvertArgs>();
    CLI::App* convert = fabric->add_subcommand(
        "convert", "Convert a KES-F or SiroFAST record (JSON) to a fabric file");
    convert->add_option("--kes", ca->kes,
                        "KES-F record: W (mg/cm2) and LT, WT, RT, EMT, B, 2HB, G, 2HG, 2HG5 "
                        "with _warp and _weft");
    convert->add_option("--fast", ca->fast,
                        "FAST record: W (g/m2), C_warp, C_weft (mm), E5/E20/E100 _warp/_weft "
                        "(%), EB5 (%), T2, T100 (mm)");
    convert->add_option("--out", ca->out, "Fabric file to write (.json)")->required();
    convert->add_option("--name", ca->name,
                        "Name of the fabric (default: the record's, or its file)");
    convert->callback([ca] { run_convert(*ca); });

    auto ta = std::make_shared<TestArgs>();
    CLI::App* test = fabric->add_subcommand(
        "test", "Simulate a lab test on a fabric and compare with the fabric's own figures");
    test->add_option("FABRIC", ta->fabric, "Library name or a .json fabric file")->required();
    test->add_option("--test", ta->test, "cantilever, tensile, bias or cusick")->required();
    test->add_option("--resolution", ta->resolution, "Cloth edge length, mm (1 to 50)")
        ->capture_default_str();
    test->add_option("--report", ta->report, "Report (JSON) naming its figures");
    test->add_option("--picture", ta->picture, "Picture (PNG): cantilever and cusick");
    test->add_option("--perturbation", ta->perturbation,
                     "Cusick: random vertical offsets of the flat start, mm")
        ->capture_default_str();
    test->add_option("--repeats", ta->repeats, "Cusick: runs with seeds 1..N")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    test->add_flag("--no-static-solve", ta->no_static_solve,
                   "Cusick: the sub-stepped drape's rest, without the Newton static solve");
    test->add_option("--threads", ta->threads, "Solver threads (0: all cores)")
        ->check(CLI::Range(0, 1024))
        ->capture_default_str();
    test->callback([ta] { run_test(*ta); });
}

}  // namespace tapeline::app
