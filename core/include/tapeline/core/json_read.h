// Checked access to JSON input: every failure is an InvalidInput naming the file and the JSON
// path of the offending value (DESIGN.md §4). Readers of every module (patterns, measurement
// sets, landmark files) share it.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/core/internal/text_scan.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>

namespace tapeline::json {

using Json = nlohmann::json;

/// Deepest nesting of arrays and objects accepted: real pattern and measurement files stay under
/// 20 levels, and code that walks a parsed document (dump, conversions) recurses once per level.
inline constexpr std::size_t max_json_depth = 256;
/// Largest JSON or XML document read: the parsed tree takes several times the text in memory.
inline constexpr std::uintmax_t max_document_bytes = std::uintmax_t(256) << 20;

/// The whole file as text.
///
/// \throws InvalidInput naming `path` when it is missing, a directory, larger than
///         max_document_bytes, or cannot be read.
inline std::string read_text_file(const std::string& path) {
    tapeline::internal::check_input_file(path, max_document_bytes, "a JSON or XML document");
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw InvalidInput(path + ": cannot open for reading");
    }
    std::ostringstream ss;
    ss << in.rdbuf();
    if (in.bad()) {
        throw InvalidInput(path + ": read error");
    }
    return ss.str();
}

/// Refuses text whose arrays and objects nest deeper than max_json_depth, before parsing it.
///
/// \throws InvalidInput naming `source` when the nesting is deeper.
inline void check_json_depth(const std::string& text, const std::string& source) {
    std::size_t depth = 0;
    bool in_string = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (in_string) {
            if (c == '\\') {
                ++i;
            } else if (c == '"') {
                in_string = false;
            }
        } else if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            if (++depth > max_json_depth) {
                throw InvalidInput(source + ": JSON nested deeper than " +
                                   std::to_string(max_json_depth) + " levels at byte " +
                                   std::to_string(i));
            }
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
}

/// Parses JSON text; a syntax error (truncated file, NaN literal, ...) names the source and byte.
///
/// \throws InvalidInput on a syntax error, a number beyond the range of a double (2e682), or
///         nesting deeper than max_json_depth.
inline Json parse_json(const std::string& text, const std::string& source) {
    check_json_depth(text, source);
    try {
        return Json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        throw InvalidInput(source + ": malformed JSON at byte " + std::to_string(e.byte) + ": " +
                           e.what());
    } catch (const nlohmann::json::exception& e) {  // out_of_range.406: number overflow
        throw InvalidInput(source + ": malformed JSON: " + e.what());
    }
}

/// Reads and parses a JSON file.
///
/// \throws InvalidInput as read_text_file and parse_json.
inline Json parse_json_file(const std::string& path) {
    return parse_json(read_text_file(path), path);
}

/// A JSON value together with where it is: "file: pieces[2].paths.seam".
struct Where {
    std::string source;  ///< file name or other source of the document
    std::string path;    ///< path inside the document; empty at the top level
    /// "source: path" for messages
    std::string str() const { return source + ": " + (path.empty() ? "(top level)" : path); }
    /// member `k` of this value
    Where key(const std::string& k) const { return {source, path.empty() ? k : path + "." + k}; }
    /// element `i` of this array
    Where index(std::size_t i) const { return {source, path + "[" + std::to_string(i) + "]"}; }
};

inline const char* type_name(const Json& j) {
    return j.type_name();
}

/// `j`, which must be an object.
///
/// \throws InvalidInput naming `w` otherwise.
inline const Json& require_object(const Json& j, const Where& w) {
    if (!j.is_object()) {
        throw InvalidInput(w.str() + ": expected an object, got " + type_name(j));
    }
    return j;
}

/// `j`, which must be an array.
///
/// \throws InvalidInput naming `w` otherwise.
inline const Json& require_array(const Json& j, const Where& w) {
    if (!j.is_array()) {
        throw InvalidInput(w.str() + ": expected an array, got " + type_name(j));
    }
    return j;
}

/// obj[key], which must exist.
///
/// \throws InvalidInput naming `w` and `key` when it does not.
inline const Json& field(const Json& obj, const std::string& key, const Where& w) {
    require_object(obj, w);
    const auto it = obj.find(key);
    if (it == obj.end()) {
        throw InvalidInput(w.str() + ": missing field '" + key + "'");
    }
    return *it;
}

inline const Json* optional_field(const Json& obj, const std::string& key) {
    if (!obj.is_object()) {
        return nullptr;
    }
    const auto it = obj.find(key);
    return it == obj.end() || it->is_null() ? nullptr : &*it;
}

/// A finite number (JSON has no NaN; writers that meet one emit null, which lands here).
///
/// \throws InvalidInput naming `w` for anything else.
inline double number(const Json& j, const Where& w) {
    if (!j.is_number()) {
        throw InvalidInput(w.str() + ": expected a number, got " +
                           (j.is_null() ? std::string("null (NaN?)") : type_name(j)));
    }
    const double v = j.get<double>();
    if (!std::isfinite(v)) {
        throw InvalidInput(w.str() + ": number is not finite");
    }
    return v;
}

/// A string.
///
/// \throws InvalidInput naming `w` for anything else.
inline std::string string(const Json& j, const Where& w) {
    if (!j.is_string()) {
        throw InvalidInput(w.str() + ": expected a string, got " + type_name(j));
    }
    return j.get<std::string>();
}

/// true or false.
///
/// \throws InvalidInput naming `w` for anything else.
inline bool boolean(const Json& j, const Where& w) {
    if (!j.is_boolean()) {
        throw InvalidInput(w.str() + ": expected true or false, got " + type_name(j));
    }
    return j.get<bool>();
}

/// A non-negative integer.
///
/// \throws InvalidInput naming `w` for anything else.
inline std::size_t index_value(const Json& j, const Where& w) {
    if (!j.is_number_integer() || j.get<long long>() < 0) {
        throw InvalidInput(w.str() + ": expected a non-negative integer, got " + j.dump());
    }
    return j.get<std::size_t>();
}

}  // namespace tapeline::json
