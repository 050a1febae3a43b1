// Pattern grading by multi-objective optimisation: resize a pattern to a target measurement set so
// that every bound measurement fits (target + ease) while the pattern keeps its style.
//
// Variables: a displacement of every node of every piece (outline control points, named points,
// grain ends) and its 2×2 gradient, so that the graded pattern is the base one plus per-point
// grade rules. Objectives (grading/README.md has every formula): fit of the bindings (a girth's
// growth split between its pieces by their base shares) and the seams — equal sides, or the base
// draft's deliberate ratio — (f1); style — turn angles at outline vertices, the shape of curved
// edges in their chord frame, proportions between nodes, grain direction — (f2); and a smooth
// displacement field (locally affine, gradient varying slowly; trims grow in length only).
//
// Search: NSGA-II (Deb, Pratap, Agarwal & Meyarivan 2002, through pagmo2) on a reduced genome —
// a quadratic displacement field per piece — gives a Pareto front of f1 against f2; each member is
// polished by Ceres least squares over all node displacements with a fit weight that follows its
// place on the front; a Ceres solve from the base pattern (the fast path) joins the candidates.
// Default choice: among candidates whose bindings and seams are all within tolerance, the best
// style; when none is, the smallest worst fit error (relative to its tolerance).
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/core/progress.h>
#include <tapeline/grading/grading_types.h>
#include <tapeline/grading/internal/model.h>
#include <tapeline/pattern/pattern.h>
#include <tapeline/sizes/measurement_set.h>

#include <ceres/autodiff_cost_function.h>
#include <ceres/dynamic_autodiff_cost_function.h>
#include <ceres/problem.h>
#include <ceres/solver.h>

#include <pagmo/algorithms/nsga2.hpp>
#include <pagmo/batch_evaluators/thread_bfe.hpp>
#include <pagmo/bfe.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problem.hpp>
#include <pagmo/utils/multi_objective.hpp>

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace tapeline::grading {

namespace tp = tapeline::pattern;

namespace internal {

inline double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// Ceres adapter for a slot-based term: the term's distinct nodes are the parameter blocks.
template <typename Term>
struct SlotFunctor {
    Term term;
    std::vector<int> block_of_slot;
    std::vector<tp::Point2> base_of_slot;

    template <typename T>
    bool operator()(T const* const* params, T* r) const {
        auto pos = [&](std::size_t k) {
            const T* d = params[block_of_slot[k]];
            return V2<T>{T(base_of_slot[k].x) + d[0], T(base_of_slot[k].y) + d[1]};
        };
        term.template operator()<T>(pos, r);
        return true;
    }
};

template <typename Term>
void add_slot_term(ceres::Problem& pb, const Model& m, const Term& t, Solution& s) {
    auto* f = new SlotFunctor<Term>{t, {}, {}};
    std::vector<std::size_t> blocks;
    for (std::size_t node : t.idx) {
        const auto it = std::find(blocks.begin(), blocks.end(), node);
        f->block_of_slot.push_back(static_cast<int>(it - blocks.begin()));
        if (it == blocks.end()) {
            blocks.push_back(node);
        }
        f->base_of_slot.push_back(m.base[node]);
    }
    auto* cost = new ceres::DynamicAutoDiffCostFunction<SlotFunctor<Term>, 8>(f);
    std::vector<double*> params;
    for (std::size_t node : blocks) {
        cost->AddParameterBlock(2);
        params.push_back(&s.d[node].x);
    }
    cost->SetNumResiduals(Term::residuals);
    pb.AddResidualBlock(cost, nullptr, params);
}

struct ConsistencyCost {
    double ex, ey, w;
    template <typename T>
    bool operator()(const T* di, const T* dj, const T* A, T* r) const {
        r[0] = T(w) * (dj[0] - di[0] - (A[0] * ex + A[1] * ey));
        r[1] = T(w) * (dj[1] - di[1] - (A[2] * ex + A[3] * ey));
        return true;
    }
};

struct DifferenceCost {  // w·(a − b) on 4-vectors (bending; the global prior)
    double w;
    template <typename T>
    bool operator()(const T* a, const T* b, T* r) const {
        for (int k = 0; k < 4; ++k) {
            r[k] = T(w) * (a[k] - b[k]);
        }
        return true;
    }
};

/// The global prior of a trim (GradingOptions::trim_aspect): across the strip the displacement
/// gradient vanishes (A u⊥ = 0: no widening, no shear), along it the strip follows the garment
/// (u∥ᵀ (A − Ā) u∥ = 0); u∥ = (ux, uy) the strip's long axis.
struct TrimCost {
    double ux, uy, w;
    template <typename T>
    bool operator()(const T* A, const T* G, T* r) const {
        const double vx = -uy, vy = ux;
        r[0] = T(w) * (A[0] * vx + A[1] * vy);
        r[1] = T(w) * (A[2] * vx + A[3] * vy);
        const T along = ux * (A[0] * ux + A[1] * uy) + uy * (A[2] * ux + A[3] * uy);
        const T galong = ux * (G[0] * ux + G[1] * uy) + uy * (G[2] * ux + G[3] * uy);
        r[2] = T(w) * (along - galong);
        return true;
    }
};

struct ProportionCost {
    double bx, by, l0, w;  // base difference p_j − p_i
    template <typename T>
    bool operator()(const T* di, const T* dj, const T* s, T* r) const {
        const V2<T> e{T(bx) + dj[0] - di[0], T(by) + dj[1] - di[1]};
        r[0] = T(w) * (norm2(e) - s[0] * T(l0));
        return true;
    }
};

struct DampingCost {
    double w;
    template <typename T>
    bool operator()(const T* d, T* r) const {
        r[0] = T(w) * d[0];
        r[1] = T(w) * d[1];
        return true;
    }
};

struct CeresOutcome {
    Solution solution;
    std::size_t iterations = 0;
    std::string status;
    std::size_t residuals = 0, variables = 0;
};

/// Least squares over every node: fit (× fit_factor) and seams, style, smoothness.
inline CeresOutcome ceres_solve(const Model& m, const GradingOptions& o, double fit_factor,
                                Solution s) {
    const GradingWeights& w = o.weights;
    const double lref = o.reference_length_mm;
    std::vector<double> scale(m.pieces.size(), 1.0);
    {
        const std::vector<double> s0 = piece_scales(m, positions(m, s));
        scale = s0;
    }
    std::array<double, 4> G{0, 0, 0, 0};
    for (const auto& a : s.A) {
        for (int k = 0; k < 4; ++k) {
            G[k] += a[k] / std::max<std::size_t>(1, s.A.size());
        }
    }
    ceres::Problem::Options po;
    po.enable_fast_removal = false;
    ceres::Problem pb(po);
    for (LengthTerm t : m.fit) {
        t.weight *= fit_factor;
        add_slot_term(pb, m, t, s);
    }
    for (const LengthTerm& t : m.seams) {
        add_slot_term(pb, m, t, s);
    }
    for (LengthTerm t : m.shares) {
        t.weight *= fit_factor;
        add_slot_term(pb, m, t, s);
    }
    for (const TurnTerm& t : m.turns) {
        if (t.idx[0] != t.idx[2]) {
            add_slot_term(pb, m, t, s);
        }
    }
    for (const GrainTerm& t : m.grains) {
        add_slot_term(pb, m, t, s);
    }
    for (const CurveTerm& t : m.curves) {
        add_slot_term(pb, m, t, s);
    }
    for (const ProportionTerm& t : m.proportions) {
        const tp::Point2 e = m.base[t.j] - m.base[t.i];
        pb.AddResidualBlock(new ceres::AutoDiffCostFunction<ProportionCost, 1, 2, 2, 1>(
                                new ProportionCost{e.x, e.y, t.l0, t.weight}),
                            nullptr, &s.d[t.i].x, &s.d[t.j].x, &scale[t.piece]);
    }
    for (const auto& [i, j] : m.graph) {
        const tp::Point2 e = m.base[j] - m.base[i];
        pb.AddResidualBlock(new ceres::AutoDiffCostFunction<ConsistencyCost, 2, 2, 2, 4>(
                                new ConsistencyCost{e.x, e.y, w.consistency}),
                            nullptr, &s.d[i].x, &s.d[j].x, s.A[i].data());
        pb.AddResidualBlock(new ceres::AutoDiffCostFunction<ConsistencyCost, 2, 2, 2, 4>(
                                new ConsistencyCost{-e.x, -e.y, w.consistency}),
                            nullptr, &s.d[j].x, &s.d[i].x, s.A[j].data());
        pb.AddResidualBlock(
            new ceres::AutoDiffCostFunction<DifferenceCost, 4, 4, 4>(new DifferenceCost{
                w.bending * lref / std::max(1.0, tp::distance(m.base[i], m.base[j]))}),
            nullptr, s.A[i].data(), s.A[j].data());
    }
    for (std::size_t i = 0; i < m.base.size(); ++i) {
        const PieceModel& pm = m.pieces[m.piece_of[i]];
        if (pm.trim) {
            pb.AddResidualBlock(new ceres::AutoDiffCostFunction<TrimCost, 3, 4, 4>(
                                    new TrimCost{pm.axis.x, pm.axis.y, w.trim}),
                                nullptr, s.A[i].data(), G.data());
        } else {
            pb.AddResidualBlock(new ceres::AutoDiffCostFunction<DifferenceCost, 4, 4, 4>(
                                    new DifferenceCost{w.global}),
                                nullptr, s.A[i].data(), G.data());
        }
        pb.AddResidualBlock(
            new ceres::AutoDiffCostFunction<DampingCost, 2, 2>(new DampingCost{1e-3}), nullptr,
            &s.d[i].x);
    }
    ceres::Solver::Options so;
    so.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
    if (!ceres::IsSparseLinearAlgebraLibraryTypeAvailable(so.sparse_linear_algebra_library_type)) {
        so.linear_solver_type = ceres::DENSE_QR;
    }
    so.max_num_iterations = static_cast<int>(o.ceres_iterations);
    so.function_tolerance = 1e-12;
    so.gradient_tolerance = 1e-12;
    so.parameter_tolerance = 1e-12;
    so.num_threads = 1;  // members are polished in parallel
    so.logging_type = ceres::SILENT;
    ceres::Solver::Summary summary;
    ceres::Solve(so, &pb, &summary);
    CeresOutcome out;
    out.iterations = summary.iterations.size();
    out.status = summary.termination_type == ceres::CONVERGENCE      ? "converged"
                 : summary.termination_type == ceres::NO_CONVERGENCE ? "iteration limit"
                                                                     : "failed";
    out.residuals = static_cast<std::size_t>(pb.NumResiduals());
    out.variables = static_cast<std::size_t>(pb.NumParameters());
    if (!summary.IsSolutionUsable()) {
        throw SolverFailure("grading: Ceres found no usable solution (" + summary.message + ")");
    }
    out.solution = std::move(s);
    return out;
}

/// The NSGA-II genome: per piece a quadratic displacement field in normalised coordinates
/// p̂ = (p − centroid)/radius, d(p) = Σ_k c_k φ_k(p̂), φ = (x̂, ŷ, x̂², x̂ŷ, ŷ²) for each of
/// x and y: 10 genes per piece, in mm.
constexpr std::size_t genes_per_piece = 10;

inline Solution decode(const Model& m, const std::vector<double>& g) {
    Solution s;
    s.d.resize(m.base.size());
    s.A.resize(m.base.size());
    for (std::size_t pi = 0; pi < m.pieces.size(); ++pi) {
        const PieceModel& pm = m.pieces[pi];
        const double* c = &g[genes_per_piece * pi];
        const double R = pm.radius;
        for (std::size_t k = pm.first; k < pm.first + pm.count; ++k) {
            const double x = (m.base[k].x - pm.centroid.x) / R;
            const double y = (m.base[k].y - pm.centroid.y) / R;
            s.d[k] = {c[0] * x + c[1] * y + c[2] * x * x + c[3] * x * y + c[4] * y * y,
                      c[5] * x + c[6] * y + c[7] * x * x + c[8] * x * y + c[9] * y * y};
            s.A[k] = {(c[0] + 2 * c[2] * x + c[3] * y) / R, (c[1] + c[3] * x + 2 * c[4] * y) / R,
                      (c[5] + 2 * c[7] * x + c[8] * y) / R, (c[6] + c[8] * x + 2 * c[9] * y) / R};
        }
    }
    return s;
}

/// Progress of the NSGA-II search: pagmo evolves all generations in one call, so generations are
/// counted from the fitness evaluations (a population's worth each) once the search starts.
struct GenerationProgress {
    Progress progress;
    std::size_t per_generation;
    std::atomic<bool> started{false};
    std::atomic<std::size_t> evaluations{0};
    std::atomic<double> best_fit{std::numeric_limits<double>::infinity()};

    GenerationProgress(std::size_t generations, std::size_t population)
        : progress("grade: NSGA-II generations", generations), per_generation(population) {}

    void evaluated(double fit) {
        if (!started.load(std::memory_order_relaxed) || !progress.enabled()) {
            return;
        }
        double best = best_fit.load(std::memory_order_relaxed);
        while (fit < best && !best_fit.compare_exchange_weak(best, fit)) {
        }
        if (fit < best) {
            char note[64];
            std::snprintf(note, sizeof note, "best fit %.3g mm", fit);
            progress.note(note);
        }
        progress.set(evaluations.fetch_add(1, std::memory_order_relaxed) / per_generation);
    }
};

struct GradingUdp {
    std::shared_ptr<const Model> model;
    GenerationProgress* progress = nullptr;  // not owned; null: no progress

    pagmo::vector_double fitness(const pagmo::vector_double& g) const {
        const Objectives o = objectives(*model, positions(*model, decode(*model, g)));
        if (progress) {
            progress->evaluated(o.fit);
        }
        return {o.fit, o.style};
    }
    std::pair<pagmo::vector_double, pagmo::vector_double> get_bounds() const {
        pagmo::vector_double lo, hi;
        for (const PieceModel& pm : model->pieces) {
            for (std::size_t k = 0; k < genes_per_piece; ++k) {
                const bool linear = k % 5 < 2;
                const double b = (linear ? 0.3 : 0.1) * pm.radius;
                lo.push_back(-b);
                hi.push_back(b);
            }
        }
        return {lo, hi};
    }
    pagmo::vector_double::size_type get_nobj() const { return 2; }
    pagmo::thread_safety get_thread_safety() const { return pagmo::thread_safety::constant; }
    std::string get_name() const { return "tapeline grading (fit, style)"; }
};

/// A uniform-scale genome: every piece scaled by the ratio of bound targets to bound lengths.
inline std::vector<double> scale_genome(const Model& m) {
    double num = 0, den = 0;
    for (const LengthTerm& t : m.fit) {
        num += t.constant;
        den += length_of(t, m.base);
    }
    const double s = den > 0 ? num / den : 1;
    std::vector<double> g(genes_per_piece * m.pieces.size(), 0);
    for (std::size_t pi = 0; pi < m.pieces.size(); ++pi) {
        g[genes_per_piece * pi + 0] = (s - 1) * m.pieces[pi].radius;
        g[genes_per_piece * pi + 6] = (s - 1) * m.pieces[pi].radius;
    }
    return g;
}

struct Candidate {
    Solution solution;
    ParetoPoint point;
};

inline ParetoPoint score(const Model& m, const Solution& s, const GradingOptions& o,
                         const std::string& origin, bool polished) {
    const Objectives ob = objectives(m, positions(m, s));
    ParetoPoint p;
    p.fit = ob.fit;
    p.style = ob.style;
    p.max_fit_error_mm = ob.max_fit;
    p.max_seam_mismatch_mm = ob.max_seam;
    p.polished = polished;
    p.origin = origin;
    p.within_tolerance = ob.max_fit <= o.tolerances.fit_mm && ob.max_seam <= o.tolerances.seam_mm;
    return p;
}

inline StyleMetrics style_metrics(const Model& m, const Solution& s, double style_cost) {
    StyleMetrics st;
    const std::vector<tp::Point2> x = positions(m, s);
    double r[4];
    double sum = 0;
    for (const TurnTerm& t : m.turns) {
        eval_term(t, x, r);
        const double deg = std::abs(r[0] / t.weight) * 180 / M_PI;
        st.max_angle_change_deg = std::max(st.max_angle_change_deg, deg);
        sum += deg;
    }
    st.mean_angle_change_deg = m.turns.empty() ? 0 : sum / m.turns.size();
    for (const CurveTerm& t : m.curves) {
        eval_term(t, x, r);
        for (double v : r) {
            st.max_curve_change = std::max(st.max_curve_change, std::abs(v / t.weight));
        }
    }
    for (const GrainTerm& t : m.grains) {
        eval_term(t, x, r);
        st.max_grain_change_deg =
            std::max(st.max_grain_change_deg, std::abs(r[0] / t.weight) * 180 / M_PI);
    }
    std::vector<double> lo(m.pieces.size(), 1e300), hi(m.pieces.size(), -1e300),
        mean(m.pieces.size(), 0), cnt(m.pieces.size(), 0);
    for (const ProportionTerm& t : m.proportions) {
        if (t.l0 < 1) {
            continue;
        }
        const double k = tp::distance(x[t.i], x[t.j]) / t.l0;
        lo[t.piece] = std::min(lo[t.piece], k);
        hi[t.piece] = std::max(hi[t.piece], k);
        mean[t.piece] += k;
        cnt[t.piece] += 1;
    }
    for (std::size_t pi = 0; pi < m.pieces.size(); ++pi) {
        if (cnt[pi] > 0) {
            st.proportion_spread =
                std::max(st.proportion_spread, (hi[pi] - lo[pi]) / (mean[pi] / cnt[pi]));
        }
    }
    st.cost = style_cost;
    return st;
}

}  // namespace internal

/// Grades `base` (drafted for `from`) to the measurements `to`, keeping the pattern's own seams and
/// those of `seams` it does not hold by name (e.g. pattern::freesewing_seams(base)). Throws
/// InvalidInput when a binding names a measurement `to` lacks or a seam names a missing piece or
/// edge, SolverFailure when Ceres fails.
///
/// \param base the pattern to grade; its measurement bindings say what to fit.
/// \param from the measurements `base` was drafted for.
/// \param to the target measurements.
/// \param o weights, search sizes, seed and thread limit.
/// \param seams seams added to the pattern's own (by name) for the seam terms.
/// \return the graded pattern (Ceres optimum), the Pareto front of the search, the report.
/// \throws InvalidInput when `base` has no bindings, a binding names a piece, edge or point
///         that does not exist or a measurement that `from` or `to` lacks, or a seam names a
///         missing piece or edges.
/// \throws SolverFailure when Ceres finds no usable solution.
inline GradeResult grade_pattern(const tp::Pattern& base, const sizes::MeasurementSet& from,
                                 const sizes::MeasurementSet& to, const GradingOptions& o = {},
                                 const std::vector<SeamSpec>& seams = {}) {
    using namespace internal;
    const auto t0 = std::chrono::steady_clock::now();
    std::unique_ptr<tbb::global_control> limit;
    if (o.threads > 0) {
        limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                      o.threads);
    }
    if (base.bindings.empty()) {
        throw InvalidInput("pattern '" + base.name +
                           "': no measurement bindings, nothing to grade to");
    }
    auto model = std::make_shared<Model>(build_model(base, from, to, o, seams));
    const Model& m = *model;
    GradeResult result;
    GradingReport& rep = result.report;
    rep.pieces = m.pieces.size();
    rep.nodes = m.base.size();
    rep.timings.setup_s = seconds_since(t0);

    std::vector<Candidate> cands;
    Solution zero;
    zero.d.assign(m.base.size(), {0, 0});
    zero.A.assign(m.base.size(), {0, 0, 0, 0});

    // Fast path: Ceres from the base pattern, fit weight as given.
    auto tc = std::chrono::steady_clock::now();
    {
        CeresOutcome c = ceres_solve(m, o, 1.0, zero);
        rep.ceres_iterations = c.iterations;
        rep.ceres_status = c.status;
        rep.residuals = c.residuals;
        rep.variables = c.variables;
        cands.push_back({c.solution, score(m, c.solution, o, "ceres", true)});
    }
    rep.timings.ceres_fast_path_s = seconds_since(tc);

    if (o.generations > 0) {
        auto tn = std::chrono::steady_clock::now();
        std::size_t np = std::max<std::size_t>(8, (o.population + 3) / 4 * 4);
        GenerationProgress progress(o.generations, np);
        pagmo::problem prob{GradingUdp{model, &progress}};
        pagmo::population pop(prob, 0, o.seed);
        // Seeds: the base pattern and a uniform scale; the rest random in the bounds, drawn
        // from the population's own seeded generator.
        pop.push_back(std::vector<double>(genes_per_piece * m.pieces.size(), 0));
        pop.push_back(scale_genome(m));
        while (pop.size() < np) {
            pop.push_back(pop.random_decision_vector());
        }
        pagmo::nsga2 algo(static_cast<unsigned>(o.generations), 0.95, 10., 0.01, 50., o.seed);
        algo.set_bfe(pagmo::bfe{pagmo::thread_bfe{}});
        progress.started = true;
        pop = algo.evolve(pop);
        progress.progress.finish();
        rep.evaluations = pop.get_problem().get_fevals();
        const std::vector<std::size_t> front = pagmo::non_dominated_front_2d(pop.get_f());
        std::vector<std::size_t> order(front.begin(), front.end());
        std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
            return pop.get_f()[a][0] < pop.get_f()[b][0];
        });
        order.erase(std::unique(order.begin(), order.end(),
                                [&](std::size_t a, std::size_t b) {
                                    return pop.get_f()[a] == pop.get_f()[b];
                                }),
                    order.end());
        std::vector<Solution> members;
        for (std::size_t i : order) {
            members.push_back(decode(m, pop.get_x()[i]));
            cands.push_back({members.back(), score(m, members.back(), o, "nsga2", false)});
        }
        rep.timings.nsga2_s = seconds_since(tn);

        if (o.ceres_polish && !members.empty()) {
            auto tp0 = std::chrono::steady_clock::now();
            // At most 8 members, evenly spread along the front, fit weight log-spaced from the
            // fit end (max factor) to the style end (min factor).
            const std::size_t k = std::min<std::size_t>(8, members.size());
            std::vector<Candidate> polished(k);
            tbb::parallel_for(std::size_t(0), k, [&](std::size_t q) {
                const std::size_t i = k == 1 ? 0 : q * (members.size() - 1) / (k - 1);
                const double u = k == 1 ? 0 : double(q) / double(k - 1);
                const double f =
                    std::exp(std::log(o.max_fit_factor) * (1 - u) + std::log(o.min_fit_factor) * u);
                CeresOutcome c = ceres_solve(m, o, f, members[i]);
                polished[q] = {c.solution, score(m, c.solution, o, "nsga2+ceres", true)};
            });
            for (Candidate& c : polished) {
                cands.push_back(std::move(c));
            }
            rep.timings.polish_s = seconds_since(tp0);
        }
    }

    // The default choice (see the file comment).
    std::size_t best = 0;
    bool best_ok = false;
    double best_key = 1e300;
    for (std::size_t i = 0; i < cands.size(); ++i) {
        const ParetoPoint& p = cands[i].point;
        const double worst = std::max(p.max_fit_error_mm / o.tolerances.fit_mm,
                                      p.max_seam_mismatch_mm / o.tolerances.seam_mm);
        const double key = p.within_tolerance ? p.style : worst;
        if ((p.within_tolerance && !best_ok) || (p.within_tolerance == best_ok && key < best_key)) {
            best = i;
            best_ok = p.within_tolerance;
            best_key = key;
        }
    }
    for (const Candidate& c : cands) {
        rep.front.push_back(c.point);
    }
    rep.chosen = best;
    rep.chosen_why = best_ok ? "every binding and seam within tolerance; best style of " +
                                   std::to_string(std::count_if(cands.begin(), cands.end(),
                                                                [](const Candidate& c) {
                                                                    return c.point.within_tolerance;
                                                                })) +
                                   " such candidates"
                             : "no candidate within tolerance; smallest worst error relative to "
                               "its tolerance";
    const Candidate& chosen = cands[best];
    rep.within_tolerance = best_ok;
    rep.max_fit_error_mm = chosen.point.max_fit_error_mm;
    rep.max_seam_mismatch_mm = chosen.point.max_seam_mismatch_mm;

    // Tables of the chosen solution.
    const std::vector<tp::Point2> x = positions(m, chosen.solution);
    for (std::size_t i = 0; i < m.fit.size(); ++i) {
        FitRow row;
        row.measurement = m.bindings[i].measurement;
        row.where = m.bindings[i].where;
        row.target_mm = m.bindings[i].target;
        row.ease_mm = m.bindings[i].ease;
        row.achieved_mm = length_of(m.fit[i], x) - row.ease_mm;
        row.error_mm = row.achieved_mm - row.target_mm;
        rep.fit.push_back(row);
    }
    for (std::size_t i = 0; i < m.seams.size(); ++i) {
        LengthTerm a = m.seams[i], b = m.seams[i];
        a.items.erase(std::remove_if(a.items.begin(), a.items.end(),
                                     [](const LengthItem& it) { return it.coef < 0; }),
                      a.items.end());
        b.items.erase(std::remove_if(b.items.begin(), b.items.end(),
                                     [](const LengthItem& it) { return it.coef > 0; }),
                      b.items.end());
        for (LengthItem& it : b.items) {
            it.coef = 1;
        }
        SeamRow row;
        row.name = m.seam_names[i];
        row.ratio = m.seam_ratio[i];
        row.length_a_mm = length_of(a, x);
        row.length_b_mm = length_of(b, x);
        row.mismatch_mm = std::abs(row.length_a_mm - row.ratio * row.length_b_mm);
        rep.seams.push_back(row);
    }
    rep.style = style_metrics(m, chosen.solution, chosen.point.style);

    result.pattern = apply(base, m, chosen.solution);
    result.pattern.size = to.name;
    for (auto& [k, v] : result.pattern.measurements_used) {
        if (const auto t = to.get(k)) {
            v = *t;
        }
    }
    for (std::size_t i = 0; i < result.pattern.bindings.size(); ++i) {
        result.pattern.bindings[i].ease_mm = m.bindings[i].ease;
    }
    if (!to.name.empty()) {
        result.pattern.name = base.name + "_graded_" + to.name;
    }
    for (std::size_t pi = 0; pi < base.pieces.size(); ++pi) {
        const tp::Piece& b = base.pieces[pi];
        const tp::Piece& g = result.pattern.pieces[pi];
        for (std::size_t e = 0; e < b.outline.edges.size(); ++e) {
            result.rules.push_back({b.name, "edge " + std::to_string(e),
                                    tp::start_point(b.outline.edges[e]),
                                    tp::start_point(g.outline.edges[e])});
        }
        for (const auto& [name, q] : b.points) {
            result.rules.push_back({b.name, name, q, g.points.at(name)});
        }
    }
    rep.timings.total_s = seconds_since(t0);
    return result;
}

}  // namespace tapeline::grading
