// The Ceres flow-step solver for the tests: the only translation unit that includes
// curvature_flow_ceres.h (and so compiles Ceres), when tapeline::geodesic_ceres exists.
#include <tapeline_test/gcf.h>

#ifdef TAPELINE_TEST_WITH_CERES
#include <tapeline/geodesic/curvature_flow_ceres.h>
#endif

namespace tapeline_test::geodesic {

bool gcf_ceres_available() {
#ifdef TAPELINE_TEST_WITH_CERES
    return tapeline::geodesic::register_ceres_flow_solver();
#else
    return false;
#endif
}

void gcf_ceres_register(bool on) {
#ifdef TAPELINE_TEST_WITH_CERES
    if (on)
        tapeline::geodesic::register_ceres_flow_solver();
    else
        tapeline::geodesic::internal::gcf::ceres_step_solver().store(nullptr);
#else
    (void)on;
#endif
}

}  // namespace tapeline_test::geodesic
