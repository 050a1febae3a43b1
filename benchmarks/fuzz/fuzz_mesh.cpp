// libFuzzer target: the OFF, OBJ, PLY and STL readers and the coordinate-range check; the first
// byte picks the format.
#include "fuzz_target.h"

#include <tapeline/core/internal/coordinate_range.h>
#include <tapeline/core/internal/read_obj.h>
#include <tapeline/core/internal/read_off.h>
#include <tapeline/core/internal/read_ply.h>
#include <tapeline/core/internal/read_stl.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) {
        return 0;
    }
    return tapeline_fuzz::run(data + 1, size - 1, [&](const std::string& text) {
        namespace ti = tapeline::internal;
        tapeline::PolygonSoup soup;
        switch (data[0] % 4) {
            case 0:
                soup = ti::read_off("fuzz.off", text);
                break;
            case 1:
                soup = ti::read_obj("fuzz.obj", text);
                break;
            case 2:
                soup = ti::read_ply("fuzz.ply", text);
                break;
            default:
                soup = ti::read_stl("fuzz.stl", text);
        }
        if (!soup.points.empty()) {
            ti::check_coordinate_range("fuzz", soup.points.front().data(), soup.points.size(), 3);
        }
    });
}
