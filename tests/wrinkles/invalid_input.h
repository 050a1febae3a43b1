// The message of the InvalidInput a call throws, for the wrinkle tests' bad-input cases.
#pragma once

#include <tapeline/core/errors.h>

#include <gtest/gtest.h>

#include <functional>
#include <string>

namespace tapeline::test {

/// What `f` throws as InvalidInput, or "(no InvalidInput)".
inline std::string error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const InvalidInput& e) {
        return e.what();
    }
    return "(no InvalidInput)";
}

/// `f` throws InvalidInput whose message holds `needle`.
inline void expect_invalid(const std::function<void()>& f, const std::string& needle) {
    const std::string message = error_of(f);
    EXPECT_NE(message.find(needle), std::string::npos) << message;
}

}  // namespace tapeline::test
