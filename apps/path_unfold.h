// The unfolded strip of a path for `tapeline geodesic path --svg` (apps/path_unfold.cpp).
#pragma once

#include "app_types.h"

#include <nlohmann/json.hpp>

#include <string>

namespace tapeline::app {

struct UnfoldOutput {
    nlohmann::json summary;  ///< faces, lengths (traced, unfolded, straight), straight_inside
    std::string svg;         ///< the picture
};

/// Unfolds the faces crossed by `points` (the JSON points array of a path on `mesh`).
/// InvalidInput when there is no path or it does not run on the faces.
UnfoldOutput unfold_path_output(const Mesh& mesh, const nlohmann::json& points,
                                const std::string& title);

}  // namespace tapeline::app
