// `tapeline bench geodesic`: every (method, mesh, source, repetition) runs in a child process of
// its own, so that its peak memory is its own, a crash or a time-out is a status and not the end of
// the benchmark, and methods are measured side by side in one run (DESIGN.md §7).
#include "app_types.h"
#include "commands.h"
#include "output.h"

#include <tapeline/core/errors.h>
#include <tapeline/surfaces/analytic_geodesics.h>

#include <tapeline_build_info.h>

#include <CLI/CLI.hpp>
#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <iostream>
#include <memory>
#include <random>
#include <set>
#include <sstream>

#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace tapeline::app {
namespace {

struct BenchArgs {
    std::vector<std::string> meshes;
    std::vector<std::string> surfaces;
    std::string methods = "exact-mmp,exact-cgal,heat,heat-idt,dijkstra";
    int sources = 1;
    int repeat = 1;
    std::string reference = "exact-mmp";
    std::string out;
    std::uint64_t seed = 1;
    double timeout = 0;
    double memory_limit_gb = 0;
    std::size_t window = 8;
    int threads = 1;
    bool append = false;
    PointsMethodOptions points;  // gcf-points: --cell, --neighbours, --projection, --noise
};

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

/// Relative errors of `values` against `reference` over the vertices that count: reachable in the
/// reference, not a source and not adjacent to one (the 1-ring, where relative error is dominated
/// by the size of the first triangles and says little about a method). Vertices where exactly one
/// of the two is infinite are counted as mismatches and left out of the statistics.
struct ErrorStats {
    double mean = NAN;
    double max = NAN;
    std::size_t count = 0;
    std::size_t reachability_mismatches = 0;
};

ErrorStats relative_errors(const std::vector<double>& values, const std::vector<double>& reference,
                           const std::vector<char>& excluded) {
    ErrorStats s;
    double sum = 0, mx = 0;
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (excluded[i]) {
            continue;
        }
        const bool fin_v = std::isfinite(values[i]);
        const bool fin_r = std::isfinite(reference[i]);
        if (fin_v != fin_r) {
            ++s.reachability_mismatches;
            continue;
        }
        if (!fin_r || reference[i] <= 0) {
            continue;
        }
        const double e = std::abs(values[i] - reference[i]) / reference[i];
        sum += e;
        mx = std::max(mx, e);
        ++s.count;
    }
    if (s.count > 0) {
        s.mean = sum / static_cast<double>(s.count);
        s.max = mx;
    }
    return s;
}

nlohmann::json number_or_null(double x) {
    return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
}

std::string format_gb(double gb) {
    std::ostringstream out;
    out << gb;
    return out.str();
}

// ---- child process plumbing ------------------------------------------------------------------

bool write_all(int fd, const void* data, std::size_t n) {
    const char* p = static_cast<const char*>(data);
    while (n > 0) {
        const ssize_t w = ::write(fd, p, n);
        if (w < 0) {
            if (errno == EINTR) {
                continue;
            }
            return false;
        }
        p += w;
        n -= static_cast<std::size_t>(w);
    }
    return true;
}

struct ChildOutcome {
    std::string status;  // ok, invalid_input, solver_failed, timeout, crash
    std::string message;
    nlohmann::json fields;          // what the child measured
    std::vector<double> distances;  // only when asked for
    std::size_t peak_rss_bytes = 0;
};

/// Runs `work` in a forked child. `work` returns the JSON fields and, optionally, distances to
/// send back. The child's exceptions become statuses; a signal becomes `crash`.
template <class Work>
ChildOutcome run_isolated(Work&& work, double timeout_seconds, double memory_limit_gb) {
    int fds[2];
    if (::pipe(fds) != 0) {
        throw std::runtime_error("pipe() failed");
    }
    std::cout.flush();
    std::cerr.flush();
    const pid_t pid = ::fork();
    if (pid < 0) {
        throw std::runtime_error("fork() failed");
    }
    if (pid == 0) {
        ::close(fds[0]);
        if (memory_limit_gb > 0) {
            // An allocation beyond the limit becomes std::bad_alloc ("crash: out of memory")
            // instead of the machine's OOM killer picking a victim.
            const rlim_t bytes = static_cast<rlim_t>(memory_limit_gb * 1e9);
            const rlimit limit{bytes, bytes};
            ::setrlimit(RLIMIT_AS, &limit);
        }
        nlohmann::json fields;
        std::vector<double> distances;
        try {
            work(fields, distances);
            fields["status"] = "ok";
        } catch (const InvalidInput& e) {
            fields = {{"status", "invalid_input"}, {"message", e.what()}};
        } catch (const TopologyError& e) {
            fields = {{"status", "invalid_input"}, {"message", e.what()}};
        } catch (const SolverFailure& e) {
            fields = {{"status", "solver_failed"}, {"message", e.what()}};
        } catch (const std::bad_alloc&) {
            fields = {{"status", "crash"},
                      {"message", memory_limit_gb > 0 ? "out of memory (--memory-limit " +
                                                            format_gb(memory_limit_gb) + " GB)"
                                                      : std::string("out of memory")}};
        } catch (const std::exception& e) {
            fields = {{"status", "crash"}, {"message", std::string("exception: ") + e.what()}};
        }
        const std::string text = fields.dump();
        const std::uint64_t len = text.size(), n = distances.size();
        const bool ok = write_all(fds[1], &len, sizeof len) &&
                        write_all(fds[1], text.data(), len) && write_all(fds[1], &n, sizeof n) &&
                        write_all(fds[1], distances.data(), n * sizeof(double));
        ::close(fds[1]);
        ::_exit(ok ? 0 : 3);
    }
    ::close(fds[1]);
    std::string buffer;
    const auto start = std::chrono::steady_clock::now();
    bool timed_out = false;
    char chunk[1 << 16];
    for (;;) {
        int wait_ms = -1;
        if (timeout_seconds > 0) {
            const double left =
                timeout_seconds -
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            if (left <= 0) {
                timed_out = true;
                ::kill(pid, SIGKILL);
                break;
            }
            wait_ms = static_cast<int>(std::ceil(left * 1000));
        }
        pollfd p{fds[0], POLLIN, 0};
        const int r = ::poll(&p, 1, wait_ms);
        if (r < 0 && errno == EINTR) {
            continue;
        }
        if (r == 0) {
            continue;  // the deadline check above fires
        }
        const ssize_t got = ::read(fds[0], chunk, sizeof chunk);
        if (got < 0 && errno == EINTR) {
            continue;
        }
        if (got <= 0) {
            break;
        }
        buffer.append(chunk, static_cast<std::size_t>(got));
    }
    ::close(fds[0]);
    int wstatus = 0;
    rusage usage{};
    while (::wait4(pid, &wstatus, 0, &usage) < 0 && errno == EINTR) {
    }
    ChildOutcome outcome;
    outcome.peak_rss_bytes = static_cast<std::size_t>(usage.ru_maxrss) * 1024;  // Linux: KiB
    if (timed_out) {
        outcome.status = "timeout";
        outcome.message = "killed after " + std::to_string(timeout_seconds) + " s";
        return outcome;
    }
    if (WIFSIGNALED(wstatus)) {
        outcome.status = "crash";
        outcome.message = std::string("killed by signal ") + ::strsignal(WTERMSIG(wstatus));
        return outcome;
    }
    std::uint64_t len = 0, n = 0;
    if (buffer.size() < sizeof len) {
        outcome.status = "crash";
        outcome.message =
            "child exited with code " + std::to_string(WEXITSTATUS(wstatus)) + " without a result";
        return outcome;
    }
    std::memcpy(&len, buffer.data(), sizeof len);
    if (buffer.size() < sizeof len + len + sizeof n) {
        outcome.status = "crash";
        outcome.message = "truncated result from child";
        return outcome;
    }
    outcome.fields = nlohmann::json::parse(buffer.substr(sizeof len, len));
    std::memcpy(&n, buffer.data() + sizeof len + len, sizeof n);
    const std::size_t offset = sizeof len + len + sizeof n;
    if (buffer.size() != offset + n * sizeof(double)) {
        outcome.status = "crash";
        outcome.message = "truncated distances from child";
        return outcome;
    }
    outcome.distances.resize(n);
    std::memcpy(outcome.distances.data(), buffer.data() + offset, n * sizeof(double));
    outcome.status = outcome.fields.value("status", "crash");
    outcome.message = outcome.fields.value("message", "");
    return outcome;
}

// ---- the benchmark -----------------------------------------------------------------------------

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

void run_bench(const BenchArgs& args) {
    std::vector<std::string> methods = split_list(args.methods);
    if (methods.empty()) {
        throw InvalidInput("--methods: give at least one method");
    }
    auto check_method = [&args](const std::string& option, const std::string& m) {
        const auto& known = distance_methods();
        const std::string base = parse_method_name(m, args.window).base;
        if (std::find(known.begin(), known.end(), base) == known.end()) {
            std::string list;
            for (const std::string& k : known) {
                list += (list.empty() ? "" : ", ") + k;
            }
            throw InvalidInput(option + ": unknown method '" + m + "' (known: " + list + ")");
        }
    };
    for (const std::string& m : methods) {
        check_method("--methods", m);
    }
    const bool use_reference = args.reference != "none";
    if (use_reference) {
        check_method("--reference", args.reference);
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
        std::cerr
            << "[bench] " << input.name << ": " << nv << " vertices, loaded in "
            << std::chrono::duration<double>(std::chrono::steady_clock::now() - load_start).count()
            << " s" << (has_truth ? ", exact smooth truth: " + truth_fn->description() : "")
            << '\n';
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
                            PointsMethodOptions points = args.points;
                            points.seed = args.seed;
                            MethodResult r =
                                run_distance_method(method, mesh, sources, args.window, points);
                            fields["pre_seconds"] = r.report.pre_seconds;
                            fields["query_seconds"] = r.report.query_seconds;
                            fields["unreachable"] = r.report.unreachable;
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
                    nlohmann::json options = nlohmann::json::object();
                    if (method == "heat-idt") {
                        options["intrinsic_delaunay"] = true;
                    } else if (method == "heat") {
                        options["intrinsic_delaunay"] = false;
                    } else if (method.rfind("gcf-", 0) == 0) {
                        const MethodName parsed = parse_method_name(method, args.window);
                        if (parsed.base != "gcf-exact") {
                            options["window"] = parsed.window;
                            options["anchor"] =
                                parsed.base == "gcf-window-thesis" ? "prefix" : "field";
                        }
                        options["length"] = parsed.on_faces ? "faces" : "smooth";
                        if (parsed.on_faces) {
                            options["repair"] = parsed.repair;
                        }
                        if (parsed.base == "gcf-points") {
                            options.erase("anchor");
                            options.erase("length");
                            options["cell"] = args.points.cell;
                            options["neighbours"] = args.points.neighbours;
                            options["projection"] = args.points.projection;
                            options["noise"] = args.points.noise;
                        }
                    }
                    line["options"] = options;
                    for (const char* key :
                         {"pre_seconds", "query_seconds", "mean_rel_error", "max_rel_error",
                          "mean_rel_error_truth", "max_rel_error_truth", "unreachable"}) {
                        line[key] = outcome.fields.contains(key) ? outcome.fields[key]
                                                                 : nlohmann::json(nullptr);
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
                    std::cerr << "[bench " << done << "/" << total << "] " << input.name << " "
                              << method << " source " << source_index << " rep " << rep << ": "
                              << outcome.status;
                    if (outcome.status == "ok") {
                        std::cerr << ", query " << line["query_seconds"].dump() << " s";
                        if (!line["mean_rel_error"].is_null()) {
                            std::cerr << ", mean rel err " << line["mean_rel_error"].dump();
                        }
                    } else {
                        std::cerr << " (" << outcome.message << ")";
                    }
                    std::cerr << '\n';
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
    std::cout << "wrote " << done << " lines to " << args.out << '\n';
}

}  // namespace

void register_bench_commands(CLI::App& app) {
    CLI::App* bench = app.add_subcommand("bench", "Side-by-side benchmarks (JSON lines)");
    bench->require_subcommand(1);
    auto a = std::make_shared<BenchArgs>();
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
           "--window", a->window,
           "Samples flowed per vertex by gcf-window (a method 'gcf-window:W' sets its own)")
        ->capture_default_str();
    geo->add_option("--cell", a->points.cell,
                    "gcf-points: grid cell size (0: the median distance to the d-th neighbour)")
        ->capture_default_str();
    geo->add_option("--neighbours", a->points.neighbours,
                    "gcf-points: neighbours d of the local surfaces")
        ->capture_default_str();
    geo->add_option("--projection", a->points.projection, "gcf-points: mls or plane")
        ->check(CLI::IsMember({"mls", "plane"}))
        ->capture_default_str();
    geo->add_option("--noise", a->points.noise,
                    "gcf-points: Gaussian noise added to the mesh's vertices, sigma as a fraction "
                    "of the bounding-box diagonal (seeded by --seed); errors stay against the "
                    "clean vertices")
        ->capture_default_str()
        ->check(CLI::NonNegativeNumber);
    geo->add_flag("--append", a->append, "Append to --out instead of replacing it");
    geo->add_option("--out,-o", a->out, "JSON-lines output")->required();
    geo->callback([a] { run_bench(*a); });
}

}  // namespace tapeline::app
