// Body landmarks found from the geometry (internal/landmark_finder.h; definitions with their
// ISO 8559-1 / ASTM D5219 terms in measurement/README.md); points given by the user
// (landmark_overrides.h) replace those found.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/measurement/body.h>
#include <tapeline/measurement/internal/landmark_finder.h>
#include <tapeline/measurement/landmark_overrides.h>
#include <tapeline/measurement/measurement_types.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace tapeline::measurement {

/// What find_landmarks did.
struct LandmarkReport {
    std::size_t sections = 0;           ///< plane sections cut
    std::vector<std::string> warnings;  ///< landmarks not found, odd contacts
    /// The chin's underside, mm above the floor, when the front midline shows it (the first
    /// level above the armpits where it comes forward by more than 2 mm per mm of height).
    std::optional<double> chin_underside;
};

/// Every landmark of landmark_names() on the body: found, overridden or not_found with a reason.
/// A landmark that cannot be found is a value (not_found), not an exception: the mesh was
/// checked when the Body was made (make_body).
inline LandmarkSet find_landmarks(const Body& body, const MeasureOptions& options = {},
                                  const LandmarkOverrides& overrides = {},
                                  LandmarkReport* report = nullptr) {
    internal::LandmarkFinder finder(body.mesh, options, body.frame.pose,
                                    overrides.canonical_points(body.frame));
    LandmarkSet set = finder.run();
    if (report) {
        report->sections = finder.cuts();
        report->warnings = finder.warnings();
        report->chin_underside = finder.chin_underside();
    }
    return set;
}

}  // namespace tapeline::measurement
