// Fabrics the cloth solver knows by name, and fabric files (JSON with FabricParams' fields).
//
// The names are those of the fabric library (fabric_lab.h): five cloth classes (cotton_jersey,
// cotton_shirting, denim, silk_charmeuse, wool_suiting: order-of-magnitude values of their class,
// not measurements of one cloth) and the ten fabrics measured by Wang, O'Brien and Ramamoorthi
// 2011. `tapeline fabric convert` writes fabric files from KES-F and FAST reports.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/core/json_read.h>
#include <tapeline/garment/drape_types.h>
#include <tapeline/garment/fabric_lab.h>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace tapeline::garment {

/// The solver parameters of every library fabric, in library order.
inline const std::vector<FabricParams>& fabric_catalogue() {
    static const std::vector<FabricParams> list = [] {
        std::vector<FabricParams> l;
        for (const Fabric& f : fabric_library()) {
            l.push_back(f.params);
        }
        return l;
    }();
    return list;
}

/// The library fabric called `name_or_file`, or a fabric file (.json with any of fabric_json's
/// fields; FabricParams' fields left out take cotton_jersey's values). InvalidInput naming the
/// fabric, or the file and field, when it is unknown or a value is not a positive finite number.
inline Fabric fabric_record_from(const std::string& name_or_file) {
    if (const Fabric* f = library_fabric(name_or_file)) {
        return *f;
    }
    const bool json_file =
        name_or_file.size() > 5 && name_or_file.compare(name_or_file.size() - 5, 5, ".json") == 0;
    if (!json_file) {
        std::string known;
        for (const Fabric& f : fabric_library()) {
            known += (known.empty() ? "" : ", ") + f.params.name;
        }
        throw InvalidInput("--fabric: unknown fabric '" + name_or_file + "' (known: " + known +
                           "; or a .json fabric file)");
    }
    return fabric_from_json(tapeline::json::parse_json_file(name_or_file), name_or_file);
}

/// The solver parameters of fabric_record_from(name_or_file).
inline FabricParams fabric_from(const std::string& name_or_file) {
    return fabric_record_from(name_or_file).params;
}

}  // namespace tapeline::garment
