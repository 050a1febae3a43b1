// `tapeline mesh generate`, `check`, `remesh` and `simplify`.
#include "app_types.h"
#include "commands.h"
#include "output.h"

#include <tapeline/core/atomic_write.h>
#include <tapeline/core/errors.h>
#include <tapeline/core/mesh_io.h>
#include <tapeline/core/mesh_writers.h>
#include <tapeline/core/remesh.h>
#include <tapeline/measurement/synthetic_body.h>
#include <tapeline/surfaces/analytic_geodesics.h>
#include <tapeline/surfaces/analytic_surface_types.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <array>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace tapeline::app {
namespace {

struct GenerateArgs {
    std::string spec;
    std::string out;
    std::uint64_t seed = 1;
    long truth_source = -1;
    std::string truth_out;
};

/// Parses `body[:AROUND,RING_MM[,ARM_DEGREES]]` with the surface specs' field parsers
/// (surfaces/analytic_surface_types.h); nullopt when the spec is not a body's.
std::optional<measurement::SyntheticBodyOptions> body_spec(const std::string& spec) {
    if (spec != "body" && spec.rfind("body:", 0) != 0) {
        return std::nullopt;
    }
    measurement::SyntheticBodyOptions o;
    if (spec == "body") {
        return o;
    }
    const std::vector<std::string> f = internal::split(spec.substr(5), ',');
    if (f.size() < 2 || f.size() > 3) {
        internal::spec_error(spec, "expected body:AROUND,RING_MM[,ARM_DEGREES]");
    }
    o.around = internal::parse_int_in(spec, f[0], "AROUND", 8, 1024);
    o.ring_step = internal::parse_double(spec, f[1], "RING_MM");
    if (o.ring_step < 1 || o.ring_step > 100) {
        internal::spec_error(spec, "RING_MM must be in 1..100");
    }
    if (f.size() == 3) {
        o.arm_angle_degrees = internal::parse_double(spec, f[2], "ARM_DEGREES");
        if (o.arm_angle_degrees < 20 || o.arm_angle_degrees > 90) {
            internal::spec_error(spec, "ARM_DEGREES must be in 20..90");
        }
    }
    return o;
}

/// `mesh generate body...`: the synthetic body of measurement/synthetic_body.h in millimetres
/// (+Y up, +Z front) and, with --truth-out, its exact girths as JSON.
void run_generate_body(const GenerateArgs& args, const measurement::SyntheticBodyOptions& o) {
    if (args.truth_source >= 0) {
        throw InvalidInput(
            "--truth-source: the synthetic body's truth is its girths "
            "(--truth-out FILE.json), not a distance field");
    }
    check_mesh_output(args.out);
    if (!args.truth_out.empty() && extension_of(args.truth_out) != ".json") {
        throw InvalidInput("--truth-out " + args.truth_out +
                           ": the synthetic body's truth is written as .json");
    }
    OutputFiles outputs({args.out, args.truth_out});
    const measurement::SyntheticBody body(o);
    std::vector<std::array<double, 3>> points(body.points().begin(), body.points().end());
    std::vector<std::vector<std::size_t>> faces;
    faces.reserve(body.triangles().size());
    for (const auto& t : body.triangles()) {
        faces.push_back({t[0], t[1], t[2]});
    }
    const LoadedMesh<Mesh> loaded = triangle_mesh_from_soup<Mesh>(points, faces, "synthetic body");
    write_mesh(outputs.temporary(args.out), loaded.mesh);
    const std::vector<measurement::SyntheticTruth> truth = measurement::synthetic_girth_truth(body);
    if (!args.truth_out.empty()) {
        nlohmann::ordered_json j;
        j["format"] = "tapeline-synthetic-body-truth";
        j["unit"] = "mm";
        j["spec"] = args.spec;
        j["around"] = o.around;
        j["ring_step_mm"] = o.ring_step;
        j["arm_angle_degrees"] = o.arm_angle_degrees;
        j["stature"] = measurement::SyntheticBody::kHeight;
        j["note"] =
            "exact perimeters of the analytic sections at the levels the construction "
            "defines (measurement/synthetic_body.h); tolerance: what this mesh resolves";
        auto& list = j["girths"] = nlohmann::ordered_json::array();
        for (const auto& t : truth) {
            list.push_back({{"name", t.name},
                            {"value_mm", t.value},
                            {"tolerance_mm", t.tolerance},
                            {"level_mm", t.level},
                            {"level_from_landmarks", t.from_landmarks}});
        }
        outputs.write(args.truth_out, [&](std::ostream& out) { out << j.dump(2) << '\n'; });
    }
    outputs.commit();
    std::cout << "wrote " << args.out << ": synthetic body (" << o.around << " around, "
              << o.ring_step << " mm rings, arms " << o.arm_angle_degrees << " degrees), "
              << num_vertices(loaded.mesh) << " vertices, " << num_faces(loaded.mesh)
              << " faces, millimetres, +Y up, +Z front\n";
    if (!args.truth_out.empty()) {
        std::cout << "wrote " << args.truth_out << ": exact values of " << truth.size()
                  << " girths\n";
    }
}

void run_generate(const GenerateArgs& args) {
    if (const auto body = body_spec(args.spec)) {
        run_generate_body(args, *body);
        return;
    }
    InputMesh input = make_input_surface(args.spec, args.seed);
    const Mesh& mesh = input.loaded.mesh;
    if (!args.truth_out.empty() && args.truth_source < 0) {
        throw InvalidInput("--truth-out needs --truth-source V");
    }
    std::vector<double> truth;
    if (args.truth_source >= 0) {
        if (static_cast<std::size_t>(args.truth_source) >= num_vertices(mesh)) {
            throw InvalidInput("--truth-source " + std::to_string(args.truth_source) +
                               ": the surface has " + std::to_string(num_vertices(mesh)) +
                               " vertices");
        }
        AnalyticGeodesicDistance distance(*input.spec);
        if (!distance.available()) {
            throw InvalidInput(input.name +
                               ": no exact smooth geodesic distance is known for this "
                               "surface (torus and triaxial ellipsoid have none)");
        }
        if (args.truth_out.empty()) {
            throw InvalidInput("--truth-source needs --truth-out FILE (.txt or .ply)");
        }
        truth = analytic_distances(*input.spec, mesh_points(mesh),
                                   static_cast<std::size_t>(args.truth_source));
    }
    write_mesh(args.out, mesh);
    std::cout << "wrote " << args.out << ": " << input.name << ", " << num_vertices(mesh)
              << " vertices, " << num_faces(mesh) << " faces\n";
    if (!truth.empty()) {
        write_distances(args.truth_out, mesh, truth, truth);
        std::cout << "wrote " << args.truth_out << ": exact smooth distance from vertex "
                  << args.truth_source << " ("
                  << AnalyticGeodesicDistance(*input.spec).description() << ")\n";
    }
}

void run_check(const std::string& path, bool strict) {
    InputMesh input = load_input_mesh_file(path, strict);
    std::cout << input.loaded.report.summary();
    if (!input.loaded.report.summary().empty() && input.loaded.report.summary().back() != '\n') {
        std::cout << '\n';
    }
}

struct RemeshArgs {
    std::string in, out;
    double edge = 0;
    unsigned iterations = 3;
    std::size_t vertices = 0;
};

/// Reads `a.in`, applies `change` (re-meshing or decimation) and writes `a.out`, whose path is
/// checked before any work.
void rewrite_mesh(const RemeshArgs& a,
                  const std::function<RemeshReport(Mesh&, const std::string&)>& change) {
    check_mesh_output(a.out);
    InputMesh input = load_input_mesh_file(a.in, false);
    const RemeshReport r = change(input.loaded.mesh, a.in);
    write_mesh(a.out, input.loaded.mesh);
    std::cout << "wrote " << a.out << ": " << r.vertices_after << " vertices, " << r.faces_after
              << " faces (from " << r.vertices_before << " vertices, " << r.faces_before
              << " faces)\n";
}

}  // namespace

void register_mesh_commands(CLI::App& app) {
    CLI::App* mesh = app.add_subcommand("mesh", "Generate analytic test surfaces, check meshes");
    mesh->require_subcommand(1);

    auto gen = std::make_shared<GenerateArgs>();
    CLI::App* generate = mesh->add_subcommand(
        "generate",
        "Write an analytic surface mesh (and optionally its exact smooth geodesic distance).\n"
        "SPEC: icosphere:LEVEL[:J] | uvsphere:NLAT,NLON[:J] | ellipsoid:A,B,C:LEVEL[:J] |\n"
        "      torus:R,r:NU,NV[:J] | cylinder:R,H:NU,NV[:J]   (J = tangential jitter, 0..0.5)\n"
        "      body[:AROUND,RING_MM[,ARM_DEGREES]]: the synthetic body of exactly known girths\n"
        "      (mm, +Y up, +Z front; default body:48,8,40); --truth-out FILE.json its girths");
    generate->add_option("spec", gen->spec, "Surface spec, e.g. icosphere:4")->required();
    generate->add_option("--out,-o", gen->out, "Output mesh (.off, .obj, .ply, .stl)")->required();
    generate->add_option("--seed", gen->seed, "Seed of the jitter (default 1)");
    generate->add_option("--truth-source", gen->truth_source,
                         "Vertex whose exact smooth geodesic distance to every vertex is written");
    generate->add_option("--truth-out", gen->truth_out,
                         "Where to write that distance (.txt: one per vertex; .ply: coloured), or "
                         "the synthetic body's girths (.json)");
    generate->callback([gen] { run_generate(*gen); });

    auto check_path = std::make_shared<std::string>();
    auto check_strict = std::make_shared<bool>(false);
    CLI::App* check = mesh->add_subcommand(
        "check", "Read a mesh (OFF, OBJ, PLY, STL) and report what was found and repaired");
    check->add_option("mesh", *check_path, "Mesh file")->required();
    check->add_flag("--strict", *check_strict,
                    "Reject polygons, duplicates and non-manifold elements instead of repairing");
    check->callback([check_path, check_strict] { run_check(*check_path, *check_strict); });

    auto rem = std::make_shared<RemeshArgs>();
    CLI::App* remesh = mesh->add_subcommand(
        "remesh",
        "Re-mesh a surface to near-equilateral triangles of a target edge length (CGAL isotropic "
        "remeshing; borders kept)");
    remesh->add_option("mesh", rem->in, "Mesh file (OFF, OBJ, PLY, STL)")->required();
    remesh
        ->add_option("--edge", rem->edge,
                     "Target edge length in the mesh's unit (0.05 is 5 mm on a decimetre body)")
        ->required();
    remesh->add_option("--iterations", rem->iterations, "Remeshing rounds")->capture_default_str();
    remesh->add_option("--out,-o", rem->out, "Output mesh (.off, .obj, .ply, .stl)")->required();
    remesh->callback([rem] {
        rewrite_mesh(*rem, [&](Mesh& m, const std::string& name) {
            return remesh_isotropic(m, rem->edge, rem->iterations, name);
        });
    });

    auto sim = std::make_shared<RemeshArgs>();
    CLI::App* simplify = mesh->add_subcommand(
        "simplify",
        "Decimate a triangle mesh to about N vertices (CGAL edge collapse, Garland-Heckbert "
        "quadrics)");
    simplify->add_option("mesh", sim->in, "Mesh file (OFF, OBJ, PLY, STL)")->required();
    simplify->add_option("--vertices", sim->vertices, "Target vertex count")->required();
    simplify->add_option("--out,-o", sim->out, "Output mesh (.off, .obj, .ply, .stl)")->required();
    simplify->callback([sim] {
        rewrite_mesh(*sim, [&](Mesh& m, const std::string& name) {
            return simplify_to_vertices(m, sim->vertices, name);
        });
    });
}

}  // namespace tapeline::app
