// Unfolded path strips for the tests: the only translation unit that instantiates unfold.h.
#define TAPELINE_TEST_GEODESIC_WITH_CGAL
#include <tapeline_test/geodesic.h>
#include <tapeline_test/unfold.h>

#include <tapeline/geodesic/unfold.h>
#include <tapeline/geodesic/unfold_svg.h>

#include <sstream>

namespace tapeline_test::geodesic {

UnfoldedPath unfold(const Soup& soup, const std::vector<Vec3>& path, const UnfoldOptions& options,
                    MeshKind kind) {
    std::vector<cgal::Kernel::Point_3> pts;
    for (const auto& p : path)
        pts.emplace_back(p[0], p[1], p[2]);
    return cgal::with_mesh(
        soup, kind, [&](auto& tm) { return tapeline::geodesic::unfold_path(tm, pts, options); });
}

std::string unfold_svg(const UnfoldedPath& u, const std::string& title) {
    std::ostringstream out;
    tapeline::geodesic::write_unfold_svg(out, u, title);
    return out.str();
}

}  // namespace tapeline_test::geodesic
