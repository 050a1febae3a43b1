// `tapeline bench geodesic`: the command line of the geodesic benchmark harness
// (<tapeline/bench/geodesic_bench.h>).
#include "app_types.h"
#include "commands.h"

#include <tapeline/bench/geodesic_bench.h>

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>

namespace tapeline::app {

void register_bench_commands(CLI::App& app) {
    CLI::App* bench = app.add_subcommand("bench", "Side-by-side benchmarks (JSON lines)");
    bench->require_subcommand(1);
    auto a = std::make_shared<bench::GeodesicBenchConfig>();
    CLI::App* geo = bench->add_subcommand(
        "geodesic",
        "Time and accuracy of geodesic distance methods, one JSON line per (method, mesh, source, "
        "repetition); each run in its own process (peak memory, crash and time-out isolation)");
    geo->add_option("--mesh", a->meshes, "Mesh file (repeatable)");
    geo->add_option("--surface", a->surfaces,
                    "Analytic surface spec (repeatable): icosphere:L, uvsphere:NLAT,NLON, "
                    "ellipsoid:A,B,C:L[:J], torus:R,r:NU,NV[:J], cylinder:R,H:NU,NV[:J]");
    geo->add_option("--methods", a->methods, "Comma-separated methods")->capture_default_str();
    geo->add_option("--sources", a->sources,
                    "Number of source vertices per mesh (vertex 0, then "
                    "seeded random ones)")
        ->capture_default_str();
    geo->add_option("--repeat", a->repeat, "Repetitions of each run")->capture_default_str();
    geo->add_option("--reference", a->reference,
                    "Method the errors are measured against ('none': no reference errors, for "
                    "meshes too large for an exact method)")
        ->capture_default_str();
    geo->add_option("--seed", a->seed, "Seed for sources and surface jitter")
        ->capture_default_str();
    geo->add_option("--threads", a->threads,
                    "Threads a method may use (TBB loops: gcf-window, gcf-exact); 1 compares "
                    "single-threaded methods like for like")
        ->capture_default_str()
        ->check(CLI::Range(1, 256));
    geo->add_option("--timeout", a->timeout, "Seconds before a run is killed (0: none)")
        ->capture_default_str();
    geo->add_option("--memory-limit", a->memory_limit_gb,
                    "Address-space limit of each run in GB (0: none); a run beyond it is a crash "
                    "with the message 'out of memory'")
        ->capture_default_str();
    geo->add_option(
           "--window", a->settings.window,
           "Samples flowed per vertex by gcf-window (a method 'gcf-window:W' sets its own)")
        ->check(CLI::Range(1, 4096))
        ->capture_default_str();
    geo->add_option("--cell", a->settings.points.cell_size,
                    "gcf-points: grid cell size (0: the median distance to the d-th neighbour)")
        ->capture_default_str();
    geo->add_option("--neighbours", a->settings.points.neighbours,
                    "gcf-points: neighbours d of the local surfaces")
        ->check(CLI::Range(1, 10000))
        ->capture_default_str();
    add_projection_option(geo, a->settings.points, "gcf-points: mls or plane");
    geo->add_option("--noise", a->settings.noise,
                    "gcf-points: Gaussian noise added to the mesh's vertices, sigma as a fraction "
                    "of the bounding-box diagonal (seeded by --seed); errors stay against the "
                    "clean vertices")
        ->capture_default_str()
        ->check(CLI::NonNegativeNumber);
    geo->add_flag("--append", a->append, "Append to --out instead of replacing it");
    geo->add_option("--out,-o", a->out, "JSON-lines output")->required();
    geo->callback([a] {
        const std::size_t lines = bench::run_geodesic_bench(*a);
        std::cout << "wrote " << lines << " lines to " << a->out << '\n';
    });
}

}  // namespace tapeline::app
