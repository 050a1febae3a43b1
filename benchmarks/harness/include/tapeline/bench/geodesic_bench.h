// `tapeline bench geodesic`: time and accuracy of geodesic distance methods, one JSON line per
// (method, mesh, source, repetition), every run in a child process of its own (isolation.h).
#pragma once

#include <tapeline/bench/methods.h>

#include <cstdint>
#include <string>
#include <vector>

namespace tapeline::bench {

struct GeodesicBenchConfig {
    std::vector<std::string> meshes;    ///< mesh files
    std::vector<std::string> surfaces;  ///< analytic surface specs (exact smooth truth)
    std::string methods = "exact-mmp,exact-cgal,heat,heat-idt,dijkstra";  ///< comma-separated
    int sources = 1;                      ///< vertex 0, then seeded random ones
    int repeat = 1;                       ///< repetitions of each run
    std::string reference = "exact-mmp";  ///< errors are measured against it; "none": no errors
    std::string out;                      ///< JSON-lines output (OUT.partial while running)
    std::uint64_t seed = 1;               ///< sources, surface jitter and gcf-points noise
    double timeout = 0;                   ///< seconds before a run is killed (0: never)
    double memory_limit_gb = 0;           ///< address space of each run (0: no limit)
    int threads = 1;                      ///< TBB threads a method may use
    bool append = false;                  ///< append to `out` instead of replacing it
    MethodSettings settings;              ///< window, gcf-points options and noise
};

/// Runs the benchmark; every input is checked before the first measurement (InvalidInput). Lines
/// go to OUT.partial as they are measured and OUT appears when the run is complete. Progress
/// (runs done / total) goes through tapeline::Progress. Returns the number of lines written.
std::size_t run_geodesic_bench(const GeodesicBenchConfig& config);

}  // namespace tapeline::bench
