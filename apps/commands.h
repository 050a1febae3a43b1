// Registration of the tool's subcommand families (each defined in its own translation unit).
#pragma once

#include <string>

namespace CLI {
class App;
}
namespace tapeline::geodesic {
struct PointCloudDistanceOptions;
}
namespace tapeline::pattern {
struct Pattern;
}

namespace tapeline::app {
void register_mesh_commands(CLI::App& app);
void register_geodesic_commands(CLI::App& app);
void register_bench_commands(CLI::App& app);
void register_pattern_commands(CLI::App& app);
void register_grade_commands(CLI::App& app);
void register_measure_commands(CLI::App& app);
void register_dress_commands(CLI::App& app);
void register_fabric_commands(CLI::App& app);
void register_batch_commands(CLI::App& app);
void register_wrinkles_commands(CLI::App& app);
/// `tapeline wrinkles buckling`, under the `wrinkles` family (defined in wrinkles_buckling.cpp).
void register_wrinkles_buckling(CLI::App& wrinkles);
/// `tapeline wrinkles refine`, `train` and `apply` (defined in wrinkles_synthesis.cpp).
void register_wrinkles_synthesis(CLI::App& wrinkles);

/// --projection (mls or plane) of gcf-points into `options`, its default shown from `options`.
void add_projection_option(CLI::App* cmd, geodesic::PointCloudDistanceOptions& options,
                           const std::string& help);
/// NAME in the pattern database `db` (default database when empty), or a pattern file in
/// `format` (empty: by extension) when NAME is an existing file (defined in pattern_commands.cpp).
pattern::Pattern load_pattern(const std::string& name_or_file, const std::string& db,
                              const std::string& format);
/// Whether path names a regular file (defined in pattern_commands.cpp).
bool is_file(const std::string& path);
}  // namespace tapeline::app
