// Registration of the tool's subcommand families (each defined in its own translation unit).
#pragma once

#include <string>

namespace CLI {
class App;
}

namespace tapeline::app {
void register_mesh_commands(CLI::App& app);
void register_geodesic_commands(CLI::App& app);
void register_bench_commands(CLI::App& app);
void register_pattern_commands(CLI::App& app);
void register_grade_commands(CLI::App& app);
void register_measure_commands(CLI::App& app);

/// Whether path names a regular file (defined in pattern_commands.cpp).
bool is_file(const std::string& path);
}  // namespace tapeline::app
