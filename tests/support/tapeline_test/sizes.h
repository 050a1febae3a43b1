// Fixtures for the sizes tests: data paths and temporary files. Header-only: the sizes module
// has no CGAL, so its tests include its headers directly.
#pragma once

#include <tapeline_test/temp_dir.h>

#include <string>

namespace tapeline_test::sizes {

inline std::string data_patterns(const std::string& name) {
    return std::string(TAPELINE_DATA_DIR) + "/patterns/" + name;
}

inline std::string shared_patterns(const std::string& name) {
    return std::string(TAPELINE_SHARED_DATA_DIR) + "/patterns/" + name;
}

}  // namespace tapeline_test::sizes
