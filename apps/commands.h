// Registration of the tool's subcommand families (each defined in its own translation unit).
#pragma once

#include <cstddef>
#include <cstdint>
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
namespace tapeline::sizes {
struct MeasurementSet;
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

/// --projection (mls or plane) of gcf-points into `options`, its default shown from `options`.
void add_projection_option(CLI::App* cmd, geodesic::PointCloudDistanceOptions& options,
                           const std::string& help);
/// NAME in the pattern database `db` (default database when empty), or a pattern file in
/// `format` (empty: by extension) when NAME is an existing file (defined in pattern_commands.cpp).
pattern::Pattern load_pattern(const std::string& name_or_file, const std::string& db,
                              const std::string& format);
/// `base` graded from `from` to `to` as `tapeline grade` does with its default options (FreeSewing
/// bindings and seams included), notes on stderr (defined in grade_commands.cpp). InvalidInput
/// when the tool was built without grading.
pattern::Pattern grade_for_body(const pattern::Pattern& base, const sizes::MeasurementSet& from,
                                const sizes::MeasurementSet& to, std::uint32_t seed,
                                std::size_t threads);
/// Whether path names a regular file (defined in pattern_commands.cpp).
bool is_file(const std::string& path);
}  // namespace tapeline::app
