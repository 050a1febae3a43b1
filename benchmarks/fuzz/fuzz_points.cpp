// libFuzzer target: the .xyz and .csv point readers; the first byte picks the format.
#include "fuzz_target.h"

#include <tapeline/core/point_io.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) {
        return 0;
    }
    return tapeline_fuzz::run(data + 1, size - 1, [&](const std::string& text) {
        tapeline::internal::read_delimited_points("fuzz", text, data[0] % 2 == 1);
    });
}
