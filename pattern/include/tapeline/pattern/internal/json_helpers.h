// Checked JSON access for the pattern readers: core's helpers (tapeline/core/json_read.h) under
// the names the readers use, plus pattern points.
#pragma once

#include <tapeline/core/json_read.h>
#include <tapeline/pattern/geometry.h>

namespace tapeline::pattern::internal {

using json::boolean;
using json::field;
using json::index_value;
using json::Json;
using json::number;
using json::optional_field;
using json::parse_json;
using json::parse_json_file;
using json::read_text_file;
using json::require_array;
using json::require_object;
using json::string;
using json::type_name;
using json::Where;

/// [x, y] as a point.
inline Point2 point(const Json& j, const Where& w) {
    if (!j.is_array() || j.size() != 2) {
        throw InvalidInput(w.str() + ": expected a point [x, y], got " + j.dump());
    }
    return {number(j[0], w.index(0)), number(j[1], w.index(1))};
}

}  // namespace tapeline::pattern::internal
