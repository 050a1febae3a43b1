// Length units and their size in millimetres: the one table every reader and option (`--units`
// of a body mesh, the unit of a measurement file, a pattern's units) converts through. Inside the
// library lengths are millimetres (DESIGN.md §8).
#pragma once

#include <tapeline/core/errors.h>

#include <optional>
#include <string>

namespace tapeline {

enum class LengthUnit { mm, cm, dm, m, inch };

/// "mm", "cm", "dm", "m" or "inch".
inline const char* to_string(LengthUnit u) {
    switch (u) {
        case LengthUnit::mm:
            return "mm";
        case LengthUnit::cm:
            return "cm";
        case LengthUnit::dm:
            return "dm";
        case LengthUnit::m:
            return "m";
        case LengthUnit::inch:
            break;
    }
    return "inch";
}

inline double millimetres_per(LengthUnit u) {
    switch (u) {
        case LengthUnit::mm:
            return 1;
        case LengthUnit::cm:
            return 10;
        case LengthUnit::dm:
            return 100;
        case LengthUnit::m:
            return 1000;
        case LengthUnit::inch:
            break;
    }
    return 25.4;
}

/// The unit spelled `text` (its to_string name, or "in" for the inch); nullopt for anything else.
inline std::optional<LengthUnit> length_unit(const std::string& text) {
    for (LengthUnit u :
         {LengthUnit::mm, LengthUnit::cm, LengthUnit::dm, LengthUnit::m, LengthUnit::inch}) {
        if (text == to_string(u)) {
            return u;
        }
    }
    if (text == "in") {
        return LengthUnit::inch;
    }
    return std::nullopt;
}

/// Millimetres per `unit` (see length_unit); InvalidInput naming `where` for anything else.
///
/// \throws InvalidInput when `unit` is not mm, cm, dm, m, inch or in.
inline double millimetres_per_unit(const std::string& unit, const std::string& where) {
    if (const auto u = length_unit(unit)) {
        return millimetres_per(*u);
    }
    throw InvalidInput(where + ": unknown unit '" + unit + "' (expected mm, cm, dm, m or inch)");
}

}  // namespace tapeline
