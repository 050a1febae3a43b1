// libFuzzer target: the JSON readers of a fabric file, of KES-F and FAST measurements, and of
// landmark overrides; the first byte picks the reader.
#include "fuzz_target.h"

#include <tapeline/core/json_read.h>
#include <tapeline/garment/fabric_lab.h>
#include <tapeline/measurement/landmarks.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) {
        return 0;
    }
    return tapeline_fuzz::run(data + 1, size - 1, [&](const std::string& text) {
        const int which = data[0] % 4;
        if (which == 0) {
            tapeline::measurement::parse_landmark_overrides(text, "fuzz.json");
            return;
        }
        const auto j = tapeline::json::parse_json(text, "fuzz.json");
        if (which == 1) {
            tapeline::garment::fabric_from_json(j, "fuzz.json");
        } else if (which == 2) {
            tapeline::garment::fabric_from_kes(j, "fuzz.json");
        } else {
            tapeline::garment::fabric_from_fast(j, "fuzz.json");
        }
    });
}
