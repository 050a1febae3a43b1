// A GoogleTest fixture for tests that write input files: a temporary directory per test.
#pragma once

#include <tapeline_test/io.h>

#include <gtest/gtest.h>

#include <string>

namespace tapeline_test {

class TempFileTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = temp_dir(::testing::UnitTest::GetInstance()->current_test_info()->name());
    }
    /// Writes `content` to dir/name and returns the path.
    std::string file(const std::string& name, const std::string& content) const {
        const std::string path = dir_ + "/" + name;
        write_bytes(path, content);
        return path;
    }
    std::string dir_;
};

}  // namespace tapeline_test
