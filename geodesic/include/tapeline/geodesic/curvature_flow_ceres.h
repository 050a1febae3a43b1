// Ceres as the least-squares solver of the geodesic-curvature-flow step (curvature_flow.h,
// CurvatureFlowSolver::ceres). Link the CMake target tapeline::geodesic_ceres; programs that need
// only geodesics include curvature_flow.h alone and never compile Ceres.
//
// Including this header registers the solver (an inline variable initialised before main); call
// register_ceres_flow_solver() explicitly when the including translation unit sits in a static
// library that the linker might drop. Then set CurvatureFlowOptions::solver = ceres.
//
// The step as a Ceres problem (the thesis' Eq. 3-4 with the tangent-space constraint of Eq. 5-7):
// every sample is a 3D parameter block on a tangent-plane ceres::Manifold (Plus(p, a) = p + T a,
// T the sample's 3x2 tangent basis), the endpoints are constant blocks, and the residuals are
//   T_iᵀ (p_{i-1} - 2 p_i + p_{i+1})      geodesic curvature at interior sample i
//   mu^{-1/2} T_iᵀ (p_i - p_i^0)          damping of the step (options.step = mu)
// Both are linear in the tangent coordinates, so one Gauss-Newton iteration (Levenberg-Marquardt
// with a trust region of 1e16, i.e. no extra damping) is the exact minimiser: the same system as
// the Eigen solvers, with the endpoints held exactly instead of by weighted rows.
#pragma once

#include <tapeline/geodesic/curvature_flow.h>
#include <tapeline/geodesic/curvature_flow_types.h>
#include <tapeline/geodesic/internal/gcf_engine.h>

// One by one, never ceres/ceres.h (DESIGN.md §5).
#include <ceres/cost_function.h>
#include <ceres/manifold.h>
#include <ceres/problem.h>
#include <ceres/sized_cost_function.h>
#include <ceres/solver.h>
#include <ceres/types.h>

#include <Eigen/Dense>

#include <memory>
#include <vector>

namespace tapeline::geodesic {

namespace internal::gcf_ceres {

using Tangent = Eigen::Matrix<double, 3, 2>;

/// The plane p + T a through a sample, T orthonormal (3x2).
class TangentPlaneManifold final : public ceres::Manifold {
public:
    explicit TangentPlaneManifold(const Tangent& t) : t_(t) {}
    int AmbientSize() const override { return 3; }
    int TangentSize() const override { return 2; }
    bool Plus(const double* x, const double* delta, double* x_plus_delta) const override {
        (Eigen::Map<Eigen::Vector3d>(x_plus_delta)) =
            Eigen::Map<const Eigen::Vector3d>(x) + t_ * Eigen::Map<const Eigen::Vector2d>(delta);
        return true;
    }
    bool PlusJacobian(const double*, double* jacobian) const override {
        (Eigen::Map<Eigen::Matrix<double, 3, 2, Eigen::RowMajor>>(jacobian)) = t_;
        return true;
    }
    bool Minus(const double* y, const double* x, double* y_minus_x) const override {
        (Eigen::Map<Eigen::Vector2d>(y_minus_x)) =
            t_.transpose() *
            (Eigen::Map<const Eigen::Vector3d>(y) - Eigen::Map<const Eigen::Vector3d>(x));
        return true;
    }
    bool MinusJacobian(const double*, double* jacobian) const override {
        (Eigen::Map<Eigen::Matrix<double, 2, 3, Eigen::RowMajor>>(jacobian)) = t_.transpose();
        return true;
    }

private:
    Tangent t_;
};

/// T_iᵀ (p_{i-1} - 2 p_i + p_{i+1}) with T_i fixed at the start of the step.
class CurvatureResidual final : public ceres::SizedCostFunction<2, 3, 3, 3> {
public:
    explicit CurvatureResidual(const Tangent& t) : tt_(t.transpose()) {}
    bool Evaluate(double const* const* p, double* residuals, double** jacobians) const override {
        const Eigen::Map<const Eigen::Vector3d> a(p[0]), b(p[1]), c(p[2]);
        (Eigen::Map<Eigen::Vector2d>(residuals)) = tt_ * (a - 2 * b + c);
        if (jacobians) {
            const double scale[3] = {1, -2, 1};
            for (int k = 0; k < 3; ++k)
                if (jacobians[k])
                    (Eigen::Map<Eigen::Matrix<double, 2, 3, Eigen::RowMajor>>(jacobians[k])) =
                        scale[k] * tt_;
        }
        return true;
    }

private:
    Eigen::Matrix<double, 2, 3> tt_;
};

/// w T_iᵀ (p_i - p_i^0): the damping 1/mu of the step, in the sample's tangent coordinates.
class DampingResidual final : public ceres::SizedCostFunction<2, 3> {
public:
    DampingResidual(const Tangent& t, const Eigen::Vector3d& p0, double w)
        : wt_(w * t.transpose()), p0_(p0) {}
    bool Evaluate(double const* const* p, double* residuals, double** jacobians) const override {
        (Eigen::Map<Eigen::Vector2d>(residuals)) =
            wt_ * (Eigen::Map<const Eigen::Vector3d>(p[0]) - p0_);
        if (jacobians && jacobians[0])
            (Eigen::Map<Eigen::Matrix<double, 2, 3, Eigen::RowMajor>>(jacobians[0])) = wt_;
        return true;
    }

private:
    Eigen::Matrix<double, 2, 3> wt_;
    Eigen::Vector3d p0_;
};

/// The TangentStepSolver of CurvatureFlowSolver::ceres (see gcf_engine.h).
inline bool ceres_step(const std::vector<gcf::Sample>& s, const std::vector<Tangent>& t,
                       const CurvatureFlowOptions& o, double step, Eigen::VectorXd& x) {
    const std::size_t n = s.size();
    std::vector<double> p(3 * n);
    for (std::size_t i = 0; i < n; ++i)
        (Eigen::Map<Eigen::Vector3d>(&p[3 * i])) = s[i].p;
    ceres::Problem problem;  // owns the cost functions and manifolds
    const double damp = 1.0 / std::sqrt(step);
    for (std::size_t i = 1; i + 1 < n; ++i) {
        problem.AddResidualBlock(new CurvatureResidual(t[i]), nullptr, &p[3 * (i - 1)], &p[3 * i],
                                 &p[3 * (i + 1)]);
        problem.AddResidualBlock(new DampingResidual(t[i], s[i].p, damp), nullptr, &p[3 * i]);
    }
    for (std::size_t i = 1; i + 1 < n; ++i)
        problem.SetManifold(&p[3 * i], new TangentPlaneManifold(t[i]));
    problem.SetParameterBlockConstant(&p[0]);
    problem.SetParameterBlockConstant(&p[3 * (n - 1)]);

    ceres::Solver::Options so;
    so.max_num_iterations = 1;
    so.minimizer_type = ceres::TRUST_REGION;
    so.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
    so.initial_trust_region_radius = 1e16;  // LM damping 1e-16: a Gauss-Newton step
    so.num_threads = 1;                     // parallelism is over paths (GeodesicPathSolver::paths)
    so.logging_type = ceres::SILENT;
    so.minimizer_progress_to_stdout = false;
    so.function_tolerance = 0;
    so.gradient_tolerance = 0;
    so.parameter_tolerance = 0;
    switch (o.ceres_linear_solver) {
        case CeresLinearSolver::dense_qr:
            so.linear_solver_type = ceres::DENSE_QR;
            break;
        case CeresLinearSolver::cgnr:
            so.linear_solver_type = ceres::CGNR;
            so.max_linear_solver_iterations = static_cast<int>(4 * n);
            break;
        case CeresLinearSolver::sparse_normal_cholesky_eigen:
            so.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
            so.sparse_linear_algebra_library_type = ceres::EIGEN_SPARSE;
            break;
        default:
            so.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
            so.sparse_linear_algebra_library_type = ceres::SUITE_SPARSE;
    }
    ceres::Solver::Summary summary;
    ceres::Solve(so, &problem, &summary);
    if (!summary.IsSolutionUsable())
        return false;
    x = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(2 * n));
    for (std::size_t i = 1; i + 1 < n; ++i)
        x.segment<2>(static_cast<Eigen::Index>(2 * i)) =
            t[i].transpose() * (Eigen::Map<const Eigen::Vector3d>(&p[3 * i]) - s[i].p);
    return true;
}

}  // namespace internal::gcf_ceres

/// Makes CurvatureFlowSolver::ceres available (idempotent; done on inclusion already).
inline bool register_ceres_flow_solver() {
    internal::gcf::ceres_step_solver().store(&internal::gcf_ceres::ceres_step,
                                             std::memory_order_release);
    return true;
}

namespace internal::gcf_ceres {
inline const bool registered = register_ceres_flow_solver();
}  // namespace internal::gcf_ceres

}  // namespace tapeline::geodesic
