// Reading a pattern file of any supported format: the format is recognised from the file's JSON
// keys, so a caller (the tool, a batch import, bindings) needs only a path.
//
//   "format": "tapeline-pattern"        → json         (read_pattern_json)
//   "pattern": {"panels": ...}          → garmentcode  (read_garmentcode)
//   "pieces" and "design"               → freesewing   (read_freesewing, with the design's seams)
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/core/json_read.h>
#include <tapeline/pattern/io_freesewing.h>
#include <tapeline/pattern/io_garmentcode.h>
#include <tapeline/pattern/io_json.h>
#include <tapeline/pattern/pattern.h>

#include <nlohmann/json.hpp>

#include <fstream>
#include <string>

namespace tapeline::pattern {

/// The importer a file needs ("freesewing", "garmentcode" or "json"), recognised from its JSON
/// keys. Throws InvalidInput naming the file when it cannot be opened, is not JSON, or matches no
/// known format.
///
/// \throws InvalidInput naming the file, as above.
inline std::string detect_pattern_format(const std::string& path) {
    // read_text_file refuses directories and oversized files; the depth check runs before the
    // parser so that hostile nesting cannot exhaust the stack.
    const std::string text = json::read_text_file(path);
    json::check_json_depth(text, path);
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {
        throw InvalidInput(path + ": not valid JSON (" + std::string(e.what()) +
                           "); give the format for other files");
    }
    if (j.is_object() && j.value("format", "") == "tapeline-pattern") {
        return "json";
    }
    if (j.is_object() && j.contains("pattern") && j["pattern"].is_object() &&
        j["pattern"].contains("panels")) {
        return "garmentcode";
    }
    if (j.is_object() && j.contains("pieces") && j.contains("design")) {
        return "freesewing";
    }
    throw InvalidInput(path +
                       ": cannot tell the pattern format (not FreeSewing, GarmentCode or "
                       "tapeline JSON); give the format");
}

/// Reads a pattern file with the importer `format` ("freesewing", "garmentcode", "json"; "auto" or
/// empty: detect_pattern_format). `report` (optional) receives what the importer did.
/// Throws InvalidInput for an unknown format name and whatever the importer throws.
///
/// \throws InvalidInput for an unknown format name, an undetectable file, or from the importer
///         (read_freesewing, read_garmentcode, read_pattern_json).
inline Pattern read_pattern_file(const std::string& path, std::string format = "auto",
                                 ImportReport* report = nullptr) {
    if (format.empty() || format == "auto") {
        format = detect_pattern_format(path);
    }
    if (format == "freesewing") {
        return read_freesewing(path, report);
    }
    if (format == "garmentcode") {
        return read_garmentcode(path, report);
    }
    if (format == "json") {
        return read_pattern_json(path);
    }
    throw InvalidInput("unknown pattern format '" + format +
                       "' (known: auto, freesewing, garmentcode, json)");
}

}  // namespace tapeline::pattern
