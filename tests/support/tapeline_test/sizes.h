// Fixtures for the sizes tests: data paths and temporary files. Header-only: the sizes module
// has no CGAL, so its tests include its headers directly.
#pragma once

#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <string>

namespace tapeline_test::sizes {

inline std::string data_patterns(const std::string& name) {
    return std::string(TAPELINE_DATA_DIR) + "/patterns/" + name;
}

inline std::string shared_patterns(const std::string& name) {
    return std::string(TAPELINE_SHARED_DATA_DIR) + "/patterns/" + name;
}

/// A fresh directory per test, removed with everything in it at the end.
struct TempDir {
    std::filesystem::path path;
    TempDir() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        path = std::filesystem::temp_directory_path() /
               ("tapeline_sizes_" + std::string(info ? info->name() : "test") + "_" +
                std::to_string(::getpid()));
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
    }
    std::string file(const std::string& name) const { return (path / name).string(); }
    /// Writes `text` to `name` in the directory; returns its path.
    std::string write(const std::string& name, const std::string& text) const {
        std::ofstream(file(name)) << text;
        return file(name);
    }
};

}  // namespace tapeline_test::sizes
