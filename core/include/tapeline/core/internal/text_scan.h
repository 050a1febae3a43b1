// Small helpers shared by the mesh format readers: whole-file loading, line and token scanning
// with line numbers, and number parsing that says what it could not parse.
#pragma once

#include <tapeline/core/errors.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <system_error>

namespace tapeline::internal {

/// Largest mesh or point file read: the soup and the mesh built from it take several times the
/// file in memory, and line numbers are 32-bit.
inline constexpr std::uintmax_t max_mesh_file_bytes = std::uintmax_t(2) << 30;

/// Refuses a directory, and a regular file larger than `max_bytes` (`what`: "a mesh file", ...),
/// before anything is read.
inline void check_input_file(const std::string& path, std::uintmax_t max_bytes, const char* what) {
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (std::filesystem::is_directory(status)) {
        throw InvalidInput(path + ": is a directory, not a file");
    }
    if (std::filesystem::is_regular_file(status)) {
        const std::uintmax_t bytes = std::filesystem::file_size(path, ec);
        if (!ec && bytes > max_bytes) {
            throw InvalidInput(path + ": " + std::to_string(bytes >> 20) +
                               " MiB is larger than the " + std::to_string(max_bytes >> 20) +
                               " MiB " + what + " may have");
        }
    }
}

/// The whole file as bytes; a missing or unreadable file is InvalidInput naming the path.
inline std::string load_file(const std::string& path) {
    check_input_file(path, max_mesh_file_bytes, "a mesh or point file");
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        const std::error_code ec(errno, std::generic_category());
        throw InvalidInput(path + ": cannot open file: " + ec.message());
    }
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    if (size < 0) {
        throw InvalidInput(path + ": cannot read file (is it a directory?)");
    }
    in.seekg(0, std::ios::beg);
    std::string bytes(static_cast<std::size_t>(size), '\0');
    if (size > 0 && !in.read(bytes.data(), size)) {
        throw InvalidInput(path + ": cannot read file (read error)");
    }
    if (bytes.empty()) {
        throw InvalidInput(path + ": file is empty");
    }
    return bytes;
}

inline bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
}

/// Walks a buffer line by line (LF or CRLF), counting lines from 1.
class LineScanner {
public:
    explicit LineScanner(std::string_view text, std::size_t start = 0, std::uint32_t first_line = 1)
        : text_(text), pos_(start), next_line_(first_line) {}

    /// Next line without its terminator; false at the end of the buffer.
    bool next(std::string_view& line) {
        if (pos_ >= text_.size()) {
            return false;
        }
        const std::size_t end = text_.find('\n', pos_);
        const std::size_t stop = end == std::string_view::npos ? text_.size() : end;
        line = text_.substr(pos_, stop - pos_);
        if (!line.empty() && line.back() == '\r') {
            line.remove_suffix(1);
        }
        pos_ = stop + 1;
        line_ = next_line_++;
        return true;
    }
    std::uint32_t line_number() const { return line_; }
    std::size_t position() const { return pos_; }

private:
    std::string_view text_;
    std::size_t pos_;
    std::uint32_t next_line_;
    std::uint32_t line_ = 0;
};

/// Splits one line into whitespace-separated tokens.
class Tokens {
public:
    explicit Tokens(std::string_view line) : line_(line) {}
    bool next(std::string_view& token) {
        while (pos_ < line_.size() && is_space(line_[pos_])) {
            ++pos_;
        }
        if (pos_ >= line_.size()) {
            return false;
        }
        const std::size_t start = pos_;
        while (pos_ < line_.size() && !is_space(line_[pos_])) {
            ++pos_;
        }
        token = line_.substr(start, pos_ - start);
        return true;
    }
    std::string_view rest() const { return line_.substr(std::min(pos_, line_.size())); }

private:
    std::string_view line_;
    std::size_t pos_ = 0;
};

/// Line without a trailing `#` comment.
inline std::string_view strip_comment(std::string_view line) {
    const std::size_t hash = line.find('#');
    return hash == std::string_view::npos ? line : line.substr(0, hash);
}

inline bool is_blank(std::string_view line) {
    for (char c : line) {
        if (!is_space(c)) {
            return false;
        }
    }
    return true;
}

/// Parses a whole token as a double (accepts a leading '+', nan and inf); false if it is not one.
inline bool parse_double(std::string_view token, double& value) {
    if (!token.empty() && token.front() == '+') {
        token.remove_prefix(1);
    }
    if (token.empty()) {
        return false;
    }
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (ec == std::errc::result_out_of_range) {
        // Overflow: from_chars leaves the value untouched; an overflowing literal is infinite.
        value = (token.front() == '-') ? -HUGE_VAL : HUGE_VAL;
        return end == token.data() + token.size();
    }
    return ec == std::errc() && end == token.data() + token.size();
}

/// Parses a whole token as a signed integer; false if it is not one.
inline bool parse_integer(std::string_view token, long long& value) {
    if (!token.empty() && token.front() == '+') {
        token.remove_prefix(1);
    }
    if (token.empty()) {
        return false;
    }
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    return ec == std::errc() && end == token.data() + token.size();
}

/// "line 17: " prefix used by the text readers.
inline std::string at_line(std::uint32_t line) {
    return "line " + std::to_string(line) + ": ";
}

/// Short printable excerpt of a token for messages.
inline std::string quoted(std::string_view token) {
    std::string s(token.substr(0, 40));
    for (char& c : s) {
        if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) {
            c = '?';
        }
    }
    return "'" + s + (token.size() > 40 ? "...'" : "'");
}

/// "" if finite, else "a NaN coordinate" / "an infinite coordinate".
inline const char* non_finite_kind(double x, double y, double z) {
    if (std::isnan(x) || std::isnan(y) || std::isnan(z)) {
        return "a NaN coordinate";
    }
    if (std::isinf(x) || std::isinf(y) || std::isinf(z)) {
        return "an infinite coordinate";
    }
    return "";
}

/// Lower-case extension with its dot ("" if none).
/// Reads the three coordinates of text vertex `index` (OFF and OBJ share this) from `tokens`,
/// rejecting a missing, unparsable or non-finite coordinate with a message naming the line.
inline std::array<double, 3> read_xyz(Tokens& tokens, const std::string& path, std::uint32_t line,
                                      std::size_t index) {
    std::array<double, 3> p{};
    std::string_view token;
    for (int k = 0; k < 3; ++k) {
        if (!tokens.next(token)) {
            throw InvalidInput(path + ": " + at_line(line) + "vertex " + std::to_string(index) +
                               " has " + std::to_string(k) + " coordinates, expected 3");
        }
        if (!parse_double(token, p[k])) {
            throw InvalidInput(path + ": " + at_line(line) + "vertex " + std::to_string(index) +
                               ": cannot parse " + quoted(token) + " as a number");
        }
    }
    if (const char* bad = non_finite_kind(p[0], p[1], p[2]); *bad) {
        throw InvalidInput(path + ": " + at_line(line) + "vertex " + std::to_string(index) +
                           " has " + bad);
    }
    return p;
}

inline std::string lower_extension(const std::string& path) {
    const std::size_t slash = path.find_last_of("/\\");
    const std::size_t dot = path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) {
        return "";
    }
    std::string ext = path.substr(dot);
    for (char& c : ext) {
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return ext;
}

/// Initial capacity for `announced` elements of at least `min_bytes` each in a file of `file_bytes`
/// bytes: a corrupt header must not make us allocate terabytes before we notice the truncation.
inline std::size_t safe_reserve(std::uint64_t announced, std::size_t file_bytes,
                                std::size_t min_bytes) {
    const std::uint64_t cap = file_bytes / (min_bytes == 0 ? 1 : min_bytes) + 1;
    return static_cast<std::size_t>(announced < cap ? announced : cap);
}

}  // namespace tapeline::internal
