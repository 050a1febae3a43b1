// libFuzzer target: the XML reader through the Seamly2D individual (.vit) and multisize (.vst)
// readers; the first byte picks the format.
#include "fuzz_target.h"

#include <tapeline/sizes/seamly.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) {
        return 0;
    }
    return tapeline_fuzz::run(data + 1, size - 1, [&](const std::string& text) {
        if (data[0] % 2 == 0) {
            tapeline::sizes::parse_seamly_individual(text, "fuzz.vit");
        } else {
            tapeline::sizes::parse_seamly_multisize(text, "fuzz.vst");
        }
    });
}
