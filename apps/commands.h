// Registration of the tool's subcommand families (each defined in its own translation unit).
#pragma once

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
}  // namespace tapeline::app
