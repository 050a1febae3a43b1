// A FAST record (W, C, E5/E20/E100 per direction, EB5, T2, T100) shared by the fabric tests: a
// shirting-like fabric whose warp is stiffer than its weft and whose tensile curve stiffens.
#pragma once

#include <nlohmann/json.hpp>

namespace tapeline_test {

inline nlohmann::json fast_record() {
    return {{"W", 168},         {"C_warp", 15},     {"C_weft", 12},   {"E5_warp", 0.67},
            {"E20_warp", 1.87}, {"E100_warp", 4.9}, {"E5_weft", 0.9}, {"E20_weft", 2.6},
            {"E100_weft", 6.8}, {"EB5", 4.7},       {"T2", 0.62},     {"T100", 0.51}};
}

}  // namespace tapeline_test
