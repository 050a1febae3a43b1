// Fabrics the cloth solver knows by name, and fabric files (JSON with FabricParams' fields).
//
// The named fabrics are typical values of their class, in the solver's units (FabricParams):
// areal density, tensile stiffness per unit width along warp and weft, in-plane shear stiffness,
// bending rigidity (1 gf·cm²/cm of KES-F's B = 0.98 µN·m) and friction. They are order-of-magnitude
// classes, not measurements of one cloth.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/garment/drape_types.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

namespace tapeline::garment {

/// The named fabrics.
inline const std::vector<FabricParams>& fabric_catalogue() {
    static const std::vector<FabricParams> list = {
        // name, g/m², warp N/m, weft N/m, shear N/m, bending µN·m, friction, thickness mm
        {"cotton_jersey", 180, 1500, 800, 200, 2, 0.3, 1.0},
        {"cotton_shirting", 120, 8000, 6000, 800, 5, 0.3, 0.8},
        {"denim", 400, 20000, 15000, 3000, 40, 0.4, 1.5},
        {"silk_charmeuse", 80, 4000, 3000, 200, 0.5, 0.2, 0.6},
        {"wool_suiting", 260, 10000, 8000, 1000, 15, 0.35, 1.2},
    };
    return list;
}

/// The named fabric, or a fabric file (.json with any of FabricParams' fields; the rest default
/// to cotton_jersey). InvalidInput naming the fabric or the file and field when it is unknown
/// or a value is not a positive finite number.
inline FabricParams fabric_from(const std::string& name_or_file) {
    for (const FabricParams& f : fabric_catalogue()) {
        if (f.name == name_or_file) {
            return f;
        }
    }
    const bool json_file =
        name_or_file.size() > 5 && name_or_file.compare(name_or_file.size() - 5, 5, ".json") == 0;
    if (!json_file) {
        std::string known;
        for (const FabricParams& f : fabric_catalogue()) {
            known += (known.empty() ? "" : ", ") + f.name;
        }
        throw InvalidInput("--fabric: unknown fabric '" + name_or_file + "' (known: " + known +
                           "; or a .json fabric file)");
    }
    std::ifstream in(name_or_file);
    if (!in) {
        throw InvalidInput(name_or_file + ": cannot read the fabric file");
    }
    nlohmann::json j;
    try {
        in >> j;
    } catch (const std::exception& e) {
        throw InvalidInput(name_or_file + ": not valid JSON (" + e.what() + ")");
    }
    if (!j.is_object()) {
        throw InvalidInput(name_or_file + ": a fabric file is a JSON object");
    }
    FabricParams f = fabric_catalogue().front();
    f.name = j.value("name", name_or_file);
    const auto num = [&](const char* key, double& field, bool allow_zero) {
        if (!j.contains(key)) {
            return;
        }
        if (!j[key].is_number() || !std::isfinite(j[key].get<double>()) ||
            j[key].get<double>() < 0 || (!allow_zero && j[key].get<double>() == 0)) {
            throw InvalidInput(name_or_file + ": \"" + key + "\" must be a " +
                               (allow_zero ? "non-negative" : "positive") + " finite number");
        }
        field = j[key].get<double>();
    };
    num("density_g_m2", f.density_g_m2, false);
    num("stretch_warp_n_m", f.stretch_warp_n_m, false);
    num("stretch_weft_n_m", f.stretch_weft_n_m, false);
    num("shear_n_m", f.shear_n_m, false);
    num("bending_un_m", f.bending_un_m, true);
    num("friction", f.friction, true);
    num("thickness_mm", f.thickness_mm, false);
    for (const auto& [key, value] : j.items()) {
        static const char* known[] = {
            "name",      "density_g_m2", "stretch_warp_n_m", "stretch_weft_n_m",
            "shear_n_m", "bending_un_m", "friction",         "thickness_mm"};
        bool ok = false;
        for (const char* k : known) {
            ok = ok || key == k;
        }
        if (!ok) {
            throw InvalidInput(name_or_file + ": unknown field \"" + key + "\"");
        }
    }
    return f;
}

}  // namespace tapeline::garment
