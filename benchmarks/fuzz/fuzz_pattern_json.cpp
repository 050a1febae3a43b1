// libFuzzer target: the JSON reader (depth check, parse) and the tapeline, FreeSewing and
// GarmentCode pattern importers with validation; the first byte picks the importer.
#include "fuzz_target.h"

#include <tapeline/core/json_read.h>
#include <tapeline/pattern/io_freesewing.h>
#include <tapeline/pattern/io_garmentcode.h>
#include <tapeline/pattern/io_json.h>
#include <tapeline/pattern/validate.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) {
        return 0;
    }
    return tapeline_fuzz::run(data + 1, size - 1, [&](const std::string& text) {
        namespace tp = tapeline::pattern;
        const tapeline::json::Json j = tapeline::json::parse_json(text, "fuzz.json");
        tp::Pattern p;
        switch (data[0] % 3) {
            case 0:
                p = tp::from_json(j, "fuzz.json");
                break;
            case 1:
                p = tp::freesewing_from_json(j, "fuzz.json");
                break;
            default:
                p = tp::garmentcode_from_json(j, "fuzz.json", "fuzz");
        }
        tp::validate(p);
    });
}
