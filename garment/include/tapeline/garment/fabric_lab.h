// Fabrics from laboratory measurements: KES-F and SiroFAST reports converted to the solver's SI
// parameters (FabricParams), the ten measured fabrics of Wang, O'Brien and Ramamoorthi 2011, and
// the fabric library that `tapeline fabric` and `tapeline dress --fabric` use.
//
// Sources of the conversions (formulas and derivations in garment/README.md, "Fabrics"):
//  - S. Kawabata, "The Standardization and Analysis of Hand Evaluation", 2nd ed., Textile
//    Machinery Society of Japan, 1980 (KES-F: units of B, G, EMT, LT, WT; tensile to 500 gf/cm).
//  - SiroFAST (CSIRO): A. De Boos, D. Tester, "SiroFAST: Fabric Assurance by Simple Testing",
//    CSIRO Report WT92.02, 1994 (B = W·C³·9.81e-6 µN·m, G = 123/EB5 N/m, E5/E20/E100, T2/T100).
//  - F. T. Peirce, "The handle of cloth as a measurable quantity", J. Text. Inst. 21, 1930
//    (bending length C = (B / (W·g))^⅓).
//  - H. Wang, J. F. O'Brien, R. Ramamoorthi, "Data-Driven Elastic Models for Cloth: Modeling and
//    Measurement", SIGGRAPH 2011; their materials as distributed with ARCSim (Narain, Samii,
//    O'Brien, SIGGRAPH Asia 2012): densities, the small-strain stretching row and the bending
//    samples at zero curvature.
// No CGAL, no Eigen: the command-line tool and loggers include it cheaply.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/garment/bending.h>
#include <tapeline/garment/drape_types.h>

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <vector>

namespace tapeline::garment {

/// 1 gf·cm²/cm (KES-F bending rigidity B) in N·m: 9.80665e-3 N · 1e-4 m² / 1e-2 m.
constexpr double kKesBendingToNm = 9.80665e-5;
/// 1 gf/cm in N/m.
constexpr double kGfPerCmToNPerM = 0.980665;
/// 1 gf/(cm·degree) (KES-F shear rigidity G) in N/m per radian: 0.980665 · 180/π.
constexpr double kKesShearToNPerMRad = kGfPerCmToNPerM * 180.0 / 3.14159265358979323846;
/// Gravity of the FAST bending formula (B = W·C³·9.81e-6 µN·m), m/s².
constexpr double kFastGravity = 9.81;
/// The loads of FAST-3 extensibility E5, E20, E100, gf/cm.
constexpr std::array<double, 3> kFastLoadsGfCm{5, 20, 100};
/// KES-F tensile tests run to this load (EMT is the strain there), gf/cm.
constexpr double kKesMaxLoadGfCm = 500;

/// A fabric: the solver's parameters plus the laboratory figures it was made from (NaN where the
/// source has none; the virtual tests then take their targets from the parameters).
struct Fabric {
    /// The parameters the solver runs with.
    FabricParams params;
    std::string source;  ///< where the numbers come from
    /// Strain in % at 5, 20 and 100 gf/cm along warp and weft (FAST E5, E20, E100; from KES by
    /// the power-law curve, see fabric_from_kes).
    ///@{
    std::array<double, 3> extension_warp_pct{nan(), nan(), nan()};
    std::array<double, 3> extension_weft_pct{nan(), nan(), nan()};
    ///@}
    double bias_extension_pct = nan();  ///< FAST EB5: bias strain at 5 gf/cm, %

    /// Quiet NaN: the value of a figure the source does not give.
    static constexpr double nan() { return std::numeric_limits<double>::quiet_NaN(); }
};

/// FAST bending rigidity B = W·C³·9.81e-6 (µN·m, W in g/m², C in mm).
inline double fast_bending_un_m(double w_g_m2, double c_mm) {
    return w_g_m2 * c_mm * c_mm * c_mm * 9.81e-6;
}

/// Bending length C = (B / (W·g))^⅓ in mm (B in µN·m, W in g/m²): the inverse of the above.
inline double bending_length_mm(double bending_un_m, double w_g_m2) {
    return std::cbrt(bending_un_m / (w_g_m2 * 9.81e-6));
}

/// FAST shear rigidity G = 123/EB5 N/m (EB5 in %): see README ("Fabrics") for the derivation
/// G = (T/2)/γ with γ = 2·ε₄₅ at T = 5 gf/cm, 4.903/(4·EB5/100) = 122.6/EB5.
inline double fast_shear_n_m(double eb5_pct) {
    return 123.0 / eb5_pct;
}

/// Bias extension EB5 (%) that shear rigidity G (N/m) gives: the inverse of fast_shear_n_m.
inline double bias_extension_pct_of(double shear_n_m) {
    return 123.0 / shear_n_m;
}

/// Secant tensile stiffness (N/m) of a strain of `pct` % under `load_gf_cm`.
inline double secant_stiffness_n_m(double load_gf_cm, double pct) {
    return load_gf_cm * kGfPerCmToNPerM / (pct / 100);
}

namespace internal {

/// A JSON object's numbers by key, with one-line refusals naming the file and the keys.
struct LabRecord {
    const nlohmann::json& j;
    std::string where;  ///< file name (or "input") for messages
    std::string kind;   ///< "FAST" or "KES"

    void check_keys(const std::vector<std::string>& required,
                    const std::vector<std::string>& optional) const {
        if (!j.is_object()) {
            throw InvalidInput(where + ": a " + kind + " record is a JSON object");
        }
        std::string unknown;
        for (const auto& [key, value] : j.items()) {
            bool ok = key == "name" || key == "source";
            for (const auto& k : required) {
                ok = ok || key == k;
            }
            for (const auto& k : optional) {
                ok = ok || key == k;
            }
            if (!ok) {
                unknown += (unknown.empty() ? "" : ", ") + key;
            }
        }
        if (!unknown.empty()) {
            std::string known;
            for (const auto& k : required) {
                known += (known.empty() ? "" : ", ") + k;
            }
            for (const auto& k : optional) {
                known += ", " + k;
            }
            throw InvalidInput(where + ": unknown " + kind + " key(s): " + unknown +
                               " (known: " + known + ", name, source)");
        }
        std::string missing;
        for (const auto& k : required) {
            if (!j.contains(k)) {
                missing += (missing.empty() ? "" : ", ") + k;
            }
        }
        if (!missing.empty()) {
            throw InvalidInput(where + ": missing " + kind + " key(s): " + missing);
        }
        for (const char* k : {"name", "source"}) {
            if (j.contains(k) && !j[k].is_string()) {
                throw InvalidInput(where + ": \"" + k + "\" must be a string");
            }
        }
    }
    /// The positive finite number at `key`.
    double positive(const std::string& key) const {
        const nlohmann::json& v = j.at(key);
        if (!v.is_number() || !std::isfinite(v.get<double>()) || !(v.get<double>() > 0)) {
            throw InvalidInput(where + ": " + kind + " \"" + key +
                               "\" must be a positive finite number, got " + v.dump());
        }
        return v.get<double>();
    }
    std::string text(const char* key, const std::string& fallback) const {
        return j.contains(key) ? j[key].get<std::string>() : fallback;
    }
};

inline std::vector<std::string> suffixed(const std::vector<std::string>& stems) {
    std::vector<std::string> out;
    for (const auto& s : stems) {
        out.push_back(s + "_warp");
        out.push_back(s + "_weft");
    }
    return out;
}

}  // namespace internal

/// A fabric from a SiroFAST report (JSON object). Keys, all required: W (g/m²), C_warp, C_weft
/// (bending length, mm), E5_warp, E20_warp, E100_warp, E5_weft, E20_weft, E100_weft
/// (extensibility, %), EB5 (bias extensibility, %), T2, T100 (thickness at 2 and 100 gf/cm²,
/// mm); optional "name" and "source" (strings). Solver parameters:
///  - density W; bending warp/weft W·C³·9.81e-6 µN·m, bias their mean (FAST has no bias bending);
///  - tensile stiffness: the secant at 5 gf/cm, 4.903/(E5/100) N/m (drape loads are a few gf/cm;
///    the solver is linear, the whole curve is kept for the tensile test);
///  - shear 123/EB5 N/m; thickness T2; friction 0.3 (FAST measures none).
/// InvalidInput, one line naming `where` and the key(s), on an unknown or missing key or a value
/// that is not a positive finite number, or E5 ≥ E20 ≥ E100 out of order.
inline Fabric fabric_from_fast(const nlohmann::json& j, const std::string& where) {
    const internal::LabRecord r{j, where, "FAST"};
    std::vector<std::string> required = {"W",         "C_warp",    "C_weft",  "E5_warp",
                                         "E20_warp",  "E100_warp", "E5_weft", "E20_weft",
                                         "E100_weft", "EB5",       "T2",      "T100"};
    r.check_keys(required, {});
    for (const auto& k : required) {
        r.positive(k);
    }
    Fabric f;
    FabricParams& p = f.params;
    p.name = r.text("name", where);
    f.source = r.text("source", "SiroFAST report " + where);
    const double w = r.positive("W");
    p.density_g_m2 = w;
    p.bending_un_m = fast_bending_un_m(w, r.positive("C_warp"));
    p.bending_weft_un_m = fast_bending_un_m(w, r.positive("C_weft"));
    p.bending_bias_un_m = 0.5 * (p.bending_un_m + p.bending_weft_un_m);
    const char* stems[3] = {"E5_", "E20_", "E100_"};
    for (int d = 0; d < 2; ++d) {
        const std::string dir = d == 0 ? "warp" : "weft";
        auto& e = d == 0 ? f.extension_warp_pct : f.extension_weft_pct;
        for (int k = 0; k < 3; ++k) {
            e[k] = r.positive(stems[k] + dir);
        }
        if (!(e[0] < e[1] && e[1] < e[2])) {
            throw InvalidInput(where + ": FAST E5_" + dir + " < E20_" + dir + " < E100_" + dir +
                               " must hold (strain grows with load)");
        }
    }
    p.stretch_warp_n_m = secant_stiffness_n_m(5, f.extension_warp_pct[0]);
    p.stretch_weft_n_m = secant_stiffness_n_m(5, f.extension_weft_pct[0]);
    f.bias_extension_pct = r.positive("EB5");
    p.shear_n_m = fast_shear_n_m(f.bias_extension_pct);
    p.thickness_mm = r.positive("T2");
    if (!(r.positive("T100") <= p.thickness_mm)) {
        throw InvalidInput(where + ": FAST T100 must not exceed T2 (compression thins the fabric)");
    }
    p.friction = 0.3;
    return f;
}

/// Strain (%) at `load_gf_cm` of the KES tensile curve F = Fm·(ε/εm)^n with Fm = 500 gf/cm,
/// εm = EMT and n = 2/LT − 1 (LT = WT / (½·Fm·εm) is the ratio of the curve's energy to the
/// straight line's; a power law has energy Fm·εm/(n+1)).
inline double kes_strain_pct(double emt_pct, double lt, double load_gf_cm) {
    const double n = 2 / lt - 1;
    return emt_pct * std::pow(load_gf_cm / kKesMaxLoadGfCm, 1 / n);
}

/// A fabric from a KES-F report (JSON object). Keys, all required: W (mg/cm², KES's unit), and
/// with _warp and _weft suffixes LT, WT (gf·cm/cm²), RT (%), EMT (%), B (gf·cm²/cm), 2HB
/// (gf·cm/cm), G (gf/(cm·deg)), 2HG, 2HG5 (gf/cm); optional "name", "source". Solver
/// parameters: density 10·W g/m²; bending B·98.0665 µN·m (warp, weft; bias their mean); shear
/// the mean of G warp and weft × 56.19 N/m per radian; tensile stiffness the secant at 5 gf/cm of
/// the power-law curve through (EMT, 500 gf/cm) whose energy ratio is LT; thickness 1 mm and
/// friction 0.3 (compression and surface are not in the record). WT must agree with
/// LT·½·500·EMT/100 within 5 % (a check on the record); RT, 2HB, 2HG and 2HG5 (hysteresis) are
/// checked and not used (the solver is elastic).
inline Fabric fabric_from_kes(const nlohmann::json& j, const std::string& where) {
    const internal::LabRecord r{j, where, "KES"};
    std::vector<std::string> required = {"W"};
    for (const auto& k :
         internal::suffixed({"LT", "WT", "RT", "EMT", "B", "2HB", "G", "2HG", "2HG5"})) {
        required.push_back(k);
    }
    r.check_keys(required, {});
    for (const auto& k : required) {
        r.positive(k);
    }
    Fabric f;
    FabricParams& p = f.params;
    p.name = r.text("name", where);
    f.source = r.text("source", "KES-F report " + where);
    p.density_g_m2 = 10 * r.positive("W");
    p.bending_un_m = r.positive("B_warp") * kKesBendingToNm * 1e6;
    p.bending_weft_un_m = r.positive("B_weft") * kKesBendingToNm * 1e6;
    p.bending_bias_un_m = 0.5 * (p.bending_un_m + p.bending_weft_un_m);
    p.shear_n_m = 0.5 * (r.positive("G_warp") + r.positive("G_weft")) * kKesShearToNPerMRad;
    for (int d = 0; d < 2; ++d) {
        const std::string dir = d == 0 ? "_warp" : "_weft";
        const double lt = r.positive("LT" + dir), emt = r.positive("EMT" + dir);
        if (!(lt < 2)) {
            throw InvalidInput(where + ": KES LT" + dir + " must be below 2 (it is " +
                               std::to_string(lt) + ")");
        }
        const double wt_line = lt * 0.5 * kKesMaxLoadGfCm * emt / 100;
        const double wt = r.positive("WT" + dir);
        if (std::abs(wt - wt_line) > 0.05 * wt_line) {
            throw InvalidInput(where + ": KES WT" + dir + " = " + std::to_string(wt) +
                               " disagrees with LT·½·500·EMT/100 = " + std::to_string(wt_line) +
                               " (more than 5 %)");
        }
        auto& e = d == 0 ? f.extension_warp_pct : f.extension_weft_pct;
        for (int k = 0; k < 3; ++k) {
            e[k] = kes_strain_pct(emt, lt, kFastLoadsGfCm[k]);
        }
        (d == 0 ? p.stretch_warp_n_m : p.stretch_weft_n_m) = secant_stiffness_n_m(5, e[0]);
    }
    f.bias_extension_pct = bias_extension_pct_of(p.shear_n_m);
    p.thickness_mm = 1.0;
    p.friction = 0.3;
    return f;
}

/// A Wang et al. 2011 material from its ARCSim record: areal density (kg/m²), the small-strain
/// stretching row (k11, k12, k22, k33, as stored) and the bending samples at zero curvature for
/// hinge edges at 0°, 45° and 90° to the first material axis (N·m, as stored). ARCSim doubles
/// the stretching samples when it loads them and its energy is ½·(k11·G11² + 2·k12·G11·G22 +
/// k22·G22² + k33·G12²) in the Green strain, so a strip's tensile stiffness is 2·k11 (2·k22) and
/// the shear rigidity 2·k33/4 (G12 = γ/2). Its hinge energy k·|e|²·θ²/(8·A_e) against
/// bending.h's ½·B·|e|²·θ²/A_e gives B = k/4; a hinge along the first axis (0°) bends across
/// it, so it gives the weft rigidity (the first axis taken as the warp).
inline Fabric fabric_from_arcsim(const std::string& name, const std::string& use,
                                 double density_kg_m2, std::array<double, 4> stretch_row0,
                                 std::array<double, 3> bending_0_45_90) {
    Fabric f;
    FabricParams& p = f.params;
    p.name = name;
    f.source = "Wang, O'Brien, Ramamoorthi 2011, ARCSim material '" + name + "' (" + use +
               "): density, stretching row 0, bending at zero curvature; B = k/4, stretch 2k";
    p.density_g_m2 = density_kg_m2 * 1000;
    p.stretch_warp_n_m = 2 * stretch_row0[0];
    p.stretch_weft_n_m = 2 * stretch_row0[2];
    p.shear_n_m = 2 * stretch_row0[3] / 4;
    p.bending_weft_un_m = bending_0_45_90[0] / 4 * 1e6;
    p.bending_bias_un_m = bending_0_45_90[1] / 4 * 1e6;
    p.bending_un_m = bending_0_45_90[2] / 4 * 1e6;
    p.friction = 0.3;
    p.thickness_mm = 1.0;
    return f;
}

/// The fabric library: the five cloth classes (order-of-magnitude values of their class, with
/// isotropic bending) and the ten measured fabrics of Wang et al. 2011.
inline const std::vector<Fabric>& fabric_library() {
    static const std::vector<Fabric> list = [] {
        std::vector<Fabric> l;
        auto cls = [&](FabricParams p) {
            Fabric f;
            f.params = std::move(p);
            f.source =
                "class value: the order of magnitude of its class, not a measurement "
                "of one cloth";
            l.push_back(f);
        };
        // name, g/m², warp N/m, weft N/m, shear N/m, bending µN·m, friction, thickness mm
        cls({"cotton_jersey", 180, 1500, 800, 200, 2, 0.3, 1.0});
        cls({"cotton_shirting", 120, 8000, 6000, 800, 5, 0.3, 0.8});
        cls({"denim", 400, 20000, 15000, 3000, 40, 0.4, 1.5});
        cls({"silk_charmeuse", 80, 4000, 3000, 200, 0.5, 0.2, 0.6});
        cls({"wool_suiting", 260, 10000, 8000, 1000, 15, 0.35, 1.2});
        // Wang et al. 2011 as distributed with ARCSim: kg/m², stretching row 0 (k11, k12, k22,
        // k33), bending at κ = 0 for hinges at 0°/45°/90° (µN·m).
        struct W {
            const char* name;
            const char* use;
            double density;
            std::array<double, 4> s;
            std::array<double, 3> b;
        };
        const W wang[] = {
            {"11oz-black-denim", "jeans", 0.324, {205, 10, 1014, 53}, {64, 73, 97}},
            {"camel-ponte-roma", "jacket", 0.284, {31, -13, 44, 32}, {36, 33, 37}},
            {"gray-interlock", "t-shirt", 0.187, {17, -15, 34, 37}, {23, 25, 14}},
            {"ivory-rib-knit", "underwear", 0.276, {43, 0, 65, 83}, {46, 30, 32}},
            {"navy-sparkle-sweat", "sweater", 0.224, {12, -20, 3, 18}, {60, 40, 46}},
            {"pink-ribbon-brown", "blanket", 0.228, {152, 106, 245, 30}, {117, 88, 60}},
            {"royal-target", "pants", 0.220, {2017, 9, 2035, 105}, {125, 108, 125}},
            {"tango-red-jet-set", "jacket", 0.113, {43, 54, 171, 14}, {14, 22, 20}},
            {"white-dots-on-blk", "tablecloth", 0.128, {2002, 0, 2028, 19}, {52, 41, 31}},
            {"white-swim-solid", "swimsuit", 0.204, {48, 7, 105, 61}, {60, 59, 51}},
        };
        for (const W& w : wang) {
            l.push_back(fabric_from_arcsim(w.name, w.use, w.density, w.s,
                                           {w.b[0] * 1e-6, w.b[1] * 1e-6, w.b[2] * 1e-6}));
        }
        return l;
    }();
    return list;
}

/// The library fabric called `name`, or null.
inline const Fabric* library_fabric(const std::string& name) {
    for (const Fabric& f : fabric_library()) {
        if (f.params.name == name) {
            return &f;
        }
    }
    return nullptr;
}

/// The fabric as a JSON object: FabricParams' fields, the source, the lab figures it carries and
/// derived figures (bending lengths, EB5 of the shear rigidity). fabric_from_json reads it back.
inline nlohmann::ordered_json fabric_json(const Fabric& f) {
    const FabricParams& p = f.params;
    nlohmann::ordered_json j;
    j["name"] = p.name;
    j["source"] = f.source;
    j["density_g_m2"] = p.density_g_m2;
    j["stretch_warp_n_m"] = p.stretch_warp_n_m;
    j["stretch_weft_n_m"] = p.stretch_weft_n_m;
    j["shear_n_m"] = p.shear_n_m;
    j["bending_un_m"] = p.bending_un_m;
    j["bending_weft_un_m"] = bending_weft_of(p);
    j["bending_bias_un_m"] = bending_bias_of(p);
    j["friction"] = p.friction;
    j["thickness_mm"] = p.thickness_mm;
    j["damping_per_second"] = p.damping_per_second;
    if (std::isfinite(f.extension_warp_pct[0])) {
        j["extension_warp_pct"] = f.extension_warp_pct;
        j["extension_weft_pct"] = f.extension_weft_pct;
    }
    if (std::isfinite(f.bias_extension_pct)) {
        j["bias_extension_pct"] = f.bias_extension_pct;
    }
    j["derived"] = {
        {"bending_length_warp_mm", bending_length_mm(p.bending_un_m, p.density_g_m2)},
        {"bending_length_weft_mm", bending_length_mm(bending_weft_of(p), p.density_g_m2)},
        {"bias_extension_pct_of_shear", bias_extension_pct_of(p.shear_n_m)}};
    return j;
}

/// A fabric from a fabric JSON object (fabric_json's keys; any FabricParams field may be left
/// out and then takes cotton_jersey's value; "derived" is ignored). InvalidInput naming `where`
/// and the field on an unknown field or a bad value.
inline Fabric fabric_from_json(const nlohmann::json& j, const std::string& where) {
    if (!j.is_object()) {
        throw InvalidInput(where + ": a fabric file is a JSON object");
    }
    Fabric f = fabric_library().front();
    f.source = where;
    FabricParams& p = f.params;
    p.name = where;
    p.bending_weft_un_m = p.bending_bias_un_m = -1;
    for (const char* k : {"name", "source"}) {
        if (j.contains(k)) {
            if (!j[k].is_string()) {
                throw InvalidInput(where + ": \"" + std::string(k) + "\" must be a string");
            }
            (std::string(k) == "name" ? p.name : f.source) = j[k].get<std::string>();
        }
    }
    const auto number = [&](const char* key, double& field, bool allow_zero) {
        if (!j.contains(key)) {
            return;
        }
        if (!j[key].is_number() || !std::isfinite(j[key].get<double>()) ||
            j[key].get<double>() < 0 || (!allow_zero && j[key].get<double>() == 0)) {
            throw InvalidInput(where + ": \"" + key + "\" must be a " +
                               (allow_zero ? "non-negative" : "positive") + " finite number");
        }
        field = j[key].get<double>();
    };
    number("density_g_m2", p.density_g_m2, false);
    number("stretch_warp_n_m", p.stretch_warp_n_m, false);
    number("stretch_weft_n_m", p.stretch_weft_n_m, false);
    number("shear_n_m", p.shear_n_m, false);
    number("bending_un_m", p.bending_un_m, true);
    number("bending_weft_un_m", p.bending_weft_un_m, true);
    number("bending_bias_un_m", p.bending_bias_un_m, true);
    number("friction", p.friction, true);
    number("thickness_mm", p.thickness_mm, false);
    number("damping_per_second", p.damping_per_second, true);
    for (const char* key : {"extension_warp_pct", "extension_weft_pct"}) {
        if (!j.contains(key)) {
            continue;
        }
        const nlohmann::json& a = j[key];
        auto& e =
            std::string(key) == "extension_warp_pct" ? f.extension_warp_pct : f.extension_weft_pct;
        bool ok = a.is_array() && a.size() == 3;
        for (std::size_t k = 0; ok && k < 3; ++k) {
            ok = a[k].is_number() && std::isfinite(a[k].get<double>()) && a[k].get<double>() > 0;
            if (ok) {
                e[k] = a[k].get<double>();
            }
        }
        if (!ok) {
            throw InvalidInput(where + ": \"" + key +
                               "\" must be three positive numbers (strain % at 5, 20, 100 gf/cm)");
        }
    }
    if (j.contains("bias_extension_pct")) {
        number("bias_extension_pct", f.bias_extension_pct, false);
    }
    static const std::set<std::string> known = {"name",
                                                "source",
                                                "density_g_m2",
                                                "stretch_warp_n_m",
                                                "stretch_weft_n_m",
                                                "shear_n_m",
                                                "bending_un_m",
                                                "bending_weft_un_m",
                                                "bending_bias_un_m",
                                                "friction",
                                                "thickness_mm",
                                                "damping_per_second",
                                                "extension_warp_pct",
                                                "extension_weft_pct",
                                                "bias_extension_pct",
                                                "derived"};
    for (const auto& [key, value] : j.items()) {
        if (!known.count(key)) {
            const char* lab = j.contains("C_warp") || j.contains("EB5")          ? "FAST"
                              : j.contains("EMT_warp") || j.contains("2HB_warp") ? "KES"
                                                                                 : nullptr;
            throw InvalidInput(where + ": unknown field \"" + key + "\"" +
                               (lab ? std::string(" (a ") + lab +
                                          " record, not a fabric file: convert it with "
                                          "`tapeline fabric convert`)"
                                    : std::string()));
        }
    }
    if (std::isfinite(f.extension_warp_pct[0]) != std::isfinite(f.extension_weft_pct[0])) {
        throw InvalidInput(where +
                           ": \"extension_warp_pct\" and \"extension_weft_pct\" come together");
    }
    return f;
}

}  // namespace tapeline::garment
