// libFuzzer target: the database's compressed pattern blob decoder.
#include "fuzz_target.h"

#include <tapeline/pattern/compression.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return tapeline_fuzz::run(data, size, [&](const std::string&) {
        tapeline::pattern::decompress_pattern(data, size, "fuzz blob");
    });
}
