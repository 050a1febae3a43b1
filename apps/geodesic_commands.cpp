// `tapeline geodesic distances` and `tapeline geodesic path`.
#include "app_types.h"
#include "commands.h"
#include "output.h"
#include "path_unfold.h"

#include <tapeline/core/atomic_write.h>
#include <tapeline/core/errors.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>

namespace tapeline::app {

// Defined in geodesic_path.cpp and method_exact_mmp.cpp (the heavy path machinery stays out of
// this translation unit).
nlohmann::json exact_cgal_path_json(const Mesh& mesh, Vertex from, Vertex to);
nlohmann::json exact_mmp_path_json(const Mesh& mesh, Vertex from, Vertex to);
nlohmann::json gcf_path_json(const Mesh& mesh, Vertex from, Vertex to);

namespace {

struct MeshArgs {
    std::string mesh;
    std::string surface;
    bool strict = false;
};

void add_mesh_args(CLI::App* cmd, MeshArgs& args) {
    auto* file = cmd->add_option("mesh", args.mesh, "Triangle mesh (.off, .obj, .ply, .stl)");
    auto* surface = cmd->add_option("--surface", args.surface,
                                    "Analytic surface spec instead of a file, e.g. icosphere:4");
    file->excludes(surface);
    surface->excludes(file);
    cmd->add_flag("--strict", args.strict,
                  "Reject polygons, duplicates and non-manifold elements instead of repairing");
}

InputMesh load(const MeshArgs& args) {
    if (args.mesh.empty() && args.surface.empty()) {
        throw InvalidInput("give a mesh file or --surface SPEC");
    }
    return args.surface.empty() ? load_input_mesh_file(args.mesh, args.strict)
                                : make_input_surface(args.surface);
}

// "F:b0,b1,b2" -> a face location on `mesh`.
CGAL::Polygon_mesh_processing::Face_location<Mesh, double> parse_face_point(const std::string& text,
                                                                            const Mesh& mesh) {
    const std::string what = "--source-point '" + text + "'";
    const auto colon = text.find(':');
    if (colon == std::string::npos) {
        throw InvalidInput(what + ": expected FACE:B0,B1,B2 (face index, barycentric coordinates)");
    }
    std::size_t face = 0;
    std::array<double, 3> bary{};
    try {
        std::size_t used = 0;
        face = std::stoul(text.substr(0, colon), &used);
        if (used != colon) {
            throw std::invalid_argument("face");
        }
        std::stringstream rest(text.substr(colon + 1));
        char c1 = 0, c2 = 0;
        if (!(rest >> bary[0] >> c1 >> bary[1] >> c2 >> bary[2]) || c1 != ',' || c2 != ',' ||
            !(rest >> std::ws).eof()) {
            throw std::invalid_argument("bary");
        }
    } catch (const std::exception&) {
        throw InvalidInput(what + ": expected FACE:B0,B1,B2 (face index, barycentric coordinates)");
    }
    if (face >= num_faces(mesh)) {
        throw InvalidInput(what + ": face " + std::to_string(face) +
                           " does not exist (the mesh has " + std::to_string(num_faces(mesh)) +
                           " faces)");
    }
    const double sum = bary[0] + bary[1] + bary[2];
    if (!std::isfinite(sum) || std::abs(sum - 1.0) > 1e-6 ||
        *std::min_element(bary.begin(), bary.end()) < -1e-12) {
        throw InvalidInput(what + ": barycentric coordinates must be >= 0 and sum to 1");
    }
    return {Mesh::Face_index(static_cast<Mesh::size_type>(face)), bary};
}

std::vector<Vertex> vertices_of(const InputMesh& input, long id, const std::string& option) {
    if (id < 0) {
        throw InvalidInput(option + " " + std::to_string(id) + ": vertex ids start at 0");
    }
    std::vector<Vertex> result = input.loaded.mesh_vertices_of(static_cast<std::size_t>(id));
    if (result.empty()) {
        throw InvalidInput(option + " " + std::to_string(id) + ": vertex " + std::to_string(id) +
                           " of " + input.name + " is not used by any face");
    }
    return result;
}

struct DistancesArgs {
    MeshArgs mesh;
    std::vector<long> sources;
    std::vector<std::string> source_points;
    std::string method = "exact-mmp";
    std::string out;
    bool point_cloud = false;
    MethodSettings settings;  // --window, --cell, --neighbours, --projection
};

// --point-cloud: the positional input is a point set (.xyz, .csv, .ply); gcf-points from one
// point; one distance per point, in file order.
void run_point_cloud_distances(const DistancesArgs& args, bool method_given) {
    if (args.mesh.mesh.empty()) {
        throw InvalidInput("--point-cloud needs a points file (.xyz, .csv or .ply)");
    }
    if (method_given && parse_method_name(args.method, args.settings.window).base != "gcf-points") {
        throw InvalidInput("--point-cloud: method '" + args.method +
                           "' needs a mesh; point clouds take gcf-points");
    }
    if (args.sources.size() != 1 || !args.source_points.empty()) {
        throw InvalidInput("--point-cloud takes exactly one --source I (a point index)");
    }
    if (args.sources.front() < 0) {
        throw InvalidInput("--source " + std::to_string(args.sources.front()) +
                           ": point indices start at 0");
    }
    if (extension_of(args.out) != ".txt") {
        throw InvalidInput(args.out +
                           ": a point cloud's distances are written as .txt (one per "
                           "point per line)");
    }
    geodesic::PointCloudDistanceOptions options = args.settings.points;
    options.window = parse_method_name(args.method, args.settings.window).window;
    const bench::PointCloudRun run = bench::run_point_cloud_file(
        args.mesh.mesh, static_cast<std::size_t>(args.sources.front()), options);
    write_file_atomically(args.out, [&](std::ostream& out) {
        out.precision(17);
        for (double d : run.distances) {
            write_distance(out, d);
            out << '\n';
        }
    });
    const auto& r = run.report;
    std::cout << "wrote " << args.out << ": gcf-points on " << args.mesh.mesh << " (" << r.points
              << " points in R^" << r.dimension << ", k " << r.manifold_dimension << ", cell "
              << r.cell_size << ", " << r.nodes << " nodes), prepare " << r.prepare_seconds
              << " s, total " << r.seconds << " s, unreachable " << r.unreachable << ", "
              << r.status << '\n';
}

void run_distances(const DistancesArgs& args) {
    InputMesh input = load(args.mesh);
    for (const std::string& w : input.loaded.report.warnings) {
        std::cerr << "tapeline: warning: " << w << '\n';
    }
    Sources sources;
    for (long id : args.sources) {
        for (Vertex v : vertices_of(input, id, "--source")) {
            sources.vertices.push_back(v);
        }
    }
    for (const std::string& p : args.source_points) {
        sources.locations.push_back(parse_face_point(p, input.loaded.mesh));
    }
    if (sources.vertices.empty() && sources.locations.empty()) {
        throw InvalidInput("give at least one --source V or --source-point F:B0,B1,B2");
    }
    MethodResult result =
        run_distance_method(args.method, input.loaded.mesh, sources, args.settings);
    const std::vector<double> in_order = input.loaded.to_input_order(result.distances);
    write_distances(args.out, input.loaded.mesh, result.distances, in_order);
    double max_d = 0;
    for (double d : result.distances) {
        if (std::isfinite(d)) {
            max_d = std::max(max_d, d);
        }
    }
    std::cout << "wrote " << args.out << ": " << args.method << " on " << input.name << " ("
              << num_vertices(input.loaded.mesh) << " vertices), pre "
              << result.report.prepare_seconds << " s, query " << result.report.query_seconds
              << " s, max distance " << max_d << ", unreachable " << result.report.unreachable
              << '\n';
}

struct MatrixArgs {
    MeshArgs mesh;
    std::vector<long> sources;
    unsigned threads = 0;
    std::string out;
};

// Exact distances from each source to every vertex: one row per source, in the order given.
void run_matrix(const MatrixArgs& args) {
    if (extension_of(args.out) != ".txt") {
        throw InvalidInput(args.out + ": the matrix is written as .txt (one row per source)");
    }
    InputMesh input = load(args.mesh);
    for (const std::string& w : input.loaded.report.warnings) {
        std::cerr << "tapeline: warning: " << w << '\n';
    }
    std::vector<Vertex> sources;
    for (long id : args.sources) {
        const std::vector<Vertex> copies = vertices_of(input, id, "--source");
        if (copies.size() != 1) {
            throw InvalidInput("--source " + std::to_string(id) + ": vertex " + std::to_string(id) +
                               " of " + input.name + " stands for " +
                               std::to_string(copies.size()) +
                               " mesh vertices (split where the mesh is not manifold); a row "
                               "needs one source: give another vertex");
        }
        sources.push_back(copies.front());
    }
    const auto t0 = std::chrono::steady_clock::now();
    const std::vector<std::vector<double>> rows =
        bench::exact_mmp_matrix(input.loaded.mesh, sources, args.threads);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    write_file_atomically(args.out, [&](std::ostream& out) {
        out.precision(17);
        for (const auto& row : rows) {
            const std::vector<double> in_order = input.loaded.to_input_order(row);
            for (std::size_t i = 0; i < in_order.size(); ++i) {
                out << (i ? " " : "");
                write_distance(out, in_order[i]);
            }
            out << '\n';
        }
    });
    std::cout << "wrote " << args.out << ": exact-mmp distance matrix, " << rows.size()
              << " sources x " << input.loaded.to_input_order(rows.front()).size()
              << " vertices of " << input.name << ", " << args.threads << " threads"
              << (args.threads == 0 ? " (every hardware thread)" : "") << ", " << seconds << " s\n";
}

struct PathArgs {
    MeshArgs mesh;
    long from = -1;
    long to = -1;
    std::string method = "exact-mmp";
    std::string out;
    std::string svg;
};

void run_path(const PathArgs& args) {
    OutputFiles outputs({args.out, args.svg});  // both checked before any work
    InputMesh input = load(args.mesh);
    const Vertex from = vertices_of(input, args.from, "--from").front();
    const Vertex to = vertices_of(input, args.to, "--to").front();
    const auto start = std::chrono::steady_clock::now();
    nlohmann::json j = args.method == "exact-mmp" ? exact_mmp_path_json(input.loaded.mesh, from, to)
                       : args.method == "exact-cgal"
                           ? exact_cgal_path_json(input.loaded.mesh, from, to)
                           : gcf_path_json(input.loaded.mesh, from, to);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    j["method"] = args.method;
    j["mesh"] = input.name;
    j["from"] = args.from;
    j["to"] = args.to;
    j["seconds"] = seconds;
    std::string svg;
    if (!args.svg.empty()) {
        UnfoldOutput u = unfold_path_output(
            input.loaded.mesh, j["points"],
            "tapeline geodesic path --method " + args.method + " " + input.name + " --from " +
                std::to_string(args.from) + " --to " + std::to_string(args.to));
        j["unfold"] = std::move(u.summary);
        svg = std::move(u.svg);
    }
    // Both to temporary names, renamed together: a failure leaves neither.
    if (!args.svg.empty()) {
        outputs.write(args.svg, [&](std::ostream& out) { out << svg; });
    }
    outputs.write(args.out, [&](std::ostream& out) { out << j.dump(2) << '\n'; });
    outputs.commit();
    std::cout << "wrote " << args.out << ": " << args.method << " path of length "
              << j["length"].dump() << " with " << j["points"].size() << " points\n";
    if (!args.svg.empty()) {
        std::cout << "wrote " << args.svg << ": " << j["unfold"]["faces"].dump()
                  << " unfolded faces, traced length " << j["unfold"]["traced_length"].dump()
                  << ", unfolded straight length " << j["unfold"]["straight_length"].dump() << '\n';
    }
}

}  // namespace

void add_projection_option(CLI::App* cmd, geodesic::PointCloudDistanceOptions& options,
                           const std::string& help) {
    cmd->add_option_function<std::string>(
           "--projection",
           [&options](const std::string& text) {
               options.projection = bench::parse_projection(text, "--projection");
           },
           help)
        ->check(CLI::IsMember({"mls", "plane"}))
        ->default_str(geodesic::to_string(options.projection));
}
/// CLI11 reads an empty number as 0; `--source ""` must not mean vertex 0.
const CLI::Validator not_empty(
    [](std::string& value) { return value.empty() ? std::string("empty value") : std::string(); },
    "");

void register_geodesic_commands(CLI::App& app) {
    CLI::App* geo = app.add_subcommand("geodesic", "Geodesic distances and paths on a mesh");
    geo->require_subcommand(1);

    auto d = std::make_shared<DistancesArgs>();
    CLI::App* dist = geo->add_subcommand(
        "distances", "Geodesic distance from one or more sources to every vertex");
    add_mesh_args(dist, d->mesh);
    dist->add_option("--source", d->sources, "Source vertex (index in the input file; repeatable)")
        ->check(not_empty);
    dist->add_option(
        "--source-point", d->source_points,
        "Source point FACE:B0,B1,B2 in a face of the loaded triangle mesh (repeatable)");
    dist->add_option("--method", d->method,
                     "Method (default exact-mmp); a gcf-* method with '/faces' reports the length "
                     "of its samples on the faces instead of the Phong-lifted one, and re-solves "
                     "the vertices its neighbours contradict as two-point paths ('/faces/raw': "
                     "without that repair)")
        ->check(CLI::Validator(
            [](std::string& m) {
                const std::string base = parse_method_name(m).base;
                const auto& known = distance_methods();
                return std::find(known.begin(), known.end(), base) == known.end()
                           ? "unknown method '" + m + "'"
                           : std::string();
            },
            "METHOD"));
    dist->add_option("--window", d->settings.window, "Samples flowed per vertex by gcf-window")
        ->check(CLI::Range(1, 4096))
        ->capture_default_str();
    dist->add_option("--out,-o", d->out,
                     "Output: .txt (one distance per input vertex per line, inf if unreachable) "
                     "or .ply (mesh coloured by distance)")
        ->required();
    dist->add_flag("--point-cloud", d->point_cloud,
                   "The input is a point set (.xyz, .csv: any dimension; .ply): distances by "
                   "gcf-points (curvature flow over a grid of cells, the thesis' Algorithm 3)");
    dist->add_option("--cell", d->settings.points.cell_size,
                     "gcf-points: grid cell size (0: the median distance to the d-th neighbour)")
        ->check(not_empty)
        ->capture_default_str();
    dist->add_option("--neighbours", d->settings.points.neighbours,
                     "gcf-points: neighbours d of the local surfaces (PCA, MLS)")
        ->check(CLI::Range(1, 10000))
        ->capture_default_str();
    add_projection_option(dist, d->settings.points,
                          "gcf-points: local surface, mls (quadric) or plane");
    auto* method_option = dist->get_option("--method");
    dist->callback([d, method_option] {
        if (d->point_cloud) {
            run_point_cloud_distances(*d, method_option->count() > 0);
        } else {
            run_distances(*d);
        }
    });

    auto mx = std::make_shared<MatrixArgs>();
    CLI::App* matrix = geo->add_subcommand(
        "matrix",
        "Exact distances (exact-mmp) from each source to every vertex: one row per source, "
        "rows computed in parallel");
    add_mesh_args(matrix, mx->mesh);
    matrix
        ->add_option("--source", mx->sources,
                     "Source vertex (index in the input file; one row "
                     "each, in the order given; repeatable)")
        ->required()
        ->check(not_empty);
    matrix->add_option("--threads", mx->threads, "Threads for the rows (0: every hardware thread)")
        ->check(CLI::Range(0, 1024))
        ->capture_default_str();
    matrix
        ->add_option("--out,-o", mx->out,
                     "Output .txt: one row per source, one distance per input vertex, "
                     "space-separated, inf if unreachable")
        ->required();
    matrix->callback([mx] { run_matrix(*mx); });

    auto p = std::make_shared<PathArgs>();
    CLI::App* path = geo->add_subcommand(
        "path",
        "Geodesic path between two vertices: exact polyhedral (exact-mmp, exact-cgal) or by "
        "geodesic curvature flow (gcf: also the smooth polyline and the flow's report)");
    add_mesh_args(path, p->mesh);
    path->add_option("--from", p->from, "Start vertex (index in the input file)")
        ->required()
        ->check(not_empty);
    path->add_option("--to", p->to, "End vertex (index in the input file)")
        ->required()
        ->check(not_empty);
    path->add_option("--method", p->method, "Method (default exact-mmp)")
        ->check(CLI::IsMember({"exact-mmp", "exact-cgal", "gcf"}));
    path->add_option("--out,-o", p->out, "Output JSON: points and length")->required();
    path->add_option("--svg", p->svg,
                     "Also draw the faces crossed by the path unfolded into the plane (SVG), "
                     "with the straight segment between the unfolded end points; adds 'unfold' "
                     "(traced vs straight length) to the JSON");
    path->callback([p] { run_path(*p); });
}

}  // namespace tapeline::app
