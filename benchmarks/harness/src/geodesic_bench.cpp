// The geodesic benchmark: every (method, mesh, source, repetition) runs in a child process of its
// own, so that its peak memory is its own, a crash or a time-out is a status and not the end of
// the benchmark, and methods are measured side by side in one run (DESIGN.md §7).
#include <tapeline/bench/geodesic_bench.h>

#include <tapeline/bench/error_stats.h>
#include <tapeline/bench/isolation.h>
#include <tapeline/bench/surfaces.h>
#include <tapeline/core/errors.h>
#include <tapeline/core/progress.h>

#include <tapeline_build_info.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <iostream>
#include <memory>
#include <random>
#include <set>
#include <sstream>

namespace tapeline::bench {

namespace {

std::vector<std::string> split_list(const std::string& text) {
    std::vector<std::string> out;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ',')) {
        if (!item.empty()) {
            out.push_back(item);
        }
    }
    return out;
}

std::string utc_now() {
    char buf[32];
    const std::time_t t = std::time(nullptr);
    std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
    return buf;
}

double mean_edge_length(const Mesh& mesh) {
    double sum = 0;
    std::size_t n = 0;
    for (auto e : edges(mesh)) {
        sum += std::sqrt(
            CGAL::squared_distance(mesh.point(source(e, mesh)), mesh.point(target(e, mesh))));
        ++n;
    }
    return n ? sum / static_cast<double>(n) : 0.0;
}

/// `count` distinct vertices drawn with a seeded generator; vertex 0 first so that a one-source
/// run is reproducible by hand (`--source 0`).
std::vector<std::size_t> pick_sources(std::size_t n_vertices, int count, std::uint64_t seed) {
    std::vector<std::size_t> picked;
    if (n_vertices == 0) {
        return picked;
    }
    picked.push_back(0);
    std::set<std::size_t> seen{0};
    std::mt19937_64 rng(seed);
    const std::size_t want = std::min<std::size_t>(static_cast<std::size_t>(count), n_vertices);
    while (picked.size() < want) {
        const std::size_t v = static_cast<std::size_t>(rng() % n_vertices);
        if (seen.insert(v).second) {
            picked.push_back(v);
        }
    }
    return picked;
}

}  // namespace

std::size_t run_geodesic_bench(const GeodesicBenchConfig& args) {
    std::vector<std::string> methods = split_list(args.methods);
    if (methods.empty()) {
        throw InvalidInput("--methods: give at least one method");
    }
    for (const std::string& m : methods) {
        check_method_name("--methods", m);
    }
    MethodSettings settings = args.settings;
    settings.seed = args.seed;
    const bool use_reference = args.reference != "none";
    if (use_reference) {
        check_method_name("--reference", args.reference);
        // The reference runs first on each source so that the others can be compared with it.
        methods.erase(std::remove(methods.begin(), methods.end(), args.reference), methods.end());
        methods.insert(methods.begin(), args.reference);
    }
    if (args.sources < 1 || args.repeat < 1) {
        throw InvalidInput("--sources and --repeat must be at least 1");
    }
    if (args.meshes.empty() && args.surfaces.empty()) {
        throw InvalidInput("give at least one --mesh FILE or --surface SPEC");
    }
    // Validate every input before the first measurement: a typo should not cost an hour.
    for (const std::string& s : args.surfaces) {
        SurfaceSpec::parse(s);
    }
    for (const std::string& m : args.meshes) {
        std::ifstream probe(m);
        if (!probe) {
            throw InvalidInput(m + ": cannot open file");
        }
    }

    // Lines go to OUT.partial as they are measured (a long run that is killed keeps what it
    // measured, under a name that says so); OUT appears only when the run is complete.
    const std::string partial = args.out + ".partial";
    {
        std::ofstream fresh(partial, std::ios::trunc);
        std::ifstream previous(args.out);
        if (args.append && previous) {
            fresh << previous.rdbuf();
        }
        if (!fresh) {
            throw InvalidInput(partial + ": cannot open for writing");
        }
    }
    std::ofstream out(partial, std::ios::app);
    if (!out) {
        throw InvalidInput(partial + ": cannot open for writing");
    }
    struct Item {
        bool is_surface;
        std::string text;
    };
    std::vector<Item> items;
    for (const std::string& s : args.surfaces) {
        items.push_back({true, s});
    }
    for (const std::string& m : args.meshes) {
        items.push_back({false, m});
    }
    const std::size_t total = items.size() * static_cast<std::size_t>(args.sources) *
                              methods.size() * static_cast<std::size_t>(args.repeat);
    std::size_t done = 0;
    // Every run is a process of its own and lasts a while: no delay before the first line.
    Progress progress("bench geodesic", total, 0.0);
    for (const Item& item : items) {
        const auto load_start = std::chrono::steady_clock::now();
        InputMesh input = item.is_surface ? make_input_surface(item.text, args.seed)
                                          : load_input_mesh_file(item.text, false);
        const Mesh& mesh = input.loaded.mesh;
        const std::size_t nv = num_vertices(mesh);
        const double h = mean_edge_length(mesh);
        std::unique_ptr<AnalyticGeodesicDistance> truth_fn;
        if (input.spec) {
            truth_fn = std::make_unique<AnalyticGeodesicDistance>(*input.spec);
        }
        const bool has_truth = truth_fn && truth_fn->available();
        const std::vector<std::array<double, 3>> points = mesh_points(mesh);
        {
            std::ostringstream note;
            note << input.name << ": " << nv << " vertices, loaded in "
                 << std::chrono::duration<double>(std::chrono::steady_clock::now() - load_start)
                        .count()
                 << " s" << (has_truth ? ", exact smooth truth: " + truth_fn->description() : "");
            progress.note(note.str());
        }
        for (std::size_t source_index : pick_sources(nv, args.sources, args.seed)) {
            const Vertex src(static_cast<Mesh::size_type>(source_index));
            std::vector<char> excluded(nv, 0);
            excluded[source_index] = 1;
            for (Vertex w : vertices_around_target(halfedge(src, mesh), mesh)) {
                excluded[static_cast<std::size_t>(w)] = 1;
            }
            std::vector<double> truth;
            if (has_truth) {
                truth = analytic_distances(*input.spec, points, source_index);
            }
            std::vector<double> reference;
            for (const std::string& method : methods) {
                for (int rep = 0; rep < args.repeat; ++rep) {
                    const bool want_reference =
                        use_reference && method == args.reference && reference.empty();
                    const std::size_t base_rss = current_rss_bytes();
                    ChildOutcome outcome = run_isolated(
                        [&](nlohmann::json& fields, std::vector<double>& distances_out) {
#ifdef CGAL_LINKED_WITH_TBB
                            // Per run, in the child: methods with TBB loops use at most this many.
                            const tbb::global_control threads(
                                tbb::global_control::max_allowed_parallelism,
                                static_cast<std::size_t>(args.threads));
#endif
                            Sources sources;
                            sources.vertices.push_back(src);
                            MethodResult r = run_distance_method(method, mesh, sources, settings);
                            fields["pre_seconds"] = r.report.prepare_seconds;
                            fields["query_seconds"] = r.report.query_seconds;
                            fields["unreachable"] = r.report.unreachable;
                            fields["method_extra"] = r.extra;
                            if (!reference.empty()) {
                                const ErrorStats e =
                                    relative_errors(r.distances, reference, excluded);
                                fields["mean_rel_error"] = number_or_null(e.mean);
                                fields["max_rel_error"] = number_or_null(e.max);
                                fields["reachability_mismatches"] = e.reachability_mismatches;
                            }
                            if (!truth.empty()) {
                                const ErrorStats e = relative_errors(r.distances, truth, excluded);
                                fields["mean_rel_error_truth"] = number_or_null(e.mean);
                                fields["max_rel_error_truth"] = number_or_null(e.max);
                            }
                            if (want_reference) {
                                distances_out = std::move(r.distances);
                            }
                        },
                        args.timeout, args.memory_limit_gb);
                    if (want_reference && outcome.status == "ok") {
                        reference = std::move(outcome.distances);
                        const ErrorStats self = relative_errors(reference, reference, excluded);
                        outcome.fields["mean_rel_error"] = number_or_null(self.mean);
                        outcome.fields["max_rel_error"] = number_or_null(self.max);
                    }
                    nlohmann::json line;
                    line["method"] = method;
                    line["mesh"] = input.name;
                    line["family"] = input.family;
                    line["mesh_file"] =
                        input.file.empty() ? nlohmann::json(nullptr) : nlohmann::json(input.file);
                    line["vertices"] = nv;
                    line["faces"] = num_faces(mesh);
                    line["mean_edge_length"] = h;
                    line["source"] = input.loaded.input_index[source_index];
                    line["repetition"] = rep;
                    line["options"] = method_options_json(method, settings);
                    for (const char* key :
                         {"pre_seconds", "query_seconds", "mean_rel_error", "max_rel_error",
                          "mean_rel_error_truth", "max_rel_error_truth", "unreachable"}) {
                        line[key] = outcome.fields.contains(key) ? outcome.fields[key]
                                                                 : nlohmann::json(nullptr);
                    }
                    if (outcome.fields.contains("method_extra")) {  // the method's own figures
                        for (const auto& [key, value] : outcome.fields["method_extra"].items()) {
                            line[key] = value;
                        }
                    }
                    line["peak_rss_bytes"] = outcome.peak_rss_bytes;
                    line["base_rss_bytes"] = base_rss;
                    line["reference"] =
                        use_reference ? nlohmann::json(args.reference) : nlohmann::json(nullptr);
                    line["truth"] = has_truth ? nlohmann::json(truth_fn->description())
                                              : nlohmann::json(nullptr);
                    line["status"] = outcome.status;
                    line["message"] = outcome.message;
                    line["git"] = TAPELINE_GIT_REVISION;
                    line["compiler_flags"] = TAPELINE_COMPILER_FLAGS;
                    line["threads"] = args.threads;
                    line["timestamp"] = utc_now();
                    out << line.dump() << '\n';
                    out.flush();
                    ++done;
                    std::ostringstream note;
                    note << input.name << " " << method << " source " << source_index << " rep "
                         << rep << ": " << outcome.status;
                    if (outcome.status == "ok") {
                        note << ", query " << line["query_seconds"].dump() << " s";
                        if (!line["mean_rel_error"].is_null()) {
                            note << ", mean rel err " << line["mean_rel_error"].dump();
                        }
                    } else {
                        note << " (" << outcome.message << ")";
                    }
                    progress.note(note.str());
                    progress.advance();
                }
            }
        }
    }
    out.close();
    if (!out) {
        throw InvalidInput(partial + ": write failed");
    }
    if (std::rename(partial.c_str(), args.out.c_str()) != 0) {
        throw InvalidInput(args.out + ": cannot rename " + partial + " into place");
    }
    return done;
}

}  // namespace tapeline::bench
