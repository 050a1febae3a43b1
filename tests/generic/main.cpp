// Genericity, proven: the main algorithms compile on CGAL::Polyhedron_3 and on a minimal
// hand-written mesh type (minimal_mesh.h), and on a small sphere give what they give on
// Surface_mesh.
// Same vertex and face order everywhere, so the same arithmetic: the fields must agree to
// rounding (1e-12 relative), and differ only where a mesh type's traversal order feeds a
// floating-point sum.
#include "run_algorithms.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

using tapeline_test::generic::Results;

int failures = 0;

void check(const char* mesh, const char* what, double a, double b) {
    const double tol = 1e-12 * (1 + std::abs(b));
    if (!(std::abs(a - b) <= tol)) {
        std::printf("FAIL %s %s: %.17g, Surface_mesh %.17g\n", mesh, what, a, b);
        ++failures;
    }
}

void check(const char* mesh, const char* what, const std::vector<double>& a,
           const std::vector<double>& b) {
    if (a.size() != b.size()) {
        std::printf("FAIL %s %s: %zu values, Surface_mesh %zu\n", mesh, what, a.size(), b.size());
        ++failures;
        return;
    }
    double worst = 0;
    std::size_t at = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const double d = std::abs(a[i] - b[i]) / (1 + std::abs(b[i]));
        if (!(d <= worst)) {
            worst = d;
            at = i;
        }
    }
    std::printf("%-13s %-9s max relative difference %.3g\n", mesh, what, worst);
    if (!(worst <= 1e-12)) {
        std::printf("FAIL %s %s at vertex %zu: %.17g, Surface_mesh %.17g\n", mesh, what, at, a[at],
                    b[at]);
        ++failures;
    }
}

void compare(const char* mesh, const Results& r, const Results& ref) {
    check(mesh, "exact-mmp", r.mmp, ref.mmp);
    check(mesh, "heat", r.heat, ref.heat);
    check(mesh, "dijkstra", r.dijkstra, ref.dijkstra);
    check(mesh, "fmm", r.fmm, ref.fmm);
    check(mesh, "gcf-window", r.gcf, ref.gcf);
    check(mesh, "mmp path", r.mmp_path, ref.mmp_path);
    check(mesh, "gcf path", r.gcf_path, ref.gcf_path);
    check(mesh, "unfolded", r.unfolded, ref.unfolded);
}

}  // namespace

int main() {
    namespace tg = tapeline_test::generic;
    // A jittered sphere: irregular triangles, so that ties between paths are rare.
    const tapeline::SurfaceSpec spec = tapeline::SurfaceSpec::parse("icosphere:2:0.2");
    const std::size_t source = 0, target = 100;
    const Results ref = tg::on_surface_mesh(spec, source, target);
    // The reference itself must be a distance field: 0 at the source, exact <= every other.
    if (ref.mmp.size() != spec.vertex_count() || ref.mmp[source] != 0 ||
        !(ref.mmp_path > 1 && ref.mmp_path < 3.2)) {
        std::printf("FAIL Surface_mesh reference: %zu values, path %.6g\n", ref.mmp.size(),
                    ref.mmp_path);
        return 1;
    }
    for (std::size_t i = 0; i < ref.mmp.size(); ++i) {
        if (ref.mmp[i] > ref.dijkstra[i] + 1e-12) {
            std::printf("FAIL exact above Dijkstra at %zu\n", i);
            return 1;
        }
    }
    compare("Polyhedron_3", tg::on_polyhedron(spec, source, target), ref);
    compare("minimal mesh", tg::on_minimal_mesh(spec, source, target), ref);
    std::printf(failures ? "%d differences\n" : "every field equals Surface_mesh's\n", failures);
    return failures ? 1 : 0;
}
