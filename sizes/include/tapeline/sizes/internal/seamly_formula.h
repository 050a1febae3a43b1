// The formulas of Seamly2D/Valentina measurement files: a value may be an expression over numbers
// and the file's other measurements ("(neck_circ - neck_arc_f)", "@M_J10 + bustpoint_to_waist",
// "0.91*leg_ankle_circ"), evaluated in the file's unit.
//
// Supported: decimal numbers, measurement names, + - * /, unary sign, parentheses. That is the
// whole arithmetic Valentina's bundled tables and example measurements use. Refused with the
// formula and what is not supported: functions (sqrt(...)), other operators (^, comparison, the
// conditional ?:), division by zero; a formula with more is refused rather than guessed. Names
// are resolved by the caller (seamly.h), which also refuses cycles and reports a name the file
// does not define as SeamlyUndefinedName.
#pragma once

#include <tapeline/core/errors.h>

#include <cctype>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <functional>
#include <string>

namespace tapeline::sizes::internal {

/// A formula refers to a name its file does not define: the measurement cannot be evaluated,
/// by Seamly2D either.
struct SeamlyUndefinedName : InvalidInput {
    using InvalidInput::InvalidInput;
};

/// Characters that end a measurement name (Valentina's shortName pattern excludes them).
inline bool seamly_name_stop(char c) {
    return std::isspace(static_cast<unsigned char>(c)) ||
           std::string("*/&|!<>^()-+.,=?:;'\"").find(c) != std::string::npos;
}

/// Recursive-descent evaluation of one formula; `lookup` gives the value of a name (file units).
class SeamlyFormula {
public:
    using Lookup = std::function<double(const std::string&)>;

    SeamlyFormula(const std::string& text, Lookup lookup, std::string where)
        : s_(text), lookup_(std::move(lookup)), where_(std::move(where)) {}

    double evaluate() {
        const double v = sum();
        skip_space();
        if (pos_ < s_.size()) {
            unsupported(std::string("'") + s_[pos_] + "' at character " + std::to_string(pos_ + 1));
        }
        if (!std::isfinite(v)) {
            fail(" is not finite");
        }
        return v;
    }

private:
    const std::string& s_;
    Lookup lookup_;
    std::string where_;
    std::size_t pos_ = 0;
    std::size_t depth_ = 0;

    [[noreturn]] void fail(const std::string& what) const {
        throw InvalidInput(where_ + ": formula '" + s_ + "'" + what);
    }
    [[noreturn]] void unsupported(const std::string& what) const {
        fail(": " + what +
             " is not supported (numbers, measurement names, + - * / and "
             "parentheses are)");
    }

    void skip_space() {
        while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) {
            ++pos_;
        }
    }
    bool take(char c) {
        skip_space();
        if (pos_ < s_.size() && s_[pos_] == c) {
            ++pos_;
            return true;
        }
        return false;
    }

    double sum() {
        double v = product();
        for (;;) {
            if (take('+')) {
                v += product();
            } else if (take('-')) {
                v -= product();
            } else {
                return v;
            }
        }
    }
    double product() {
        double v = unary();
        for (;;) {
            if (take('*')) {
                v *= unary();
            } else if (take('/')) {
                const double d = unary();
                if (d == 0) {
                    fail(": division by zero");
                }
                v /= d;
            } else {
                return v;
            }
        }
    }
    double unary() {
        if (take('-')) {
            return -unary();
        }
        if (take('+')) {
            return unary();
        }
        return primary();
    }
    double primary() {
        skip_space();
        if (pos_ >= s_.size()) {
            fail(": ends where a number or a name was expected");
        }
        const char c = s_[pos_];
        if (c == '(') {
            // Nesting is bounded so that a hostile file cannot exhaust the stack.
            if (++depth_ > 64) {
                unsupported("nesting deeper than 64 parentheses");
            }
            ++pos_;
            const double v = sum();
            if (!take(')')) {
                fail(": a '(' is not closed");
            }
            --depth_;
            return v;
        }
        if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') {
            const char* b = s_.c_str() + pos_;
            char* e = nullptr;
            const double v = std::strtod(b, &e);
            if (e == b) {
                fail(": '" + std::string(1, c) + "' does not start a number");
            }
            pos_ += static_cast<std::size_t>(e - b);
            return v;
        }
        if (seamly_name_stop(c)) {
            unsupported(std::string("'") + c + "' at character " + std::to_string(pos_ + 1));
        }
        const std::size_t begin = pos_;
        while (pos_ < s_.size() && !seamly_name_stop(s_[pos_])) {
            ++pos_;
        }
        const std::string name = s_.substr(begin, pos_ - begin);
        if (take('(')) {
            unsupported("the function '" + name + "'");
        }
        return lookup_(name);
    }
};

}  // namespace tapeline::sizes::internal
