// The C++ side of python/benchmarks/overhead.py: what a C++ program holding the same mesh as flat
// arrays (V: n x 3 doubles, F: m x 3 indices, as numpy holds them) pays for one distance field:
// the arrays turned into the loader's polygon soup, the mesh built and checked
// (triangle_mesh_from_soup), the method run (bench::run_distance_method, as tapeline.geodesic
// .distances and `tapeline geodesic distances` run it) and the result put back in the input's
// vertex order. One JSON line per run: {"method", "wall_s", "build_s", "call_s"}.
//
//     overhead_baseline MESH SOURCE REPEAT METHOD [METHOD ...]
#include <tapeline/bench/methods.h>
#include <tapeline/core/mesh_io.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;
using tapeline::bench::Mesh;

double since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) try {
    if (argc < 5) {
        std::fprintf(stderr, "usage: overhead_baseline MESH SOURCE REPEAT METHOD [METHOD ...]\n");
        return 2;
    }
    // The flat arrays, as tapeline.read_mesh gives them to Python.
    const auto file = tapeline::read_triangle_mesh<Mesh>(argv[1]);
    std::vector<double> V;
    std::vector<std::int64_t> F;
    for (auto v : vertices(file.mesh)) {
        const auto& p = file.mesh.point(v);
        V.insert(V.end(), {p.x(), p.y(), p.z()});
    }
    for (auto f : faces(file.mesh)) {
        for (auto v : vertices_around_face(halfedge(f, file.mesh), file.mesh)) {
            F.push_back(static_cast<std::int64_t>(v.idx()));
        }
    }
    const std::size_t source = std::stoul(argv[2]);
    const int repeat = std::atoi(argv[3]);
    for (int a = 4; a < argc; ++a) {
        const std::string method = argv[a];
        for (int r = 0; r < repeat; ++r) {
            // Everything a function taking the arrays and returning the field does, the mesh's
            // destruction at its end included.
            const auto t0 = Clock::now();
            double build = 0, call = 0;
            std::vector<double> d;
            {
                std::vector<std::array<double, 3>> points(V.size() / 3);
                for (std::size_t i = 0; i < points.size(); ++i) {
                    points[i] = {V[3 * i], V[3 * i + 1], V[3 * i + 2]};
                }
                std::vector<std::vector<std::size_t>> soup;
                soup.reserve(F.size() / 3);
                for (std::size_t i = 0; i < F.size(); i += 3) {
                    soup.push_back(
                        {std::size_t(F[i]), std::size_t(F[i + 1]), std::size_t(F[i + 2])});
                }
                const auto t_build = Clock::now();
                const auto loaded = tapeline::triangle_mesh_from_soup<Mesh>(points, soup, "arrays");
                build = since(t_build);
                tapeline::bench::Sources sources;
                for (auto v : loaded.mesh_vertices_of(source)) {
                    sources.vertices.push_back(v);
                }
                const auto t_call = Clock::now();
                const tapeline::bench::MethodResult m =
                    tapeline::bench::run_distance_method(method, loaded.mesh, sources, {});
                call = since(t_call);
                d = loaded.to_input_order(m.distances);
            }
            const double wall = since(t0);
            std::printf(
                "{\"method\": \"%s\", \"wall_s\": %.6f, \"build_s\": %.6f, \"call_s\": %.6f, "
                "\"d_last\": %.17g}\n",
                method.c_str(), wall, build, call, d.back());
        }
    }
    return 0;
} catch (const std::exception& e) {
    std::fprintf(stderr, "overhead_baseline: %s\n", e.what());
    return 1;
}
