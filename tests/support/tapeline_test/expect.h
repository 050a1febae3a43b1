// GoogleTest helpers shared by the test files.
#pragma once

#include <gtest/gtest.h>

#include <exception>
#include <string>
#include <vector>

namespace tapeline_test {

inline bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

/// The message of the E that `call` throws, "(no exception)" when it throws none (another
/// exception type propagates).
template <class E = std::exception, class Call>
std::string message_of(Call&& call) {
    try {
        call();
    } catch (const E& e) {
        return e.what();
    }
    return "(no exception)";
}

/// Runs `call` and checks that it throws E with every one of `parts` in its message.
template <class E, class Call>
void expect_error(Call call, const std::vector<std::string>& parts, const std::string& context) {
    try {
        call();
        ADD_FAILURE() << context << ": no exception";
    } catch (const E& e) {
        for (const auto& p : parts) {
            EXPECT_TRUE(contains(e.what(), p))
                << context << ": '" << e.what() << "' lacks '" << p << "'";
        }
    } catch (const std::exception& e) {
        ADD_FAILURE() << context << ": wrong exception type: " << e.what();
    }
}

}  // namespace tapeline_test
