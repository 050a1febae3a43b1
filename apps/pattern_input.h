// Reading a pattern file given on the command line (`tapeline pattern import`, `tapeline grade`);
// defined in pattern_commands.cpp.
#pragma once

#include <tapeline/pattern/pattern.h>

#include <string>

namespace tapeline::app {

/// Whether path names a regular file.
bool is_file(const std::string& path);
/// The importer a file needs ("freesewing", "garmentcode", "json"), recognised from its JSON keys;
/// InvalidInput naming the file when it cannot tell.
std::string detect_format(const std::string& path);
/// Reads a pattern file with the importer `format` ("auto" or empty: detect_format).
pattern::Pattern import_file(const std::string& path, std::string format,
                             pattern::ImportReport* report);

}  // namespace tapeline::app
