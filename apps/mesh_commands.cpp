// `tapeline mesh generate`, `check`, `remesh` and `simplify`.
#include "app_types.h"
#include "commands.h"
#include "output.h"

#include <tapeline/core/errors.h>
#include <tapeline/core/mesh_writers.h>
#include <tapeline/core/remesh.h>
#include <tapeline/surfaces/analytic_geodesics.h>

#include <CLI/CLI.hpp>

#include <functional>
#include <iostream>
#include <memory>

namespace tapeline::app {
namespace {

struct GenerateArgs {
    std::string spec;
    std::string out;
    std::uint64_t seed = 1;
    long truth_source = -1;
    std::string truth_out;
};

void run_generate(const GenerateArgs& args) {
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
        "      torus:R,r:NU,NV[:J] | cylinder:R,H:NU,NV[:J]   (J = tangential jitter, 0..0.5)");
    generate->add_option("spec", gen->spec, "Surface spec, e.g. icosphere:4")->required();
    generate->add_option("--out,-o", gen->out, "Output mesh (.off, .obj, .ply, .stl)")->required();
    generate->add_option("--seed", gen->seed, "Seed of the jitter (default 1)");
    generate->add_option("--truth-source", gen->truth_source,
                         "Vertex whose exact smooth geodesic distance to every vertex is written");
    generate->add_option("--truth-out", gen->truth_out,
                         "Where to write that distance (.txt: one per vertex; .ply: coloured)");
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
