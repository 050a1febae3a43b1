// `tapeline dress --wrinkles DB`: the database read and checked before the drape (a bad file
// fails before minutes of simulation), the wrinkles synthesised on the drape after it
// (wrinkles/synthesis.h; defined in wrinkles_synthesis.cpp so that the dress command's unit does
// not compile the synthesis).
#pragma once

#include <tapeline/garment/drape_types.h>
#include <tapeline/garment/garment_types.h>
#include <tapeline/measurement/body_types.h>

#include <nlohmann/json.hpp>

#include <memory>
#include <string>
#include <vector>

namespace tapeline::app {

/// The wrinkled garment, its per-triangle stretch, the synthesis report and a one-line summary.
struct DressedWrinkles {
    garment::GarmentMesh garment;
    std::vector<double> stretch;
    nlohmann::ordered_json report;
    std::string summary;
};

/// A wrinkle database ready for a dressed garment.
class WrinkleDressing {
public:
    /// Reads `path` and checks it is a database of `fabric`.
    /// \throws InvalidInput naming the file and what is wrong with it.
    WrinkleDressing(const std::string& path, const garment::FabricParams& fabric);
    /// Wrinkles on `g` (the body's canonical frame, mm) draped on `body`.
    DressedWrinkles apply(const garment::GarmentMesh& g, const measurement::Body& body) const;

private:
    struct Impl;
    std::shared_ptr<const Impl> impl_;
};

}  // namespace tapeline::app
