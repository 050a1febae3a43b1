// A body prepared and measured by tapeline_test_support_measurement, for the tests of modules
// built on measurement (garment): its Body and landmarks, without compiling the measurement
// pipeline again in the calling test (DESIGN.md §5).
#pragma once

#include <tapeline/measurement/body.h>
#include <tapeline/measurement/body_types.h>
#include <tapeline/measurement/measurement_types.h>

#include <string>

namespace tapeline_test::measurement {

struct MeasuredBody {
    tapeline::measurement::Body body;
    tapeline::measurement::LandmarkSet landmarks;
    tapeline::measurement::MeasurementSet measurements;  ///< the girths and lengths taken
};

/// read_triangle_mesh<Surface_mesh<Epick>>, make_body, then measure_body's landmarks.
MeasuredBody load_measured_body(const std::string& path,
                                const tapeline::measurement::BodyOptions& options);

/// load_measured_body of a body in decimetres (the MakeHuman bodies of the data folders).
inline MeasuredBody load_dm_body(const std::string& path) {
    tapeline::measurement::BodyOptions o;
    o.name = path;
    o.unit = tapeline::measurement::LengthUnit::dm;
    return load_measured_body(path, o);
}

#ifdef TAPELINE_DATA_DIR
/// A file of the project's data folder, by its path inside it ("bodies/mh_female_average.obj").
inline std::string bundled_path(const std::string& rel) {
    return std::string(TAPELINE_DATA_DIR) + "/" + rel;
}
#endif

}  // namespace tapeline_test::measurement
