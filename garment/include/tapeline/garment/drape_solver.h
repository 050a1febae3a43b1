// Cloth drape solver: extended position-based dynamics with small sub-steps.
//
// Papers:
//  - M. Macklin, M. Müller, N. Chentanez, "XPBD: Position-Based Simulation of Compliant
//    Constrained Dynamics", MIG 2016: compliant constraints, the λ update below.
//  - M. Macklin, K. Storey, M. Lu, P. Terdiman, N. Chentanez, S. Jeschke, M. Müller, "Small
//    Steps in Physics Simulation", SCA 2019: many sub-steps with one constraint pass each beat
//    many iterations of one big step, and keep every sub-step's motion small (no tunnelling).
//  - M. Müller, N. Chentanez, T.-Y. Kim, M. Macklin, "Strain Based Dynamics", SCA 2014:
//    in-plane stretch (warp, weft) and shear as constraints on the deformation gradient
//    F = [x1 − x0, x2 − x0]·Dm⁻¹, Dm in the fabric's grain frame.
//  - R. Bridson, S. Marino, R. Fedkiw, "Simulation of clothing with folds and wrinkles", SCA 2003:
//    the dihedral-angle gradients of the bending constraint.
//  - M. Macklin, M. Müller, N. Chentanez, T.-Y. Kim, "Unified Particle Physics for Real-Time
//    Applications", SIGGRAPH 2014: position-level Coulomb friction of contacts.
//  - M. Teschner et al., "Optimized Spatial Hashing for Collision Detection of Deformable
//    Objects", VMV 2003: the self-collision broad phase.
//
// Units and compliance. Positions mm, time s, mass kg; energy is then kg·mm²/s² = 1e-6 J.
//  - Stretch/shear: energy A·½·k·ε², k in N/m, A the rest area: in J that is ½·k·(A_mm²·1e-6)·ε²,
//    i.e. ½·(k·A_mm²)·ε² in kg·mm²/s², so the XPBD compliance of the strain constraint is
//    α = 1/(k·A_mm²) (s²/(kg·mm²)).
//  - Bending: energy ½·B(ψ)·(|e|²/A_e)·θ² per interior edge (bending.h: B(ψ) the fabric's
//    rigidity across the edge from its warp, weft and bias values, |e| the rest edge length, A_e
//    the rest area of its two triangles, θ the dihedral angle, flat at rest), B in µN·m, so
//    α = A_e/(B(ψ)·|e|²). bending.h derives the weight: a cylindrical bend gives ½·B·κ² per unit
//    area in every direction on equilateral meshes and along the grid lines of right-triangle
//    grids, at any edge length.
//  - Attachments and stitches: user compliance α_u in mm/N = 1/k with k in N/mm; energy
//    ½·k·C² N·mm = ½·k·1e3·C² kg·mm²/s², so α = α_u·1e-3 (s²/kg).
//  - Mass per vertex: a third of each incident rest triangle's area times the areal density:
//    density_g_m2·1e-9 kg/mm².
//
// Parallelism and determinism: constraints are greedily coloured once (serially, in index order)
// so that no two constraints of one colour share a vertex; Gauss–Seidel runs colour after colour
// with tbb::parallel_for inside a colour, so every update sees exactly the same values whatever
// the thread count and the result is bit-identical for any number of threads. Sums (energies) are
// taken serially; self-contacts are detected in parallel into fixed blocks and resolved serially.
//
// Collisions. Body: each sub-step first sweeps every vertex's motion through the collider by
// sphere tracing (the distance is 1-Lipschitz, so stepping by it never skips the surface) and
// stops a vertex at the body's surface; then every constraint pass pushes vertices out to the
// clearance (DrapeOptions::body_clearance_mm; by default the fabric thickness) along the distance
// gradient, with Coulomb friction. Cloth–cloth: vertex–
// triangle proximity within the thickness, detected once per sub-step through a spatial hash of
// the predicted positions; the side is taken from the sub-step's start, so a vertex that crossed
// a triangle within one sub-step is pushed back. Edge–edge pairs on request
// (DrapeOptions::edge_edge_collision; see detect_edge_edge_contacts()). Continuous
// self-collision and self-friction are not done. Edges against the body: see contact_edges().
// Tried and left out: keeping the (triangle, vertex) pairs within the thickness plus a skin s
// between searches (Verlet lists; found again once a vertex has moved s/2, which keeps the
// contacts exact). The search is 29 % of a frame of the T-shirt at 10 mm, but at rest 10–16
// light vertices (a quarter of an inner vertex's mass) still jump 0.5–0.7 mm a sub-step, so with s
// = 2.5 mm the lists were found again at every sub-step and the frame took 606 ms per 10k vertices
// against 475. Lists per vertex would be needed.
//
// Limit to know: with one constraint pass per sub-step a hard constraint acts like a spring of
// stiffness m/h² (m the vertex mass), whatever the fabric's stiffness, so a chain of N elements
// hanging from a support stretches by about g·h²·N²/2 (measured: 12 elements of 10 mm, h = 1/300 s:
// 7 %; 40 sub-steps: 0.4 %). Fine meshes therefore need sub-steps in proportion to the number of
// elements between supports (or more iterations, which help less), as Macklin et al. 2019 do.
// Tethers (DrapeOptions::tether_stretch) bound that stretch in cloth hanging from pinned
// vertices: long-range attachments (Kim, Chentanez, Müller, "Long Range Attachments", SCA 2012).
// The rest distance to the nearest pinned vertex is the shortest path over the rest edges, never
// shorter than the true rest geodesic, so a tether never holds cloth that the fabric would let
// hang within its own stretch. Tried and left out: anchors at the vertices touching the body,
// found anew every frame (from the contact flag, or from the distance to the body and the speed).
// They lower a tank top's p95 stretch (1.084 -> 1.067-1.071 graded, 1.096 -> 1.069 loose) but
// the garment no longer comes to rest (26-99 % of the vertices still moving) and a loose one
// intersects itself more: tethers to anchors that move drag the cloth and feed energy into it.
// Tried and left out: a projective-dynamics pass of the warp and weft stretch after the local
// constraints of every sub-step (Bouaziz et al. 2014; constant matrix M/h² + Σ w·c·cᵀ factored
// once with Eigen's SimplicialLDLT, 15 ms for 15k vertices, 2.4 ms per solve). On a 600 mm sheet
// hanging from its top edge at 10 mm and 10 sub-steps it takes the p95 edge stretch from 1.31
// (growing to 1.57, never at rest) to 1.001 at rest within a frame. But the global step does not
// see the body: cloth falls through a sphere it is dropped on. Holding the vertices at the body
// (factor refreshed when that set changes) keeps it outside but the cloth never comes to rest
// and the stretch of the shirt at the body stays (p95 1.55); removing only the motion into the
// body lets the free vertices through again; resisting stretch only (not compression) grows an
// oscillation on sheets of 40 rows and more. A global solve needs the contacts inside it:
// relax() (below) is such a solve for the end state, a Newton iteration on the same energies with
// the body's contacts as an active set; dress() runs it after the drape.
// Tried and left out: over-relaxing the λ update (ω = 1.5 blows up within two frames) and
// warm-starting each sub-step from a fraction β of the previous multipliers (β = 0.5 halves the
// stretch, β ≥ 0.9 blows up).
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/core/vec3.h>
#include <tapeline/garment/bending.h>
#include <tapeline/garment/collider.h>
#include <tapeline/garment/crossings.h>
#include <tapeline/garment/drape_types.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <Eigen/CholmodSupport>
#include <Eigen/Sparse>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace tapeline::garment {

namespace internal {

// A spatial hash of points (Teschner et al. 2003): cubic cells of a given size hashed into twice
// as many buckets as points, counting-sorted so that each bucket lists its points in index order
// (deterministic whatever the thread count). A bucket also holds points of other cells that hash
// alike: compare `cell`.
struct PointHash {
    using Cell = std::array<std::int64_t, 3>;
    double inv_cell = 1;
    std::size_t buckets = 1;
    std::vector<Cell> cell;             // per point
    std::vector<std::uint32_t> start;   // per bucket: where its points begin in `points`; + end
    std::vector<std::uint32_t> points;  // point indices, bucket by bucket
    std::vector<std::uint32_t> bucket;  // per point (scratch)

    Cell cell_of(const Vec3& p) const {
        return {static_cast<std::int64_t>(std::floor(p[0] * inv_cell)),
                static_cast<std::int64_t>(std::floor(p[1] * inv_cell)),
                static_cast<std::int64_t>(std::floor(p[2] * inv_cell))};
    }
    std::size_t bucket_of(const Cell& c) const {
        const std::uint64_t hsh = static_cast<std::uint64_t>(c[0]) * 73856093u ^
                                  static_cast<std::uint64_t>(c[1]) * 19349663u ^
                                  static_cast<std::uint64_t>(c[2]) * 83492791u;
        return static_cast<std::size_t>(hsh & (buckets - 1));
    }
    // Calls f(point, cell) for every point hashed in a cell from lo to hi (cell coordinates),
    // cell by cell, each bucket in index order; points of other cells met in a bucket are skipped.
    template <typename F>
    void for_each_in_cells(const Cell& lo, const Cell& hi, F&& f) const {
        for (std::int64_t i = lo[0]; i <= hi[0]; ++i) {
            for (std::int64_t j = lo[1]; j <= hi[1]; ++j) {
                for (std::int64_t k = lo[2]; k <= hi[2]; ++k) {
                    const Cell c{i, j, k};
                    const std::size_t bk = bucket_of(c);
                    for (std::uint32_t q = start[bk]; q < start[bk + 1]; ++q) {
                        if (cell[points[q]] == c) {
                            f(points[q]);
                        }
                    }
                }
            }
        }
    }
    // Hashes p[i] for every i with kept[i] (every i when `kept` is empty).
    void build(const std::vector<Vec3>& p, double cell_size,
               const std::vector<std::uint8_t>& kept = {}) {
        const std::size_t n = p.size();
        inv_cell = 1 / cell_size;
        buckets = 1;
        while (buckets < 2 * n) {
            buckets <<= 1;
        }
        cell.resize(n);
        bucket.resize(n);
        start.assign(buckets + 1, 0);
        const auto in = [&](std::size_t i) { return kept.empty() || kept[i]; };
        for (std::size_t i = 0; i < n; ++i) {
            if (in(i)) {
                cell[i] = cell_of(p[i]);
                bucket[i] = static_cast<std::uint32_t>(bucket_of(cell[i]));
                ++start[bucket[i] + 1];
            }
        }
        for (std::size_t b = 0; b < buckets; ++b) {
            start[b + 1] += start[b];
        }
        points.resize(start[buckets]);
        std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
        for (std::size_t i = 0; i < n; ++i) {
            if (in(i)) {
                points[fill[bucket[i]]++] = static_cast<std::uint32_t>(i);
            }
        }
    }
};

}  // namespace internal

/// XPBD cloth solver (see the header comment for the model, units and papers).
class DrapeSolver {
public:
    /// Validates everything and precomputes masses, rest shapes and constraint colours. Throws
    /// InvalidInput naming the triangle, vertex or field. `collider` (may be null) must outlive
    /// the solver.
    DrapeSolver(ClothModel cloth, FabricParams fabric, DrapeOptions options,
                const Collider* collider = nullptr);

    /// Advances one frame (options().frame_seconds). Throws SolverFailure("frame N: ...") when a
    /// position is not finite, a speed exceeds max_speed_mm_s or the kinetic energy explodes; the
    /// state is then unusable until reset().
    StepReport step();

    /// Replaces the attachments; they act from the next step. Throws InvalidInput naming the
    /// attachment when its vertex is out of range, its target is not finite or its compliance
    /// is not finite and >= 0.
    void set_attachments(std::vector<Attachment> attachments);
    /// Replaces the stitches; they act from the next step. Throws InvalidInput naming the stitch
    /// when a vertex is out of range, it joins a vertex to itself, or its rest_mm or compliance
    /// is not finite and >= 0.
    void set_stitches(std::vector<Stitch> stitches);

    /// Current vertex positions, mm, in the order of the model's vertices.
    const std::vector<Vec3>& positions() const { return x_; }
    /// The cloth's mass, kg: its rest area times the fabric's areal density (the vertices'
    /// lumped masses summed).
    double total_mass_kg() const {
        double m = 0;
        for (double v : mass_) {
            m += v;
        }
        return m;
    }
    /// Current vertex velocities, mm/s.
    const std::vector<Vec3>& velocities() const { return v_; }
    /// The cloth as given to the constructor (reset() returns to its positions).
    const ClothModel& model() const { return model_; }
    /// The fabric as given to the constructor.
    const FabricParams& fabric() const { return fabric_; }
    /// The options as given to the constructor, with the damping of the last set_damping().
    const DrapeOptions& options() const { return options_; }

    /// Velocity damping rate from the next step on (fraction lost per second; finite, >= 0).
    /// Damping changes how fast the cloth comes to rest, not where.
    void set_damping(double per_second) {
        if (!(std::isfinite(per_second) && per_second >= 0)) {
            throw InvalidInput("DrapeSolver: damping must be finite and >= 0, got " +
                               std::to_string(per_second));
        }
        options_.damping_per_second = per_second;
    }

    /// Untangling from the next step on (DrapeOptions::untangle). Its moves go on as long as
    /// crossings are left, so cloth that keeps some does not come to rest while it is on.
    void set_untangle(bool on) { options_.untangle = on; }

    /// The body's vertices with their outward unit normals (the collider's frame, mm), for
    /// relax(): the cloth triangle over each, met by the line along its normal from `reach_mm`
    /// below it to the clearance plus `reach_mm` above, is held at half the clearance above it
    /// (as the edge midpoints are against the collider). A
    /// bump of the body narrower than the cloth's edges (a nipple, a knuckle) then cannot poke
    /// through a triangle between the cloth's vertices, which the contacts at the vertices and
    /// edge midpoints against a collider's grid (that rounds such a bump off) let happen.
    /// `reach_mm` bounds how far below a body vertex a triangle may have sunk and still be
    /// pushed out: about the grid's cell. Replaces the last call's points; none: call with
    /// empty vectors. Throws InvalidInput naming the point when the sizes differ, a point or a
    /// normal is not finite, a normal is not of unit length (within 1e-6), or `reach_mm` is
    /// not finite and > 0.
    void set_body_points(std::vector<Vec3> points, std::vector<Vec3> normals, double reach_mm);

    /// Back to the initial positions, zero velocity, frame 0 (attachments and stitches stay).
    void reset();

    /// Looks for the static equilibrium from the current state: where the fabric's stretch,
    /// shear and bending, the stitches, the attachments, gravity and the body's push balance
    /// (damped Newton iterations on the same energies the constraints stand for; see the comment
    /// above its definition). Velocities become zero. Cloth–cloth contact and friction take no
    /// part in it. Throws InvalidInput on bad options.
    RelaxReport relax(const RelaxOptions& options = {});

    /// Flattens the cloth's fold-overs: where an edge crosses a triangle (find the crossings as
    /// the untangling does), the vertices of both and `rings` rings around them are smoothed
    /// (each moved halfway to the mean of its neighbours, a border vertex to the mean of its
    /// neighbours along the border; pinned vertices stay) and kept at the clearance from the
    /// body; then the crossings are found again, up to `max_rounds` times. Meant for the end of
    /// a drape, where cloth compressed at a finer scale than its edges has folded over itself
    /// one or two edges wide: a fold the mesh cannot hold without crossing itself. Velocities
    /// become zero. Throws InvalidInput on bad options.
    FoldReport smooth_fold_overs(const FoldOptions& options = {});

private:
    struct TriangleConstraint {
        std::uint32_t v[3];
        double c1[3], c2[3];  // F·e_warp = Σ c1_i x_i, F·e_weft = Σ c2_i x_i
        double alpha_warp, alpha_weft, alpha_shear;  // compliance; < 0: no constraint
        double area;                                 // rest area, mm²
    };
    struct BendConstraint {
        std::uint32_t v[4];  // wing of triangle A, wing of triangle B, edge start, edge end
        double alpha;
    };
    struct SelfContact {
        std::uint32_t v, t;
        double b[3];
        Vec3 n;  // unit, pointing to the vertex's side
    };
    struct EdgeEdgeContact {
        std::uint32_t e, f;  // edge_list_ indices
        double s, t;         // closest points: (1 − s)·a + s·b on e, (1 − t)·c + t·d on f
        Vec3 n;              // unit, from f's point to e's point at the sub-step's start
    };
    using Colouring = std::vector<std::vector<std::uint32_t>>;  // constraint ids per colour

    template <typename VertexOf>
    static Colouring colour(std::size_t count, int arity, std::size_t vertex_count,
                            VertexOf vertex_of);
    template <typename F>
    void for_each_coloured(const Colouring& colours, F&& f);
    void substep(double h, std::size_t frame_number);
    void sweep_body(std::size_t i);
    bool first_hit(std::size_t i);
    bool contact_body(std::size_t i);
    void contact_edges();
    void detect_self_contacts();
    void detect_edge_edge_contacts();
    void solve_self_contacts();
    std::size_t untangle();
    std::vector<std::pair<std::uint32_t, std::uint32_t>> find_crossings();
    bool near_in_rest(std::uint32_t u, std::uint32_t v) const;
    bool stitched(std::uint32_t u, std::uint32_t v) const;
    void project_triangle(std::size_t t, double h);
    void project_bend(std::size_t e, double h);
    void project_stitch(std::size_t s, double h);
    void project_attachment(std::size_t a, double h);
    void update_tethers();
    [[noreturn]] void fail(std::size_t frame_number, const std::string& what);

    ClothModel model_;
    FabricParams fabric_;
    DrapeOptions options_;
    const Collider* collider_;
    double clearance_ = 0;  // distance kept from the collider (options or the thickness)
    std::vector<Vec3> body_points_, body_normals_;  // set_body_points(), for relax()
    double body_reach_ = 0;
    std::unique_ptr<tbb::task_arena> arena_;

    std::vector<Vec3> x_, v_, p_;
    std::vector<double> mass_, w_;
    std::vector<TriangleConstraint> tris_;
    std::vector<BendConstraint> bends_;
    std::vector<Attachment> attachments_;
    std::vector<Stitch> stitches_;
    std::vector<double> stitch_alpha_, attachment_alpha_;
    Colouring tri_colours_, bend_colours_, stitch_colours_;
    std::vector<double> lambda_tri_, lambda_bend_, lambda_stitch_, lambda_attachment_;
    std::vector<std::uint32_t> neighbour_start_, neighbours_;            // one-ring, CSR, sorted
    std::vector<std::pair<std::uint32_t, std::uint32_t>> stitch_pairs_;  // both ways, sorted
    std::vector<std::uint8_t> in_contact_;
    std::vector<double> rest_edge_length_;      // per neighbours_ entry: rest length, mm
    std::vector<std::uint32_t> tether_anchor_;  // per vertex: its anchor (itself: none)
    std::vector<double> tether_limit_;          // per vertex: tether_stretch × rest distance
    std::size_t tether_anchors_ = 0;
    std::vector<double> start_distance_;  // collider distance at the sub-step's start
    std::vector<double> end_distance_;    // after the last contact pass (a lower bound)
    std::vector<Vec3> end_normal_;        // collider gradient there
    struct EdgeContact {
        std::uint32_t a, b;
        double t;
    };
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edge_list_;  // each edge once, a < b
    static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::array<std::uint32_t, 2>> edge_tris_;  // per edge_list_ entry (kNone: none)
    std::vector<std::uint8_t> tangled_;  // per vertex: on a crossing found at the frame's start
    std::vector<std::vector<EdgeContact>> edge_blocks_;
    std::vector<SelfContact> self_contacts_;
    std::vector<std::vector<SelfContact>> self_blocks_;
    std::vector<EdgeEdgeContact> edge_edge_contacts_;
    std::vector<std::vector<EdgeEdgeContact>> edge_edge_blocks_;
    internal::PointHash vertex_hash_;    // predicted vertex positions, cell hash_cell_
    internal::PointHash edge_hash_;      // predicted edge midpoints (edge–edge pairs)
    internal::PointHash crossing_hash_;  // edge midpoints at the frame's start (untangle())
    std::vector<Vec3> edge_mid_;
    std::vector<std::uint8_t> edge_kept_;
    double hash_cell_ = 1;
    std::size_t frame_ = 0;
    bool failed_ = false;
};

// ---------------------------------------------------------------------------------------------

namespace internal {

// The bounding box of a triangle grown by `margin` on every side.
inline std::pair<Vec3, Vec3> triangle_box(const Vec3& a, const Vec3& b, const Vec3& c,
                                          double margin) {
    Vec3 lo, hi;
    for (int k = 0; k < 3; ++k) {
        lo[k] = std::min({a[k], b[k], c[k]}) - margin;
        hi[k] = std::max({a[k], b[k], c[k]}) + margin;
    }
    return {lo, hi};
}

inline bool finite3(const Vec3& p) {
    return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

// Parameters (s, t) of the closest points p0 + s·(p1 − p0) and q0 + t·(q1 − q0) of two segments
// (Ericson, "Real-Time Collision Detection", 5.1.9); degenerate segments are points.
inline std::pair<double, double> closest_segment_params(const Vec3& p0, const Vec3& p1,
                                                        const Vec3& q0, const Vec3& q1) {
    using namespace tapeline::vec3;
    const Vec3 d1 = sub(p1, p0), d2 = sub(q1, q0), r = sub(p0, q0);
    const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
    const double eps = 1e-18;
    if (a <= eps && e <= eps) {
        return {0, 0};
    }
    double s = 0, t = 0;
    if (a <= eps) {
        t = std::clamp(f / e, 0.0, 1.0);
    } else {
        const double c = dot(d1, r);
        if (e <= eps) {
            s = std::clamp(-c / a, 0.0, 1.0);
        } else {
            const double b = dot(d1, d2), denom = a * e - b * b;
            s = denom > eps * a * e ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
            t = (b * s + f) / e;
            if (t < 0) {
                t = 0;
                s = std::clamp(-c / a, 0.0, 1.0);
            } else if (t > 1) {
                t = 1;
                s = std::clamp((b - c) / a, 0.0, 1.0);
            }
        }
    }
    return {s, t};
}

// Closest point of triangle (a, b, c) to p as barycentric coordinates (Ericson, "Real-Time
// Collision Detection", 5.1.5).
inline std::array<double, 3> closest_barycentric(const Vec3& p, const Vec3& a, const Vec3& b,
                                                 const Vec3& c) {
    using namespace tapeline::vec3;
    const Vec3 ab = sub(b, a), ac = sub(c, a), ap = sub(p, a);
    const double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) {
        return {1, 0, 0};
    }
    const Vec3 bp = sub(p, b);
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) {
        return {0, 1, 0};
    }
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) {
        const double v = d1 / (d1 - d3);
        return {1 - v, v, 0};
    }
    const Vec3 cp = sub(p, c);
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) {
        return {0, 0, 1};
    }
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) {
        const double w = d2 / (d2 - d6);
        return {1 - w, 0, w};
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
        const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return {0, 1 - w, w};
    }
    const double denom = 1 / (va + vb + vc);
    const double v = vb * denom, w = vc * denom;
    return {1 - v - w, v, w};
}

// Dihedral angle of the hinge with wings x1, x2 across the edge (x3, x4), zero when flat, and its
// gradients with respect to x1..x4 (Bridson, Marino, Fedkiw 2003); false when the hinge is
// degenerate.
inline bool dihedral(const Vec3& x1, const Vec3& x2, const Vec3& x3, const Vec3& x4, double& theta,
                     Vec3 g[4]) {
    using namespace tapeline::vec3;
    const Vec3 edge = sub(x4, x3);
    const double el = norm(edge);
    const Vec3 n1 = cross(sub(x1, x3), sub(x1, x4)), n2 = cross(sub(x2, x4), sub(x2, x3));
    const double n1l2 = dot(n1, n1), n2l2 = dot(n2, n2);
    if (el < 1e-12 || n1l2 < 1e-24 || n2l2 < 1e-24) {
        return false;
    }
    const Vec3 ee = scale(edge, 1 / el);
    const Vec3 m1 = scale(n1, 1 / std::sqrt(n1l2)), m2 = scale(n2, 1 / std::sqrt(n2l2));
    theta = std::atan2(dot(cross(m2, m1), ee), dot(m1, m2));
    const Vec3 a1 = scale(n1, 1 / n1l2), a2 = scale(n2, 1 / n2l2);
    g[0] = scale(a1, el);
    g[1] = scale(a2, el);
    g[2] = add(scale(a1, dot(sub(x1, x4), ee)), scale(a2, dot(sub(x2, x4), ee)));
    g[3] = scale(add(scale(a1, dot(sub(x1, x3), ee)), scale(a2, dot(sub(x2, x3), ee))), -1);
    return true;
}

}  // namespace internal

inline DrapeSolver::DrapeSolver(ClothModel cloth, FabricParams fabric, DrapeOptions options,
                                const Collider* collider)
    : model_(std::move(cloth)), fabric_(std::move(fabric)), options_(options), collider_(collider) {
    using namespace tapeline::vec3;
    const std::string where = "DrapeSolver: ";
    auto num = [](double v) { return std::to_string(v); };
    // Options.
    if (!(std::isfinite(options_.frame_seconds) && options_.frame_seconds > 0)) {
        throw InvalidInput(where + "options.frame_seconds must be finite and > 0, got " +
                           num(options_.frame_seconds));
    }
    if (options_.substeps < 1) {
        throw InvalidInput(where + "options.substeps must be >= 1, got " +
                           std::to_string(options_.substeps));
    }
    if (options_.iterations < 1) {
        throw InvalidInput(where + "options.iterations must be >= 1, got " +
                           std::to_string(options_.iterations));
    }
    if (!internal::finite3(options_.gravity)) {
        throw InvalidInput(where + "options.gravity is not finite");
    }
    if (!(std::isfinite(options_.body_clearance_mm) && options_.body_clearance_mm >= 0)) {
        throw InvalidInput(where + "options.body_clearance_mm must be finite and >= 0, got " +
                           num(options_.body_clearance_mm));
    }
    if (!(std::isfinite(options_.tether_stretch) &&
          (options_.tether_stretch == 0 || options_.tether_stretch >= 1))) {
        throw InvalidInput(where + "options.tether_stretch must be 0 (no tethers) or >= 1, got " +
                           num(options_.tether_stretch));
    }
    if (!(std::isfinite(options_.damping_per_second) && options_.damping_per_second >= 0)) {
        throw InvalidInput(where + "options.damping_per_second must be finite and >= 0, got " +
                           num(options_.damping_per_second));
    }
    if (options_.threads < 0) {
        throw InvalidInput(where + "options.threads must be >= 0, got " +
                           std::to_string(options_.threads));
    }
    if (!(options_.max_speed_mm_s > 0)) {
        throw InvalidInput(where + "options.max_speed_mm_s must be > 0, got " +
                           num(options_.max_speed_mm_s));
    }
    if (!(options_.max_energy_growth > 0)) {
        throw InvalidInput(where + "options.max_energy_growth must be > 0, got " +
                           num(options_.max_energy_growth));
    }
    // Fabric.
    const std::pair<const char*, double> fabric_fields[] = {
        {"density_g_m2", fabric_.density_g_m2},
        {"stretch_warp_n_m", fabric_.stretch_warp_n_m},
        {"stretch_weft_n_m", fabric_.stretch_weft_n_m},
        {"shear_n_m", fabric_.shear_n_m},
        {"bending_un_m", fabric_.bending_un_m},
        {"friction", fabric_.friction},
        {"thickness_mm", fabric_.thickness_mm}};
    for (const auto& [name, value] : fabric_fields) {
        if (!(std::isfinite(value) && value >= 0)) {
            throw InvalidInput(where + "fabric." + name + " must be finite and >= 0, got " +
                               num(value));
        }
    }
    if (!(fabric_.density_g_m2 > 0)) {
        throw InvalidInput(where + "fabric.density_g_m2 must be > 0");
    }
    clearance_ = options_.body_clearance_mm > 0 ? options_.body_clearance_mm : fabric_.thickness_mm;
    // Cloth.
    const std::size_t n = model_.positions.size(), nt = model_.triangles.size();
    if (n == 0 || nt == 0) {
        throw InvalidInput(where + "empty cloth (" + std::to_string(n) + " vertices, " +
                           std::to_string(nt) + " triangles)");
    }
    if (n >= std::numeric_limits<std::uint32_t>::max()) {
        throw InvalidInput(where + "too many vertices");
    }
    if (model_.rest_uv.size() != nt) {
        throw InvalidInput(where + "rest_uv has " + std::to_string(model_.rest_uv.size()) +
                           " entries for " + std::to_string(nt) + " triangles");
    }
    if (model_.grain.size() != nt) {
        throw InvalidInput(where + "grain has " + std::to_string(model_.grain.size()) +
                           " entries for " + std::to_string(nt) + " triangles");
    }
    if (!model_.pinned.empty() && model_.pinned.size() != n) {
        throw InvalidInput(where + "pinned has " + std::to_string(model_.pinned.size()) +
                           " entries for " + std::to_string(n) + " vertices");
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (!internal::finite3(model_.positions[i])) {
            throw InvalidInput(where + "vertex " + std::to_string(i) +
                               " has a non-finite position " +
                               internal::vec_to_string(model_.positions[i]));
        }
    }
    mass_.assign(n, 0.0);
    tris_.resize(nt);
    for (std::size_t t = 0; t < nt; ++t) {
        const Tri& tri = model_.triangles[t];
        const std::string name = "triangle " + std::to_string(t);
        for (std::uint32_t v : tri) {
            if (v >= n) {
                throw InvalidInput(where + name + " has vertex index " + std::to_string(v) +
                                   " out of range (" + std::to_string(n) + " vertices)");
            }
        }
        if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) {
            throw InvalidInput(where + name + " repeats a vertex");
        }
        const UV g0 = model_.grain[t];
        const double glen = std::hypot(g0[0], g0[1]);
        if (!(std::isfinite(glen) && glen > 1e-12)) {
            throw InvalidInput(where + name + ": grain direction is zero or not finite");
        }
        const UV g{g0[0] / glen, g0[1] / glen}, gp{-g[1], g[0]};
        double a[3][2];
        double longest = 0;
        for (int c = 0; c < 3; ++c) {
            const UV& u = model_.rest_uv[t][c];
            if (!std::isfinite(u[0]) || !std::isfinite(u[1])) {
                throw InvalidInput(where + name + ": rest_uv corner " + std::to_string(c) +
                                   " is not finite");
            }
            a[c][0] = u[0] * g[0] + u[1] * g[1];    // warp coordinate
            a[c][1] = u[0] * gp[0] + u[1] * gp[1];  // weft coordinate
        }
        const double m00 = a[1][0] - a[0][0], m10 = a[1][1] - a[0][1];
        const double m01 = a[2][0] - a[0][0], m11 = a[2][1] - a[0][1];
        for (int c = 0; c < 3; ++c) {
            const int d = (c + 1) % 3;
            longest = std::max(longest, std::hypot(a[d][0] - a[c][0], a[d][1] - a[c][1]));
        }
        const double det = m00 * m11 - m01 * m10;
        const double area = 0.5 * std::abs(det);
        // Relative test: a sliver whose area is a millionth of its longest edge squared has an
        // ill-conditioned Dm⁻¹ and would make its constraints infinitely stiff.
        if (!(area > 1e-6 * longest * longest) || !(area > 0)) {
            throw InvalidInput(where + name + ": degenerate rest triangle (area " + num(area) +
                               " mm², longest edge " + num(longest) + " mm)");
        }
        const double i00 = m11 / det, i01 = -m01 / det, i10 = -m10 / det, i11 = m00 / det;
        TriangleConstraint& tc = tris_[t];
        for (int c = 0; c < 3; ++c) {
            tc.v[c] = tri[c];
        }
        tc.c1[0] = -(i00 + i10);
        tc.c1[1] = i00;
        tc.c1[2] = i10;
        tc.c2[0] = -(i01 + i11);
        tc.c2[1] = i01;
        tc.c2[2] = i11;
        auto compliance = [&](double k) { return k > 0 ? 1.0 / (k * area) : -1.0; };
        tc.alpha_warp = compliance(fabric_.stretch_warp_n_m);
        tc.alpha_weft = compliance(fabric_.stretch_weft_n_m);
        tc.alpha_shear = compliance(fabric_.shear_n_m);
        tc.area = area;
        for (std::uint32_t v : tri) {
            mass_[v] += fabric_.density_g_m2 * 1e-9 * area / 3;
        }
    }
    w_.assign(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        const bool pinned = !model_.pinned.empty() && model_.pinned[i];
        // A vertex in no triangle has no mass: it stays put like a pinned one.
        w_[i] = (pinned || mass_[i] <= 0) ? 0.0 : 1.0 / mass_[i];
    }

    // Edges: one-ring neighbours, and bending across each edge shared by exactly two triangles.
    struct HalfEdge {
        std::uint64_t key;
        std::uint32_t t, opposite;
        bool operator<(const HalfEdge& o) const { return key < o.key || (key == o.key && t < o.t); }
    };
    std::vector<HalfEdge> half;
    half.reserve(3 * nt);
    for (std::size_t t = 0; t < nt; ++t) {
        for (int c = 0; c < 3; ++c) {
            std::uint64_t a = model_.triangles[t][c], b = model_.triangles[t][(c + 1) % 3];
            if (a > b) {
                std::swap(a, b);
            }
            half.push_back(
                {(a << 32) | b, static_cast<std::uint32_t>(t), model_.triangles[t][(c + 2) % 3]});
        }
    }
    std::sort(half.begin(), half.end());
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    for (std::size_t e = 0; e < half.size();) {
        std::size_t f = e;
        while (f < half.size() && half[f].key == half[e].key) {
            ++f;
        }
        const auto a = static_cast<std::uint32_t>(half[e].key >> 32);
        const auto b = static_cast<std::uint32_t>(half[e].key & 0xffffffffu);
        edges.emplace_back(a, b);
        edges.emplace_back(b, a);
        edge_tris_.push_back({half[e].t, f - e > 1 ? half[e + 1].t : kNone});
        if (f - e == 2 && (fabric_.bending_un_m > 0 || bending_weft_of(fabric_) > 0 ||
                           bending_bias_of(fabric_) > 0)) {
            const double area_e = tris_[half[e].t].area + tris_[half[e + 1].t].area;
            // Rest length of the edge from the rest shape of the first triangle.
            const Tri& tri = model_.triangles[half[e].t];
            int ca = 0, cb = 0;
            for (int c = 0; c < 3; ++c) {
                if (tri[c] == a) {
                    ca = c;
                }
                if (tri[c] == b) {
                    cb = c;
                }
            }
            const UV& ua = model_.rest_uv[half[e].t][ca];
            const UV& ub = model_.rest_uv[half[e].t][cb];
            const UV g0 = model_.grain[half[e].t];
            const double glen = std::hypot(g0[0], g0[1]);
            const double k = hinge_stiffness_un_m(fabric_, UV{ub[0] - ua[0], ub[1] - ua[1]},
                                                  UV{g0[0] / glen, g0[1] / glen}, area_e);
            if (k > 0) {
                bends_.push_back({{half[e].opposite, half[e + 1].opposite, a, b}, 1.0 / k});
            }
        }
        e = f;
    }
    std::sort(edges.begin(), edges.end());
    for (const auto& [a, b] : edges) {
        if (a < b) {
            edge_list_.emplace_back(a, b);
        }
    }
    neighbour_start_.assign(n + 1, 0);
    for (const auto& [a, b] : edges) {
        ++neighbour_start_[a + 1];
    }
    for (std::size_t i = 0; i < n; ++i) {
        neighbour_start_[i + 1] += neighbour_start_[i];
    }
    neighbours_.resize(edges.size());
    for (std::size_t k = 0; k < edges.size(); ++k) {
        neighbours_[k] = edges[k].second;  // sorted by (a, b): CSR rows come out sorted
    }
    // Rest length of every CSR entry (the shortest over the triangles sharing the edge).
    rest_edge_length_.assign(neighbours_.size(), std::numeric_limits<double>::infinity());
    for (std::size_t t = 0; t < nt; ++t) {
        for (int c = 0; c < 3; ++c) {
            const std::uint32_t a = model_.triangles[t][c], b = model_.triangles[t][(c + 1) % 3];
            const UV& ua = model_.rest_uv[t][c];
            const UV& ub = model_.rest_uv[t][(c + 1) % 3];
            const double len = std::hypot(ub[0] - ua[0], ub[1] - ua[1]);
            for (const auto& [from, to] : {std::make_pair(a, b), std::make_pair(b, a)}) {
                const auto first = neighbours_.begin() + neighbour_start_[from];
                const auto last = neighbours_.begin() + neighbour_start_[from + 1];
                const auto it = std::lower_bound(first, last, to);
                double& rest = rest_edge_length_[std::size_t(it - neighbours_.begin())];
                rest = std::min(rest, len);
            }
        }
    }
    tether_anchor_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        tether_anchor_[i] = static_cast<std::uint32_t>(i);
    }
    tether_limit_.assign(n, 0.0);
    double edge_sum = 0;
    for (std::size_t k = 0; k < edges.size(); ++k) {
        edge_sum += norm(sub(model_.positions[edges[k].first], model_.positions[edges[k].second]));
    }
    const double mean_edge = edges.empty() ? 1.0 : edge_sum / edges.size();
    hash_cell_ = std::max({mean_edge, 2 * fabric_.thickness_mm, 1e-6});

    tri_colours_ = colour(tris_.size(), 3, n, [&](std::size_t c, int k) { return tris_[c].v[k]; });
    bend_colours_ =
        colour(bends_.size(), 4, n, [&](std::size_t c, int k) { return bends_[c].v[k]; });
    lambda_tri_.assign(3 * tris_.size(), 0.0);
    lambda_bend_.assign(bends_.size(), 0.0);
    in_contact_.assign(n, 0);
    start_distance_.assign(n, 0.0);
    end_distance_.assign(n, 0.0);
    end_normal_.assign(n, Vec3{0, 0, 0});
    arena_ = std::make_unique<tbb::task_arena>(
        options_.threads > 0 ? options_.threads : static_cast<int>(tbb::task_arena::automatic));
    reset();
    if (options_.tether_stretch > 0) {
        update_tethers();  // after reset(): it sizes the vertex arrays
    }
}

template <typename VertexOf>
inline DrapeSolver::Colouring DrapeSolver::colour(std::size_t count, int arity,
                                                  std::size_t vertex_count, VertexOf vertex_of) {
    // Greedy, in index order: deterministic. Colours beyond 63 (a vertex of huge valence) go to
    // the last group, which is processed serially.
    std::vector<std::uint64_t> used(vertex_count, 0);
    Colouring colours;
    std::vector<std::uint32_t> serial;
    for (std::size_t c = 0; c < count; ++c) {
        std::uint64_t taken = 0;
        for (int k = 0; k < arity; ++k) {
            taken |= used[vertex_of(c, k)];
        }
        if (~taken == 0) {
            serial.push_back(static_cast<std::uint32_t>(c));
            continue;
        }
        int bit = 0;
        while (taken & (std::uint64_t{1} << bit)) {
            ++bit;
        }
        for (int k = 0; k < arity; ++k) {
            used[vertex_of(c, k)] |= std::uint64_t{1} << bit;
        }
        if (colours.size() <= static_cast<std::size_t>(bit)) {
            colours.resize(bit + 1);
        }
        colours[bit].push_back(static_cast<std::uint32_t>(c));
    }
    if (!serial.empty()) {
        colours.push_back(std::move(serial));
        colours.emplace_back();  // marker: the group before an empty one is serial
    }
    return colours;
}

template <typename F>
inline void DrapeSolver::for_each_coloured(const Colouring& colours, F&& f) {
    for (std::size_t c = 0; c < colours.size(); ++c) {
        const auto& ids = colours[c];
        const bool serial = c + 1 < colours.size() && colours[c + 1].empty();
        if (serial || ids.size() < 512) {
            for (std::uint32_t id : ids) {
                f(id);
            }
        } else {
            tbb::parallel_for(tbb::blocked_range<std::size_t>(0, ids.size(), 256),
                              [&](const tbb::blocked_range<std::size_t>& r) {
                                  for (std::size_t k = r.begin(); k != r.end(); ++k) {
                                      f(ids[k]);
                                  }
                              });
        }
    }
}

inline void DrapeSolver::set_attachments(std::vector<Attachment> attachments) {
    for (std::size_t a = 0; a < attachments.size(); ++a) {
        const Attachment& at = attachments[a];
        const std::string name = "DrapeSolver: attachment " + std::to_string(a);
        if (at.vertex >= x_.size()) {
            throw InvalidInput(name + ": vertex " + std::to_string(at.vertex) + " out of range (" +
                               std::to_string(x_.size()) + " vertices)");
        }
        if (!internal::finite3(at.target)) {
            throw InvalidInput(name + ": target is not finite");
        }
        if (!(std::isfinite(at.compliance) && at.compliance >= 0)) {
            throw InvalidInput(name + ": compliance must be finite and >= 0");
        }
        const double axis_length = vec3::norm(at.axis);
        if (!internal::finite3(at.axis) ||
            !(axis_length == 0 || std::abs(axis_length - 1) <= 1e-9)) {
            throw InvalidInput(name + ": axis must be zero or a unit vector, its length is " +
                               std::to_string(axis_length));
        }
    }
    attachments_ = std::move(attachments);
    attachment_alpha_.resize(attachments_.size());
    for (std::size_t a = 0; a < attachments_.size(); ++a) {
        attachment_alpha_[a] = attachments_[a].compliance * 1e-3;
    }
    lambda_attachment_.assign(attachments_.size(), 0.0);
}

inline void DrapeSolver::set_stitches(std::vector<Stitch> stitches) {
    for (std::size_t s = 0; s < stitches.size(); ++s) {
        const Stitch& st = stitches[s];
        const std::string name = "DrapeSolver: stitch " + std::to_string(s);
        if (st.a >= x_.size() || st.b >= x_.size()) {
            throw InvalidInput(name + ": vertex " + std::to_string(std::max(st.a, st.b)) +
                               " out of range (" + std::to_string(x_.size()) + " vertices)");
        }
        if (st.a == st.b) {
            throw InvalidInput(name + " joins vertex " + std::to_string(st.a) + " to itself");
        }
        if (!(std::isfinite(st.rest_mm) && st.rest_mm >= 0)) {
            throw InvalidInput(name + ": rest_mm must be finite and >= 0");
        }
        if (!(std::isfinite(st.compliance) && st.compliance >= 0)) {
            throw InvalidInput(name + ": compliance must be finite and >= 0");
        }
    }
    stitches_ = std::move(stitches);
    stitch_alpha_.resize(stitches_.size());
    for (std::size_t s = 0; s < stitches_.size(); ++s) {
        stitch_alpha_[s] = stitches_[s].compliance * 1e-3;
    }
    stitch_colours_ = colour(stitches_.size(), 2, x_.size(), [&](std::size_t c, int k) {
        return k == 0 ? stitches_[c].a : stitches_[c].b;
    });
    lambda_stitch_.assign(stitches_.size(), 0.0);
    stitch_pairs_.clear();
    for (const Stitch& st : stitches_) {
        stitch_pairs_.emplace_back(st.a, st.b);
        stitch_pairs_.emplace_back(st.b, st.a);
    }
    std::sort(stitch_pairs_.begin(), stitch_pairs_.end());
    if (options_.tether_stretch > 0) {
        update_tethers();  // stitches shorten the rest paths
    }
}

inline void DrapeSolver::set_body_points(std::vector<Vec3> points, std::vector<Vec3> normals,
                                         double reach_mm) {
    if (points.size() != normals.size()) {
        throw InvalidInput("DrapeSolver::set_body_points: " + std::to_string(points.size()) +
                           " points but " + std::to_string(normals.size()) + " normals");
    }
    if (!(std::isfinite(reach_mm) && reach_mm > 0)) {
        throw InvalidInput("DrapeSolver::set_body_points: reach_mm must be finite and > 0, got " +
                           std::to_string(reach_mm));
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
        const Vec3 &p = points[i], &nn = normals[i];
        const bool finite = std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]) &&
                            std::isfinite(nn[0]) && std::isfinite(nn[1]) && std::isfinite(nn[2]);
        if (!finite || std::abs(vec3::norm(nn) - 1) > 1e-6) {
            throw InvalidInput("DrapeSolver::set_body_points: point " + std::to_string(i) +
                               (finite ? ": its normal is not of unit length" : ": not finite"));
        }
    }
    body_points_ = std::move(points);
    body_normals_ = std::move(normals);
    body_reach_ = reach_mm;
}

inline void DrapeSolver::reset() {
    x_ = model_.positions;
    p_ = x_;
    v_.assign(x_.size(), Vec3{0, 0, 0});
    if (collider_) {
        // Vertices the contact pass skips (pinned, massless) keep these; the others are
        // refreshed by every contact pass.
        for (std::size_t i = 0; i < x_.size(); ++i) {
            end_distance_[i] = collider_->signed_distance(x_[i], &end_normal_[i]);
        }
    }
    frame_ = 0;
    failed_ = false;
}

inline void DrapeSolver::fail(std::size_t frame_number, const std::string& what) {
    failed_ = true;
    throw SolverFailure("frame " + std::to_string(frame_number) + ": " + what);
}

inline StepReport DrapeSolver::step() {
    using namespace tapeline::vec3;
    const auto start = std::chrono::steady_clock::now();
    const std::size_t frame_number = frame_ + 1;
    if (failed_) {
        throw SolverFailure("frame " + std::to_string(frame_number) +
                            ": the solver failed earlier; call reset()");
    }
    const std::size_t n = x_.size();
    const std::vector<Vec3> x_start = x_;
    double ke_start = 0, gravity_work = 0, total_mass = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (w_[i] > 0) {
            ke_start += 0.5 * mass_[i] * dot(v_[i], v_[i]);
            total_mass += mass_[i];
        }
    }
    const double h = options_.frame_seconds / options_.substeps;
    std::size_t crossings = 0;
    arena_->execute([&] {
        if (options_.self_collision && options_.untangle) {
            crossings = untangle();
        } else {
            tangled_.clear();
        }
        for (int s = 0; s < options_.substeps; ++s) {
            substep(h, frame_number);
        }
    });
    StepReport report;
    double ke = 0;
    std::size_t moving = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3 move = sub(x_[i], x_start[i]);
        const double len = norm(move);
        report.max_move_mm = std::max(report.max_move_mm, len);
        moving += len > 0.3 ? 1 : 0;
        if (w_[i] > 0) {
            ke += 0.5 * mass_[i] * dot(v_[i], v_[i]);
            gravity_work += mass_[i] * dot(options_.gravity, move);
        }
        report.contacts += in_contact_[i];
    }
    // Energy floor: the whole cloth moving at 1 m/s, so that starting from rest is no blow-up.
    const double floor = 0.5 * total_mass * 1e6;
    if (ke > options_.max_energy_growth * (ke_start + std::max(gravity_work, 0.0) + floor)) {
        fail(frame_number, "kinetic energy " + std::to_string(ke * 1e-6) + " J grew more than " +
                               std::to_string(options_.max_energy_growth) +
                               " times over the frame (blow-up; smaller frame_seconds or more "
                               "substeps)");
    }
    frame_ = frame_number;
    report.frame = frame_;
    report.simulated_seconds = frame_ * options_.frame_seconds;
    report.moving_fraction = static_cast<double>(moving) / static_cast<double>(n);
    report.kinetic_energy_j = ke * 1e-6;
    report.self_contacts = self_contacts_.size() + edge_edge_contacts_.size();
    report.cloth_crossings = crossings;
    report.tether_anchors = tether_anchors_;
    report.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}

inline void DrapeSolver::substep(double h, std::size_t frame_number) {
    using namespace tapeline::vec3;
    const std::size_t n = x_.size();
    const double keep = std::exp(-options_.damping_per_second * h);
    const Vec3 dv = scale(options_.gravity, h);
    auto parallel_vertices = [&](auto&& f) {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 512),
                          [&](const tbb::blocked_range<std::size_t>& r) {
                              for (std::size_t i = r.begin(); i != r.end(); ++i) {
                                  f(i);
                              }
                          });
    };
    parallel_vertices([&](std::size_t i) {
        if (w_[i] > 0) {
            v_[i] = add(scale(v_[i], keep), dv);
            p_[i] = add(x_[i], scale(v_[i], h));
        } else {
            v_[i] = {0, 0, 0};
            p_[i] = x_[i];
        }
        in_contact_[i] = 0;
    });
    if (collider_) {
        parallel_vertices([&](std::size_t i) { sweep_body(i); });
    }
    if (options_.self_collision) {
        detect_self_contacts();
        if (options_.edge_edge_collision) {
            detect_edge_edge_contacts();
        } else {
            edge_edge_contacts_.clear();
        }
    } else {
        self_contacts_.clear();
        edge_edge_contacts_.clear();
    }
    std::fill(lambda_tri_.begin(), lambda_tri_.end(), 0.0);
    std::fill(lambda_bend_.begin(), lambda_bend_.end(), 0.0);
    std::fill(lambda_stitch_.begin(), lambda_stitch_.end(), 0.0);
    std::fill(lambda_attachment_.begin(), lambda_attachment_.end(), 0.0);
    for (int it = 0; it < options_.iterations; ++it) {
        for_each_coloured(tri_colours_, [&](std::uint32_t t) { project_triangle(t, h); });
        for_each_coloured(bend_colours_, [&](std::uint32_t e) { project_bend(e, h); });
        for_each_coloured(stitch_colours_, [&](std::uint32_t s) { project_stitch(s, h); });
        for (std::size_t a = 0; a < attachments_.size(); ++a) {
            project_attachment(a, h);
        }
        if (tether_anchors_ > 0) {
            // Anchors are never moved here, so every vertex is independent of the others.
            parallel_vertices([&](std::size_t i) {
                const std::uint32_t a = tether_anchor_[i];
                if (a == i || w_[i] == 0) {
                    return;
                }
                const Vec3 d = sub(p_[i], p_[a]);
                const double len = norm(d);
                if (len > tether_limit_[i]) {
                    p_[i] = add(p_[a], scale(d, tether_limit_[i] / len));
                }
            });
        }
        solve_self_contacts();
        if (collider_) {
            // Last in the pass: no vertex ends the sub-step inside the body.
            // Edges first, vertices last: an edge push may move an end into the body, the vertex
            // pass (with its swept check) then has the last word.
            contact_edges();
            parallel_vertices([&](std::size_t i) {
                if (contact_body(i)) {
                    in_contact_[i] = 1;
                }
            });
        }
    }
    // Velocities from positions; the first offending vertex (lowest index) is reported.
    std::atomic<std::size_t> bad{n};
    const double inv_h = 1 / h;
    const double max_speed2 = options_.max_speed_mm_s * options_.max_speed_mm_s;
    parallel_vertices([&](std::size_t i) {
        const Vec3 v = scale(sub(p_[i], x_[i]), inv_h);
        const double s2 = dot(v, v);
        if (!(s2 <= max_speed2)) {  // NaN too
            std::size_t cur = bad.load();
            while (i < cur && !bad.compare_exchange_weak(cur, i)) {
            }
        }
        v_[i] = v;
        x_[i] = p_[i];
    });
    if (bad.load() < n) {
        const std::size_t i = bad.load();
        if (!internal::finite3(x_[i]) || !internal::finite3(v_[i])) {
            fail(frame_number, "vertex " + std::to_string(i) + " position is not finite");
        }
        fail(frame_number, "vertex " + std::to_string(i) + " speed " + std::to_string(norm(v_[i])) +
                               " mm/s exceeds max_speed_mm_s " +
                               std::to_string(options_.max_speed_mm_s));
    }
}

inline void DrapeSolver::sweep_body(std::size_t i) {
    start_distance_[i] = w_[i] > 0 ? collider_->signed_distance(x_[i], nullptr) : 0.0;
    first_hit(i);
}

// Moves p_[i] back to the last point clear of the body on the segment from the sub-step's start
// x_[i]; returns whether it did. Sphere tracing: the distance is 1-Lipschitz (the grid's bound
// outside its band is a lower bound, which keeps that true), so a step of d never crosses the
// surface.
inline bool DrapeSolver::first_hit(std::size_t i) {
    using namespace tapeline::vec3;
    const double d0 = start_distance_[i];
    if (w_[i] <= 0 || d0 < 0) {
        return false;  // pinned, or starts inside (the contact pass pushes it out)
    }
    const Vec3 move = sub(p_[i], x_[i]);
    const double length = norm(move);
    if (length < d0) {
        return false;  // cannot reach the surface
    }
    const Vec3 dir = scale(move, 1 / length);
    const double min_step = std::max(0.05, 0.1 * clearance_);
    double t = std::max(d0, min_step), safe = 0;
    for (int k = 0; k < 64; ++k) {
        if (t >= length) {
            t = length;
        }
        const double d = collider_->signed_distance(add(x_[i], scale(dir, t)), nullptr);
        if (d < 0) {
            p_[i] = add(x_[i], scale(dir, safe));
            return true;
        }
        safe = t;
        if (t >= length) {
            return false;
        }
        t += std::max(d, min_step);
    }
    p_[i] = add(x_[i], scale(dir, safe));  // undecided: keep the part known to be clear
    return true;
}

inline bool DrapeSolver::contact_body(std::size_t i) {
    using namespace tapeline::vec3;
    if (w_[i] <= 0) {
        return false;
    }
    // The constraints may have dragged the vertex through a thin limb since the sweep: stop it
    // where it entered, then push it out to the thickness.
    first_hit(i);
    Vec3 n;
    const double d = collider_->signed_distance(p_[i], &n);
    const double depth = clearance_ - d;
    end_normal_[i] = n;
    end_distance_[i] = d;
    if (!(depth > 0)) {
        return false;
    }
    // After the push and the friction below, thickness − slide bounds the distance from below
    // (1-Lipschitz).
    p_[i] = add(p_[i], scale(n, depth));
    // Coulomb friction on the sub-step's tangential motion: static while it is within μ times
    // the normal correction, kinetic (reduced by that much) beyond.
    const Vec3 dx = sub(p_[i], x_[i]);
    const Vec3 tangential = sub(dx, scale(n, dot(dx, n)));
    const double slide = norm(tangential);
    const double limit = fabric_.friction * depth;
    if (slide <= limit) {
        p_[i] = sub(p_[i], tangential);
        end_distance_[i] = clearance_ - slide;
    } else {
        p_[i] = sub(p_[i], scale(tangential, limit / slide));
        end_distance_[i] = clearance_ - limit;
    }
    return true;
}

// Edge–body contact: vertices alone let an edge cut through a thin limb or a sharp rim with both
// ends outside. Only edges that could (the balls of radius d − thickness around the two ends do
// not cover the edge) and that bend around the body (the end normals differ by more than 25°)
// are sampled at seven points; the deepest sample is pushed out to the thickness, the two ends
// moving as a lever (PBD point-on-edge constraint). Sampled, not exact: an edge can still clip
// a rim sharper than the grid resolves (tests/garment/test_sewing.cpp sees 6 such edges).
inline void DrapeSolver::contact_edges() {
    using namespace tapeline::vec3;
    const double th = clearance_;
    const std::size_t block = 4096;
    const std::size_t blocks = (edge_list_.size() + block - 1) / block;
    edge_blocks_.resize(blocks);
    tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t bl) {
        auto& out = edge_blocks_[bl];
        out.clear();
        const std::size_t end = std::min(edge_list_.size(), (bl + 1) * block);
        for (std::size_t e = bl * block; e < end; ++e) {
            const auto [a, b] = edge_list_[e];
            if (w_[a] + w_[b] == 0) {
                continue;
            }
            const double len = norm(sub(p_[a], p_[b]));
            if (end_distance_[a] + end_distance_[b] - 2 * th >= len ||
                dot(end_normal_[a], end_normal_[b]) > 0.9) {
                continue;
            }
            double best = th, best_t = -1;
            for (double t : {0.125, 0.25, 0.375, 0.5, 0.625, 0.75, 0.875}) {
                const double d =
                    collider_->signed_distance(add(scale(p_[a], 1 - t), scale(p_[b], t)), nullptr);
                if (d < best) {
                    best = d;
                    best_t = t;
                }
            }
            if (best_t >= 0) {
                out.push_back({a, b, best_t});
            }
        }
    });
    for (const auto& bl : edge_blocks_) {
        for (const EdgeContact& c : bl) {
            const double t = c.t;
            Vec3 n;
            const double d =
                collider_->signed_distance(add(scale(p_[c.a], 1 - t), scale(p_[c.b], t)), &n);
            const double depth = th - d;
            const double denom = w_[c.a] * (1 - t) * (1 - t) + w_[c.b] * t * t;
            if (!(depth > 0) || !(denom > 0)) {
                continue;
            }
            const double dl = depth / denom;
            p_[c.a] = add(p_[c.a], scale(n, w_[c.a] * (1 - t) * dl));
            p_[c.b] = add(p_[c.b], scale(n, w_[c.b] * t * dl));
        }
    }
}

inline void DrapeSolver::project_triangle(std::size_t t, double h) {
    using namespace tapeline::vec3;
    const TriangleConstraint& c = tris_[t];
    const double inv_h2 = 1 / (h * h);
    Vec3& p0 = p_[c.v[0]];
    Vec3& p1 = p_[c.v[1]];
    Vec3& p2 = p_[c.v[2]];
    Vec3* p[3] = {&p0, &p1, &p2};
    const double w[3] = {w_[c.v[0]], w_[c.v[1]], w_[c.v[2]]};
    if (w[0] + w[1] + w[2] == 0) {
        return;
    }
    auto column = [&](const double* coef) {
        Vec3 f{0, 0, 0};
        for (int k = 0; k < 3; ++k) {
            f = add(f, scale(*p[k], coef[k]));
        }
        return f;
    };
    auto apply = [&](double C, const Vec3* grad, double alpha, double& lambda) {
        double denom = alpha * inv_h2;
        for (int k = 0; k < 3; ++k) {
            denom += w[k] * dot(grad[k], grad[k]);
        }
        if (!(denom > 0)) {
            return;
        }
        const double dl = (-C - alpha * inv_h2 * lambda) / denom;
        lambda += dl;
        for (int k = 0; k < 3; ++k) {
            *p[k] = add(*p[k], scale(grad[k], w[k] * dl));
        }
    };
    // Warp and weft: C = |F·e| − 1.
    const double* coefs[2] = {c.c1, c.c2};
    const double alphas[2] = {c.alpha_warp, c.alpha_weft};
    for (int dir = 0; dir < 2; ++dir) {
        if (alphas[dir] < 0) {
            continue;
        }
        const Vec3 f = column(coefs[dir]);
        const double len = norm(f);
        if (len < 1e-12) {
            continue;
        }
        const Vec3 u = scale(f, 1 / len);
        const Vec3 grad[3] = {scale(u, coefs[dir][0]), scale(u, coefs[dir][1]),
                              scale(u, coefs[dir][2])};
        apply(len - 1, grad, alphas[dir], lambda_tri_[3 * t + dir]);
    }
    // Shear: C = cos of the angle between the deformed warp and weft (≈ the shear angle).
    if (c.alpha_shear >= 0) {
        const Vec3 f1 = column(c.c1), f2 = column(c.c2);
        const double l1 = norm(f1), l2 = norm(f2);
        if (l1 > 1e-12 && l2 > 1e-12) {
            const Vec3 u1 = scale(f1, 1 / l1), u2 = scale(f2, 1 / l2);
            const double C = dot(u1, u2);
            const Vec3 d1 = scale(sub(u2, scale(u1, C)), 1 / l1);
            const Vec3 d2 = scale(sub(u1, scale(u2, C)), 1 / l2);
            Vec3 grad[3];
            for (int k = 0; k < 3; ++k) {
                grad[k] = add(scale(d1, c.c1[k]), scale(d2, c.c2[k]));
            }
            apply(C, grad, c.alpha_shear, lambda_tri_[3 * t + 2]);
        }
    }
}

inline void DrapeSolver::project_bend(std::size_t e, double h) {
    using namespace tapeline::vec3;
    const BendConstraint& c = bends_[e];
    Vec3& x1 = p_[c.v[0]];
    Vec3& x2 = p_[c.v[1]];
    Vec3& x3 = p_[c.v[2]];
    Vec3& x4 = p_[c.v[3]];
    const double w[4] = {w_[c.v[0]], w_[c.v[1]], w_[c.v[2]], w_[c.v[3]]};
    if (w[0] + w[1] + w[2] + w[3] == 0) {
        return;
    }
    double theta;
    Vec3 g[4];
    if (!internal::dihedral(x1, x2, x3, x4, theta, g)) {
        return;
    }
    double denom = c.alpha / (h * h);
    for (int k = 0; k < 4; ++k) {
        denom += w[k] * dot(g[k], g[k]);
    }
    if (!(denom > 0)) {
        return;
    }
    const double dl = (-theta - c.alpha / (h * h) * lambda_bend_[e]) / denom;
    lambda_bend_[e] += dl;
    Vec3* x[4] = {&x1, &x2, &x3, &x4};
    for (int k = 0; k < 4; ++k) {
        *x[k] = add(*x[k], scale(g[k], w[k] * dl));
    }
}

inline void DrapeSolver::project_stitch(std::size_t s, double h) {
    using namespace tapeline::vec3;
    const Stitch& st = stitches_[s];
    const double wa = w_[st.a], wb = w_[st.b];
    const Vec3 d = sub(p_[st.a], p_[st.b]);
    const double len = norm(d);
    if (wa + wb == 0 || len < 1e-12) {
        return;
    }
    const Vec3 u = scale(d, 1 / len);
    const double alpha = stitch_alpha_[s] / (h * h);
    const double dl = (-(len - st.rest_mm) - alpha * lambda_stitch_[s]) / (wa + wb + alpha);
    lambda_stitch_[s] += dl;
    p_[st.a] = add(p_[st.a], scale(u, wa * dl));
    p_[st.b] = sub(p_[st.b], scale(u, wb * dl));
}

inline void DrapeSolver::project_attachment(std::size_t a, double h) {
    using namespace tapeline::vec3;
    const Attachment& at = attachments_[a];
    const double w = w_[at.vertex];
    const Vec3 d = sub(p_[at.vertex], at.target);
    const double alpha = attachment_alpha_[a] / (h * h);
    if (w == 0) {
        return;
    }
    if (at.axis[0] != 0 || at.axis[1] != 0 || at.axis[2] != 0) {
        // C = axis·(p − target), its gradient the axis.
        const double c = dot(at.axis, d);
        const double dl = (-c - alpha * lambda_attachment_[a]) / (w + alpha);
        lambda_attachment_[a] += dl;
        p_[at.vertex] = add(p_[at.vertex], scale(at.axis, w * dl));
        return;
    }
    const double len = norm(d);
    if (len < 1e-12) {
        return;
    }
    const double dl = (-len - alpha * lambda_attachment_[a]) / (w + alpha);
    lambda_attachment_[a] += dl;
    p_[at.vertex] = add(p_[at.vertex], scale(d, w * dl / len));
}

// Multi-source Dijkstra over the rest edges and the stitches from the anchors, the pinned
// vertices: once at construction and again whenever the stitches change. Serial and ordered by
// (distance, vertex), so the anchors do not depend on the thread count.
inline void DrapeSolver::update_tethers() {
    const std::size_t n = x_.size();
    std::vector<double> dist(n, std::numeric_limits<double>::infinity());
    using Entry = std::pair<double, std::uint32_t>;
    std::vector<Entry> heap;
    tether_anchors_ = 0;
    for (std::size_t i = 0; i < n; ++i) {
        tether_anchor_[i] = static_cast<std::uint32_t>(i);
        if (w_[i] == 0) {
            dist[i] = 0;
            heap.emplace_back(0.0, static_cast<std::uint32_t>(i));
            ++tether_anchors_;
        }
    }
    if (tether_anchors_ == 0) {
        return;
    }
    // Stitches as extra edges, both ways (CSR).
    std::vector<std::uint32_t> st_start(n + 1, 0), st_to;
    std::vector<double> st_len;
    for (const Stitch& st : stitches_) {
        ++st_start[st.a + 1];
        ++st_start[st.b + 1];
    }
    for (std::size_t i = 0; i < n; ++i) {
        st_start[i + 1] += st_start[i];
    }
    st_to.resize(st_start[n]);
    st_len.resize(st_start[n]);
    {
        std::vector<std::uint32_t> fill(st_start.begin(), st_start.end() - 1);
        for (const Stitch& st : stitches_) {
            st_to[fill[st.a]] = st.b;
            st_len[fill[st.a]++] = st.rest_mm;
            st_to[fill[st.b]] = st.a;
            st_len[fill[st.b]++] = st.rest_mm;
        }
    }
    const auto later = std::greater<Entry>();
    std::make_heap(heap.begin(), heap.end(), later);
    auto relax = [&](std::uint32_t v, std::uint32_t u, double len) {
        const double d = dist[v] + len;
        if (d < dist[u]) {
            dist[u] = d;
            tether_anchor_[u] = tether_anchor_[v];
            heap.emplace_back(d, u);
            std::push_heap(heap.begin(), heap.end(), later);
        }
    };
    while (!heap.empty()) {
        std::pop_heap(heap.begin(), heap.end(), later);
        const auto [d, v] = heap.back();
        heap.pop_back();
        if (d > dist[v]) {
            continue;
        }
        for (std::uint32_t k = neighbour_start_[v]; k < neighbour_start_[v + 1]; ++k) {
            relax(v, neighbours_[k], rest_edge_length_[k]);
        }
        for (std::uint32_t k = st_start[v]; k < st_start[v + 1]; ++k) {
            relax(v, st_to[k], st_len[k]);
        }
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (!std::isfinite(dist[i])) {
            tether_anchor_[i] = static_cast<std::uint32_t>(i);  // no anchor reaches it
        }
        tether_limit_[i] = options_.tether_stretch * dist[i];
    }
}

inline void DrapeSolver::detect_self_contacts() {
    using namespace tapeline::vec3;
    vertex_hash_.build(p_, hash_cell_);
    const internal::PointHash& hash = vertex_hash_;
    const double thickness = fabric_.thickness_mm;
    const std::size_t block = 1024;
    const std::size_t blocks = (tris_.size() + block - 1) / block;
    self_blocks_.resize(blocks);
    tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t bl) {
        std::vector<SelfContact>& out = self_blocks_[bl];
        out.clear();
        const std::size_t end = std::min(tris_.size(), (bl + 1) * block);
        for (std::size_t t = bl * block; t < end; ++t) {
            const std::uint32_t* tv = tris_[t].v;
            const Vec3& a = p_[tv[0]];
            const Vec3& b = p_[tv[1]];
            const Vec3& c = p_[tv[2]];
            const auto [lo, hi] = internal::triangle_box(a, b, c, thickness);
            const auto clo = hash.cell_of(lo), chi = hash.cell_of(hi);
            if ((chi[0] - clo[0] + 1) * (chi[1] - clo[1] + 1) * (chi[2] - clo[2] + 1) > 64) {
                continue;  // a wildly stretched triangle: leave it to the stretch constraints
            }
            const bool triangle_moves = w_[tv[0]] + w_[tv[1]] + w_[tv[2]] > 0;
            Vec3 nn{0, 0, 0}, normal_start{0, 0, 0};  // computed at the first candidate
            bool normals = false;
            for (std::int64_t i = clo[0]; i <= chi[0]; ++i) {
                for (std::int64_t j = clo[1]; j <= chi[1]; ++j) {
                    for (std::int64_t k = clo[2]; k <= chi[2]; ++k) {
                        const std::array<std::int64_t, 3> cell{i, j, k};
                        const std::size_t bk = hash.bucket_of(cell);
                        for (std::uint32_t q = hash.start[bk]; q < hash.start[bk + 1]; ++q) {
                            const std::uint32_t v = hash.points[q];
                            const Vec3& pv = p_[v];
                            if (pv[0] < lo[0] || pv[1] < lo[1] || pv[2] < lo[2] || pv[0] > hi[0] ||
                                pv[1] > hi[1] || pv[2] > hi[2] || hash.cell[v] != cell) {
                                continue;  // outside the box, or met through a hash collision
                            }
                            if (v == tv[0] || v == tv[1] || v == tv[2] ||
                                (!triangle_moves && w_[v] == 0)) {
                                continue;
                            }
                            if (!tangled_.empty() && tangled_[v] &&
                                (tangled_[tv[0]] || tangled_[tv[1]] || tangled_[tv[2]])) {
                                continue;  // on a crossing: let the layers pass back (untangle())
                            }
                            if (!normals) {
                                normals = true;
                                const Vec3 normal_now = cross(sub(b, a), sub(c, a));
                                const double normal_len = norm(normal_now);
                                if (normal_len > 1e-12) {
                                    nn = scale(normal_now, 1 / normal_len);
                                }
                                normal_start =
                                    cross(sub(x_[tv[1]], x_[tv[0]]), sub(x_[tv[2]], x_[tv[0]]));
                            }
                            if (nn == Vec3{0, 0, 0} || std::abs(dot(sub(pv, a), nn)) >= thickness) {
                                continue;  // degenerate triangle, or off its plane's slab
                            }
                            // A neighbour of a corner, or a corner's stitch partner, touches the
                            // triangle by construction: that is not a collision.
                            if (near_in_rest(v, tv[0]) || near_in_rest(v, tv[1]) ||
                                near_in_rest(v, tv[2])) {
                                continue;
                            }
                            const auto bary = internal::closest_barycentric(pv, a, b, c);
                            const Vec3 q3 =
                                add(add(scale(a, bary[0]), scale(b, bary[1])), scale(c, bary[2]));
                            const Vec3 delta = sub(pv, q3);
                            if (dot(delta, delta) >= thickness * thickness) {
                                continue;
                            }
                            // The side the vertex was on at the start of the sub-step.
                            const Vec3 q0 =
                                add(add(scale(x_[tv[0]], bary[0]), scale(x_[tv[1]], bary[1])),
                                    scale(x_[tv[2]], bary[2]));
                            double side = dot(sub(x_[v], q0), normal_start);
                            if (side == 0) {
                                side = dot(delta, nn);
                            }
                            out.push_back({v,
                                           static_cast<std::uint32_t>(t),
                                           {bary[0], bary[1], bary[2]},
                                           side < 0 ? scale(nn, -1) : nn});
                        }
                    }
                }
            }
        }
    });
    self_contacts_.clear();
    for (const auto& b : self_blocks_) {
        self_contacts_.insert(self_contacts_.end(), b.begin(), b.end());
    }
}

// Whether u and v are a stitch pair (still apart, to be sewn).
inline bool DrapeSolver::stitched(std::uint32_t u, std::uint32_t v) const {
    return !stitch_pairs_.empty() &&
           std::binary_search(stitch_pairs_.begin(), stitch_pairs_.end(), std::make_pair(u, v));
}

// Whether u and v are one vertex, neighbours, or a stitch pair: cloth that touches by
// construction. Tried and left out: letting neighbours joined by rest edges longer than three
// thicknesses collide (they can only meet where the cloth folds over itself). On twelve drapes at
// 20 mm without untangling it left more crossings on the garments that had few (aaron and teagan:
// 4 -> 24, 0 -> 10, 3 -> 15, 16 -> 32) and about as many on the others.
inline bool DrapeSolver::near_in_rest(std::uint32_t u, std::uint32_t v) const {
    return u == v ||
           std::binary_search(neighbours_.begin() + neighbour_start_[u],
                              neighbours_.begin() + neighbour_start_[u + 1], v) ||
           stitched(u, v);
}

// Edge–edge proximity: two edges crossing like an X pass through each other without any vertex
// coming near a triangle, which the vertex–triangle pairs cannot see when the edges are much
// longer than the thickness. Broad phase: the predicted edge midpoints in a spatial hash whose
// cell is the longest predicted edge (up to three times the mean rest edge; longer, wildly
// stretched edges are left to the stretch constraints) plus the thickness, so two edges closer
// than the thickness have their midpoints in neighbouring cells. Narrow phase: the closest points
// of the two segments (Ericson 5.1.9); the pairs closer than the thickness are kept with the side
// they were on at the sub-step's start. Pairs with ends that are neighbours or stitch partners
// are left out, as for the vertex–triangle pairs.
inline void DrapeSolver::detect_edge_edge_contacts() {
    using namespace tapeline::vec3;
    const std::size_t m = edge_list_.size();
    const double thickness = fabric_.thickness_mm;
    const double longest_kept = 1.5 * hash_cell_;
    edge_mid_.resize(m);
    edge_kept_.resize(m);
    for (std::size_t e = 0; e < m; ++e) {
        const Vec3& pa = p_[edge_list_[e].first];
        const Vec3& pb = p_[edge_list_[e].second];
        edge_kept_[e] = norm(sub(pb, pa)) <= longest_kept;
        edge_mid_[e] = scale(add(pa, pb), 0.5);
    }
    edge_hash_.build(edge_mid_, longest_kept + thickness, edge_kept_);
    const internal::PointHash& hash = edge_hash_;
    // A candidate pair: kept when closer than the thickness.
    auto test = [&](std::size_t e, std::uint32_t f, std::vector<EdgeEdgeContact>& out) {
        const auto [a, b] = edge_list_[e];
        const auto [c, d] = edge_list_[f];
        if (w_[a] + w_[b] + w_[c] + w_[d] == 0 || near_in_rest(a, c) || near_in_rest(a, d) ||
            near_in_rest(b, c) || near_in_rest(b, d)) {
            return;
        }
        if (!tangled_.empty() && (tangled_[a] || tangled_[b]) && (tangled_[c] || tangled_[d])) {
            return;  // on a crossing: let the layers pass back (untangle())
        }
        const auto [se, tf] = internal::closest_segment_params(p_[a], p_[b], p_[c], p_[d]);
        const Vec3 pe = add(scale(p_[a], 1 - se), scale(p_[b], se));
        const Vec3 pf = add(scale(p_[c], 1 - tf), scale(p_[d], tf));
        const Vec3 delta = sub(pe, pf);
        if (dot(delta, delta) >= thickness * thickness) {
            return;
        }
        // The side at the sub-step's start; when the points met there too, the normal of the
        // two edges' plane, turned to the side now.
        Vec3 n = sub(add(scale(x_[a], 1 - se), scale(x_[b], se)),
                     add(scale(x_[c], 1 - tf), scale(x_[d], tf)));
        double len = norm(n);
        if (!(len > 1e-9)) {
            n = cross(sub(p_[b], p_[a]), sub(p_[d], p_[c]));
            len = norm(n);
            if (!(len > 1e-12)) {
                return;  // parallel edges on one line: left to the vertex–triangle pairs
            }
            if (dot(n, delta) < 0) {
                len = -len;
            }
        }
        out.push_back({static_cast<std::uint32_t>(e), f, se, tf, scale(n, 1 / len)});
    };
    const std::size_t block = 1024;
    const std::size_t blocks = (m + block - 1) / block;
    edge_edge_blocks_.resize(blocks);
    tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t bl) {
        std::vector<EdgeEdgeContact>& out = edge_edge_blocks_[bl];
        out.clear();
        const std::size_t end = std::min(m, (bl + 1) * block);
        for (std::size_t e = bl * block; e < end; ++e) {
            if (!edge_kept_[e]) {
                continue;
            }
            const auto [a, b] = edge_list_[e];
            Vec3 elo, ehi;
            for (int k = 0; k < 3; ++k) {
                elo[k] = std::min(p_[a][k], p_[b][k]) - thickness;
                ehi[k] = std::max(p_[a][k], p_[b][k]) + thickness;
            }
            const auto& ce = hash.cell[e];
            for (std::int64_t i = ce[0] - 1; i <= ce[0] + 1; ++i) {
                for (std::int64_t j = ce[1] - 1; j <= ce[1] + 1; ++j) {
                    for (std::int64_t k = ce[2] - 1; k <= ce[2] + 1; ++k) {
                        const std::array<std::int64_t, 3> c3{i, j, k};
                        const std::size_t bk = hash.bucket_of(c3);
                        for (std::uint32_t q = hash.start[bk]; q < hash.start[bk + 1]; ++q) {
                            const std::uint32_t f = hash.points[q];
                            if (f <= e || hash.cell[f] != c3) {
                                continue;  // the pair's other visit, or a hash collision
                            }
                            const auto [c, d] = edge_list_[f];
                            bool apart = false;
                            for (int x = 0; x < 3 && !apart; ++x) {
                                apart = std::max(p_[c][x], p_[d][x]) < elo[x] ||
                                        std::min(p_[c][x], p_[d][x]) > ehi[x];
                            }
                            if (!apart) {
                                test(e, f, out);
                            }
                        }
                    }
                }
            }
        }
    });
    edge_edge_contacts_.clear();
    for (const auto& b : edge_edge_blocks_) {
        edge_edge_contacts_.insert(edge_edge_contacts_.end(), b.begin(), b.end());
    }
}

// The cloth's edges crossing (or touching) its triangles at the current positions, as pairs
// (edge_list_ index, triangle) sorted; an edge and a triangle that share a vertex or whose ends
// are stitch partners do not count. Broad phase: the edge midpoints in a spatial hash whose cell
// is the longest edge, so a crossing edge's midpoint lies within half a cell of its triangle's
// box. Narrow phase: the plane and edge orientations in double precision, each against a bound
// of its rounding error; only what that leaves undecided goes to CGAL's exact predicates, so
// the pairs are those quality.h counts. Triangles in fixed blocks, in parallel.
inline std::vector<std::pair<std::uint32_t, std::uint32_t>> DrapeSolver::find_crossings() {
    using namespace tapeline::vec3;
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    const std::size_t m = edge_list_.size();
    double longest = 0;
    edge_mid_.resize(m);
    for (std::size_t e = 0; e < m; ++e) {
        const Vec3& pa = x_[edge_list_[e].first];
        const Vec3& pb = x_[edge_list_[e].second];
        longest = std::max(longest, norm(sub(pb, pa)));
        edge_mid_[e] = scale(add(pa, pb), 0.5);
    }
    crossing_hash_.build(edge_mid_, std::max(longest, 1e-6));
    const internal::PointHash& hash = crossing_hash_;
    const auto pt = [&](std::uint32_t v) { return K::Point_3(x_[v][0], x_[v][1], x_[v][2]); };
    // Sign of a value computed with rounding error below `bound`: 0 when undecided.
    const auto sign = [](double value, double bound) {
        return value > bound ? 1 : (value < -bound ? -1 : 0);
    };
    const double eps = 1e-12;  // ~4500 times the rounding of a 3 × 3 determinant
    const std::size_t nt = tris_.size();
    const std::size_t block = 1024;
    const std::size_t blocks = (nt + block - 1) / block;
    std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> out(blocks);
    tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t bl) {
        const std::size_t end = std::min(nt, (bl + 1) * block);
        std::vector<std::uint32_t> cand;
        for (std::size_t t = bl * block; t < end; ++t) {
            const std::uint32_t* tv = tris_[t].v;
            const Vec3& c0 = x_[tv[0]];
            const Vec3& c1 = x_[tv[1]];
            const Vec3& c2 = x_[tv[2]];
            const auto [lo, hi] = internal::triangle_box(c0, c1, c2, 0.5 * longest);
            const auto clo = hash.cell_of(lo), chi = hash.cell_of(hi);
            cand.clear();
            hash.for_each_in_cells(clo, chi, [&](std::uint32_t e) { cand.push_back(e); });
            std::sort(cand.begin(), cand.end());
            const Vec3 u = sub(c1, c0), w = sub(c2, c0);
            const Vec3 nrm = cross(u, w);
            const double uw = norm(u) * norm(w);
            for (const std::uint32_t e : cand) {
                const auto [a, b] = edge_list_[e];
                if (a == tv[0] || a == tv[1] || a == tv[2] || b == tv[0] || b == tv[1] ||
                    b == tv[2]) {
                    continue;
                }
                const Vec3& pa = x_[a];
                const Vec3& pb = x_[b];
                bool apart = false;
                for (int k = 0; k < 3 && !apart; ++k) {
                    apart = std::max(pa[k], pb[k]) < std::min({c0[k], c1[k], c2[k]}) ||
                            std::min(pa[k], pb[k]) > std::max({c0[k], c1[k], c2[k]});
                }
                if (apart || stitched(a, tv[0]) || stitched(a, tv[1]) || stitched(a, tv[2]) ||
                    stitched(b, tv[0]) || stitched(b, tv[1]) || stitched(b, tv[2])) {
                    continue;
                }
                const Vec3 ra = sub(pa, c0), rb = sub(pb, c0);
                const int sa = sign(dot(nrm, ra), eps * uw * norm(ra));
                const int sb = sign(dot(nrm, rb), eps * uw * norm(rb));
                int verdict = -1;  // -1: undecided, 0: apart, 1: crossing
                if (sa != 0 && sa == sb) {
                    verdict = 0;
                } else if (sa != 0 && sb != 0) {
                    // The edge pierces the plane: inside when the three edge orientations agree.
                    const Vec3 d = sub(pb, pa);
                    const Vec3* c[3] = {&c0, &c1, &c2};
                    int s3[3];
                    for (int k = 0; k < 3; ++k) {
                        const Vec3 r0 = sub(*c[k], pa), r1 = sub(*c[(k + 1) % 3], pa);
                        s3[k] = sign(dot(d, cross(r0, r1)), eps * norm(d) * norm(r0) * norm(r1));
                    }
                    const bool mixed = std::min({s3[0], s3[1], s3[2]}) == -1 &&
                                       std::max({s3[0], s3[1], s3[2]}) == 1;
                    if (mixed) {
                        verdict = 0;
                    } else if (s3[0] != 0 && s3[0] == s3[1] && s3[1] == s3[2]) {
                        verdict = 1;
                    }
                }
                if (verdict < 0) {
                    verdict = CGAL::do_intersect(K::Segment_3(pt(a), pt(b)),
                                                 K::Triangle_3(pt(tv[0]), pt(tv[1]), pt(tv[2])))
                                  ? 1
                                  : 0;
                }
                if (verdict == 1) {
                    out[bl].push_back({e, static_cast<std::uint32_t>(t)});
                }
            }
        }
    });
    std::vector<std::pair<std::uint32_t, std::uint32_t>> all;
    for (const auto& b : out) {
        all.insert(all.end(), b.begin(), b.end());
    }
    std::sort(all.begin(), all.end());
    return all;
}

// Untangling: intersection contour minimisation (P. Volino, N. Magnenat-Thalmann, "Resolving
// surface collisions through intersection contour minimization", SIGGRAPH 2006). Where cloth cuts
// through cloth, the two surfaces meet along closed curves (or curves ending on the cloth's
// border) made of segments, one per pair of intersecting triangles, each segment running between
// two edge–triangle crossing points. The length L of those curves is zero exactly when nothing
// crosses, and moving the surfaces so that L shrinks pulls the layers back through each other.
// For a crossing of edge d = b − a through the plane of triangle t (unit normal n) at P, a
// displacement r of the edge's side against the triangle's (each side moving half of it) moves P
// by r/2 − d·(n·r)/(n·d); with r = α·n, dL/dα = G·n/2 − (G·d)/(n·d), G the sum of the unit
// vectors from P's two neighbours on the curve. Each crossing then moves the edge's ends
// (weighted by where P lies on the edge) and the triangle's corners (by P's barycentric
// coordinates) along ∓n, against the sign of dL/dα, each side by half of what takes the edge's
// end on the wrong side to the thickness on the right one; a vertex's moves are summed, and its
// step is the largest such half-distance among its crossings, capped at four thicknesses. Called
// at the start of every frame; the contacts between vertices on crossings are left out for the
// frame (detect_self_contacts), as Baraff, Witkin and Kass ("Untangling cloth", SIGGRAPH 2003)
// leave out the repulsion inside intersection regions. The step rule against fixed steps (one
// thickness: slower; eight: chaotic on some drapes) is measured in docs/garment.md, "Untangling".
// Crossings of an edge and a triangle whose ends are stitch partners are seams still being closed,
// not tangles: left out. Serial and in a fixed order: the same result for any thread count.
inline std::size_t DrapeSolver::untangle() {
    using namespace tapeline::vec3;
    const std::size_t n = x_.size();
    struct Crossing {
        std::uint32_t edge, t;
        double s;           // P = a + s·(b − a)
        double bary[3];     // P in the triangle
        Vec3 p, normal, d;  // the point, the triangle's unit normal, the edge vector
        Vec3 g{0, 0, 0};    // ∂L/∂P
    };
    tangled_.assign(n, 0);
    const auto crossings = find_crossings();
    if (crossings.empty()) {
        return 0;
    }
    // A vertex moves at most four thicknesses a frame: enough to take a fold of a few mm back
    // through within a frame, little enough that the cloth's own constraints smooth it out.
    const double cap = 4 * fabric_.thickness_mm;
    std::vector<Crossing> found;
    for (const auto& [e, t] : crossings) {
        const auto [a, b] = edge_list_[e];
        const Tri& tv = model_.triangles[t];
        const Vec3 d = sub(x_[b], x_[a]);
        Vec3 nn = cross(sub(x_[tv[1]], x_[tv[0]]), sub(x_[tv[2]], x_[tv[0]]));
        const double len = norm(nn);
        if (!(len > 1e-12)) {
            continue;
        }
        nn = scale(nn, 1 / len);
        const double nd = dot(nn, d);
        if (std::abs(nd) < 1e-9 * norm(d)) {
            continue;  // the edge lies in the triangle's plane: no crossing point
        }
        const double s = std::clamp(dot(nn, sub(x_[tv[0]], x_[a])) / nd, 0.0, 1.0);
        Crossing c;
        c.edge = e;
        c.t = t;
        c.s = s;
        c.p = add(x_[a], scale(d, s));
        const auto bary = internal::closest_barycentric(c.p, x_[tv[0]], x_[tv[1]], x_[tv[2]]);
        for (int k = 0; k < 3; ++k) {
            c.bary[k] = bary[k];
        }
        c.normal = nn;
        c.d = d;
        found.push_back(c);
    }

    // The curve's segments: the crossing points of each pair of intersecting triangles (a
    // triangle holding the crossing edge, the crossed triangle), in a fixed order.
    std::vector<std::pair<std::uint64_t, std::uint32_t>> by_pair;
    for (std::size_t i = 0; i < found.size(); ++i) {
        for (const std::uint32_t f : edge_tris_[found[i].edge]) {
            if (f != kNone) {
                const std::uint64_t lo = std::min(f, found[i].t), hi = std::max(f, found[i].t);
                by_pair.push_back({(lo << 32) | hi, static_cast<std::uint32_t>(i)});
            }
        }
    }
    std::sort(by_pair.begin(), by_pair.end());
    for (std::size_t k = 0; k < by_pair.size();) {
        std::size_t e = k;
        while (e < by_pair.size() && by_pair[e].first == by_pair[k].first) {
            ++e;
        }
        if (e - k == 2) {
            Crossing& p = found[by_pair[k].second];
            Crossing& q = found[by_pair[k + 1].second];
            const Vec3 pq = sub(q.p, p.p);
            const double len = norm(pq);
            if (len > 1e-12) {
                const Vec3 u = scale(pq, 1 / len);
                p.g = sub(p.g, u);
                q.g = add(q.g, u);
            }
        }
        k = e;
    }
    std::vector<Vec3> move(n, Vec3{0, 0, 0});
    std::vector<double> reach(n, 0.0);
    for (const Crossing& c : found) {
        const auto [a, b] = edge_list_[c.edge];
        const Tri& tv = model_.triangles[c.t];
        tangled_[a] = tangled_[b] = 1;
        for (const std::uint32_t v : tv) {
            tangled_[v] = 1;
        }
        const double slope = dot(c.g, c.normal) / 2 - dot(c.g, c.d) / dot(c.normal, c.d);
        if (slope == 0) {
            continue;
        }
        const double dir = slope > 0 ? -1.0 : 1.0;
        const Vec3 r = scale(c.normal, dir);  // the edge's side, against t's
        // How far the edge must go against the triangle for its end on the wrong side to
        // reach the thickness on the right one; half of it on each side.
        const Vec3& c0 = x_[tv[0]];
        const double far = std::max(0.0, -std::min(dir * dot(c.normal, sub(x_[a], c0)),
                                                   dir * dot(c.normal, sub(x_[b], c0))));
        const double half = 0.5 * (far + fabric_.thickness_mm);
        move[a] = add(move[a], scale(r, 1 - c.s));
        move[b] = add(move[b], scale(r, c.s));
        reach[a] = std::max(reach[a], half);
        reach[b] = std::max(reach[b], half);
        for (int k = 0; k < 3; ++k) {
            move[tv[k]] = sub(move[tv[k]], scale(r, c.bary[k]));
            reach[tv[k]] = std::max(reach[tv[k]], half);
        }
    }
    for (std::size_t v = 0; v < n; ++v) {
        const double len = norm(move[v]);
        if (w_[v] > 0 && len > 0) {
            const double m = std::min(reach[v], cap);
            x_[v] = add(x_[v], scale(move[v], m / std::max(1.0, len)));
        }
    }
    return crossings.size();
}

/// Throws InvalidInput, naming `who` and the option, unless `o` is usable by
/// smooth_fold_overs().
inline void check_fold_options(const FoldOptions& o, const std::string& who) {
    if (o.max_rounds < 0 || o.rings < 0 || o.sweeps < 1) {
        throw InvalidInput(who +
                           ": fold options need max_rounds >= 0, rings >= 0 and sweeps >= 1, got " +
                           std::to_string(o.max_rounds) + ", " + std::to_string(o.rings) + " and " +
                           std::to_string(o.sweeps));
    }
}

// Fold-overs (smooth_fold_overs): a patch of cloth folded over itself within an edge or two is
// where compression buckled the cloth at a finer scale than its edges; the mesh cannot hold
// such a fold without crossing itself, and the contacts, which leave out a vertex's
// neighbours' triangles (near_in_rest), do not stop it. Laplacian smoothing of a small patch
// around each crossing (its border fixed) flattens it; the crossings are found again and the
// patch grows where they stay. Of the states the rounds pass through, the one with the fewest
// crossings is kept (where cloth is pressed between layers or against the body, smoothing can
// make more than it removes). Jacobi sweeps over a sorted patch: the same result for any thread
// count.
inline FoldReport DrapeSolver::smooth_fold_overs(const FoldOptions& o) {
    using namespace tapeline::vec3;
    check_fold_options(o, "DrapeSolver::smooth_fold_overs");
    const auto start = std::chrono::steady_clock::now();
    const std::size_t n = x_.size();
    FoldReport report;
    const std::vector<Vec3> x0 = x_;
    // Each border vertex's neighbours along the border (edges with one triangle); a vertex with
    // more than two (where borders meet) stays where it is.
    std::vector<std::array<std::uint32_t, 2>> along(n, {kNone, kNone});
    std::vector<std::uint8_t> border(n, 0);
    for (std::size_t e = 0; e < edge_list_.size(); ++e) {
        if (edge_tris_[e][1] != kNone) {
            continue;
        }
        const auto [a, b] = edge_list_[e];
        for (const auto& [u, w] : {std::make_pair(a, b), std::make_pair(b, a)}) {
            border[u] = std::min<int>(border[u] + 1, 3);
            if (along[u][0] == kNone) {
                along[u][0] = w;
            } else {
                along[u][1] = w;
            }
        }
    }
    // Vertices joined by stitches (pairs still apart) move as one: a vertex's group joins its
    // patch whole, and every member takes the mean of the group's moves, so no seam opens.
    const std::vector<std::uint32_t> weld = weld_pairs(n, stitches_).weld_map;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> group;  // (class, member), sorted
    for (const Stitch& st : stitches_) {
        group.push_back({weld[st.a], st.a});
        group.push_back({weld[st.b], st.b});
    }
    std::sort(group.begin(), group.end());
    group.erase(std::unique(group.begin(), group.end()), group.end());
    auto crossings = find_crossings();
    report.crossings_before = crossings.size();
    std::vector<std::uint32_t> slot(n, 0);
    std::vector<std::uint8_t> in(n, 0);
    std::vector<std::uint32_t> patch;
    std::vector<Vec3> next, prev;
    // The state with the fewest crossings is kept: where cloth is pressed between layers or
    // against the body, smoothing can make more than it removes.
    std::size_t fewest = crossings.size();
    std::vector<Vec3> best = x_;
    for (int round = 0; round < o.max_rounds && !crossings.empty(); ++round) {
        ++report.rounds;
        std::fill(in.begin(), in.end(), 0);
        patch.clear();
        const auto add_vertex = [&](std::uint32_t v) {
            if (!in[v]) {
                in[v] = 1;
                patch.push_back(v);
                auto it = std::lower_bound(group.begin(), group.end(), std::make_pair(weld[v], 0u));
                for (; it != group.end() && it->first == weld[v]; ++it) {
                    if (!in[it->second]) {
                        in[it->second] = 1;
                        patch.push_back(it->second);
                    }
                }
            }
        };
        for (const auto& [e, t] : crossings) {
            add_vertex(edge_list_[e].first);
            add_vertex(edge_list_[e].second);
            for (const std::uint32_t v : model_.triangles[t]) {
                add_vertex(v);
            }
        }
        const int rings = o.rings + round / 5;
        for (int k = 0; k < rings; ++k) {
            const std::size_t end = patch.size();
            for (std::size_t i = 0; i < end; ++i) {
                const std::uint32_t v = patch[i];
                for (std::uint32_t j = neighbour_start_[v]; j < neighbour_start_[v + 1]; ++j) {
                    add_vertex(neighbours_[j]);
                }
            }
        }
        std::sort(patch.begin(), patch.end());
        for (std::size_t i = 0; i < patch.size(); ++i) {
            slot[patch[i]] = static_cast<std::uint32_t>(i);
        }
        next.resize(patch.size());
        prev.resize(patch.size());
        for (int sweep = 0; sweep < o.sweeps; ++sweep) {
            for (std::size_t i = 0; i < patch.size(); ++i) {
                prev[i] = x_[patch[i]];
            }
            for (std::size_t i = 0; i < patch.size(); ++i) {
                const std::uint32_t v = patch[i];
                next[i] = x_[v];
                if (w_[v] == 0 || border[v] > 2) {
                    continue;
                }
                Vec3 sum{0, 0, 0};
                int count = 0;
                if (border[v] == 2) {
                    sum = add(x_[along[v][0]], x_[along[v][1]]);
                    count = 2;
                } else if (border[v] == 0) {
                    for (std::uint32_t j = neighbour_start_[v]; j < neighbour_start_[v + 1]; ++j) {
                        sum = add(sum, x_[neighbours_[j]]);
                        ++count;
                    }
                }
                if (count > 0) {
                    next[i] = add(scale(x_[v], 0.5), scale(sum, 0.5 / count));
                }
            }
            for (std::size_t i = 0; i < patch.size(); ++i) {
                x_[patch[i]] = next[i];
            }
            if (collider_) {
                // Edge midpoints first, vertices last (as in the sub-steps): no edge of the
                // patch may cut into the body between two vertices outside it.
                for (const std::uint32_t v : patch) {
                    for (std::uint32_t j = neighbour_start_[v]; j < neighbour_start_[v + 1]; ++j) {
                        const std::uint32_t u = neighbours_[j];
                        if (u < v || !in[u]) {
                            continue;
                        }
                        Vec3 g;
                        const double d =
                            collider_->signed_distance(scale(add(x_[u], x_[v]), 0.5), &g);
                        if (d < clearance_) {
                            const Vec3 push = scale(g, clearance_ - d);
                            x_[u] = w_[u] > 0 ? add(x_[u], push) : x_[u];
                            x_[v] = w_[v] > 0 ? add(x_[v], push) : x_[v];
                        }
                    }
                }
                for (const std::uint32_t v : patch) {
                    for (int k = 0; k < 2 && w_[v] > 0; ++k) {  // a grid's gradient: twice to land
                        Vec3 g;
                        const double d = collider_->signed_distance(x_[v], &g);
                        if (!(d < clearance_)) {
                            break;
                        }
                        x_[v] = add(x_[v], scale(g, clearance_ - d));
                    }
                }
            }
            // Stitch groups last: each member takes the mean of the group's moves over the
            // sweep, the body's pushes included, so that the gaps stay as they were.
            for (std::size_t g = 0; g < group.size();) {
                std::size_t e = g;
                Vec3 sum{0, 0, 0};
                bool pinned = false;
                for (; e < group.size() && group[e].first == group[g].first; ++e) {
                    const std::uint32_t v = group[e].second;
                    sum = add(sum, in[v] ? sub(x_[v], prev[slot[v]]) : Vec3{0, 0, 0});
                    pinned = pinned || w_[v] == 0;
                }
                const Vec3 mean = pinned ? Vec3{0, 0, 0} : scale(sum, 1.0 / double(e - g));
                for (std::size_t k = g; k < e; ++k) {
                    const std::uint32_t v = group[k].second;
                    if (in[v]) {
                        x_[v] = add(prev[slot[v]], mean);
                    }
                }
                g = e;
            }
        }
        crossings = find_crossings();
        if (crossings.size() < fewest) {
            fewest = crossings.size();
            best = x_;
        }
    }
    if (crossings.size() > fewest) {
        x_ = best;
    }
    report.crossings_after = fewest;
    for (std::size_t v = 0; v < n; ++v) {
        const double d = norm(sub(x_[v], x0[v]));
        report.max_move_mm = std::max(report.max_move_mm, d);
        report.vertices_moved += d > 0.3 ? 1 : 0;
        v_[v] = {0, 0, 0};
    }
    report.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}

inline void DrapeSolver::solve_self_contacts() {
    using namespace tapeline::vec3;
    const double thickness = fabric_.thickness_mm;
    for (const SelfContact& sc : self_contacts_) {
        const std::uint32_t* tv = tris_[sc.t].v;
        const Vec3 q = add(add(scale(p_[tv[0]], sc.b[0]), scale(p_[tv[1]], sc.b[1])),
                           scale(p_[tv[2]], sc.b[2]));
        const double C = dot(sub(p_[sc.v], q), sc.n) - thickness;
        if (C >= 0) {
            continue;
        }
        double denom = w_[sc.v];
        for (int k = 0; k < 3; ++k) {
            denom += w_[tv[k]] * sc.b[k] * sc.b[k];
        }
        if (!(denom > 0)) {
            continue;
        }
        const double dl = -C / denom;
        p_[sc.v] = add(p_[sc.v], scale(sc.n, w_[sc.v] * dl));
        for (int k = 0; k < 3; ++k) {
            p_[tv[k]] = sub(p_[tv[k]], scale(sc.n, w_[tv[k]] * sc.b[k] * dl));
        }
    }
    for (const EdgeEdgeContact& ec : edge_edge_contacts_) {
        const auto [a, b] = edge_list_[ec.e];
        const auto [c, d] = edge_list_[ec.f];
        const Vec3 pe = add(scale(p_[a], 1 - ec.s), scale(p_[b], ec.s));
        const Vec3 pf = add(scale(p_[c], 1 - ec.t), scale(p_[d], ec.t));
        const double C = dot(sub(pe, pf), ec.n) - thickness;
        if (C >= 0) {
            continue;
        }
        const double ka = 1 - ec.s, kb = ec.s, kc = 1 - ec.t, kd = ec.t;
        const double denom = w_[a] * ka * ka + w_[b] * kb * kb + w_[c] * kc * kc + w_[d] * kd * kd;
        if (!(denom > 0)) {
            continue;
        }
        const double dl = -C / denom;
        p_[a] = add(p_[a], scale(ec.n, w_[a] * ka * dl));
        p_[b] = add(p_[b], scale(ec.n, w_[b] * kb * dl));
        p_[c] = sub(p_[c], scale(ec.n, w_[c] * kc * dl));
        p_[d] = sub(p_[d], scale(ec.n, w_[d] * kd * dl));
    }
}

/// Throws InvalidInput, naming `who` and the option, unless `ro` is usable by relax().
inline void check_relax_options(const RelaxOptions& ro, const std::string& who) {
    if (ro.max_iterations < 1) {
        throw InvalidInput(who + ": max_iterations must be >= 1, got " +
                           std::to_string(ro.max_iterations));
    }
    if (ro.friction_from_iteration < 0 || ro.release_until_iteration < 0) {
        throw InvalidInput(who +
                           ": friction_from_iteration and release_until_iteration "
                           "must be >= 0, got " +
                           std::to_string(ro.friction_from_iteration) + " and " +
                           std::to_string(ro.release_until_iteration));
    }
    if (!(std::isfinite(ro.tolerance_mm) && ro.tolerance_mm > 0)) {
        throw InvalidInput(who + ": tolerance_mm must be finite and > 0, got " +
                           std::to_string(ro.tolerance_mm));
    }
    if (ro.settle_iterations < 0 || ro.stall_rejections < 0 ||
        !(ro.settle_fraction >= 0 && ro.settle_fraction <= 1)) {
        throw InvalidInput(who +
                           ": settle_iterations and stall_rejections must be >= 0 and "
                           "settle_fraction in [0, 1], got " +
                           std::to_string(ro.settle_iterations) + ", " +
                           std::to_string(ro.stall_rejections) + " and " +
                           std::to_string(ro.settle_fraction));
    }
    if (!(std::isfinite(ro.initial_step_seconds) && ro.initial_step_seconds > 0)) {
        throw InvalidInput(who + ": initial_step_seconds must be finite and > 0, got " +
                           std::to_string(ro.initial_step_seconds));
    }
}

// Static equilibrium. The constraints above are the gradients of energies ½·C²/α (stretch,
// shear, bending, stitches, attachments); relax() minimises their sum plus gravity's potential
// and a stiff one-sided penalty that keeps the cloth at the clearance from the body,
//   E(x) = Σ ½·C(x)²/α − Σ m_i·g·x_i + Σ ½·k_c·max(0, c − d(q))²,
// q running over the vertices (c the clearance) and the edge midpoints (c half of it: an edge
// cannot cut through a bump of the body between its ends), d the collider's distance; and over
// the body's own vertices b (set_body_points), d = n_b·(q − b) for the point q of the cloth
// triangle that the line through b along its normal n_b meets (c/2; the pairing is renewed after
// every accepted step): the grid rounds off bumps a few cells wide, and at 10 mm a nipple 6 mm
// high and 14 mm wide poked through triangles between cloth vertices that kept their clearance
// from it (cloth edges through the body at the bust points on five of the issue's nine patterns
// on mh_female_average; none with these contacts, docs/garment.md). Each iteration solves a
// Newton system: the Gauss–Newton Hessian Σ ∇C·∇Cᵀ/α (positive semi-definite), the geometric
// stiffness of stretched fibres (what holds hanging cloth against swinging sideways; its negative
// part under compression is left out), the proximal term M/h² (Levenberg–Marquardt: h doubles after
// a step that lowered E, is divided by four after one that did not) and, for every contact point
// near the body, a stiff hold of its distance from it (an active set updated once per iteration:
// a point the step pulls away is released, one it takes into the body held; from
// RelaxOptions::release_until_iteration on points are only added). From
// RelaxOptions::friction_from_iteration on, Coulomb friction holds the vertices resting on the
// body (anchored tangential springs that slip at μ times the normal force). The step is
// bounded by a trust radius on the largest vertex move, then shortened until E falls; points a
// trial step takes into the body are put back at their clearance. The sparse system (three unknowns
// per free vertex) is factored by CHOLMOD's supernodal Cholesky, its pattern analysed once. Hard
// stitches and attachments (compliance 0) and k_c are a thousand times as stiff as the stiffest
// triangle term (per mm of vertex motion).
//
// Why: with one constraint pass per sub-step XPBD leaves cloth hanging from a support stretched
// by about g·h²·N (see the header), far more than its fabric; a direct solve has no such limit,
// so the drape ends at the fabric's own stretch. Left out: cloth–cloth contact (the quality gate
// on self-intersections judges what that leaves out). Serial, apart from independent distance
// queries: the same result for any thread count.
//
// Tried and left out: keeping the solve from folding cloth over, by refusing steps that turn a
// hinge through ±π and by bending energies that grow like 2·tan(θ/2) (continued along its tangent
// beyond θ₀). On the GarmentCode shirt on five bodies, the tank top and the T-shirt on one each
// at 20 mm, with θ₀ = 150° the flattenings after the solves found fewer crossings (mh_child_10y
// 72/99/64/52 -> 37/21/102/37, mh_female_heavy_short 26/29/37/25 -> 12/0) and one more drape
// passed, but on held-out mh_pop_037 a stitch opened to 1.2 mm and p95 stretch rose to 1.08, and
// solves that had converged ran out of iterations; θ₀ = 120° was worse (stitch gaps 1.4 and 2.9
// mm). Hinges across seams are sharp by design, and the barrier fights the stitches there. Refusing
// the wrapping steps alone left the solve stuck (p95 1.11, not converged).
//
// Where its time goes (GarmentCode hoody without its hood on mh_female_average at 10 mm, 10.4k
// vertices, 100 iterations, 58 s): the Cholesky factorizations 45 s (2.3 GFlop each with the
// AMD ordering CHOLMOD picks), the energy with its gradient and blocks 8 s, the assembly 1.4 s.
// Measured and not taken: METIS's ordering (1.4 GFlop, 0.37 s instead of 0.45 s a factorization;
// it changes the drapes by round-off, so the tables would have to be run again); OpenBLAS instead
// of ATLAS (0.41 s); conjugate gradients preconditioned with the last factorization instead of a
// new one (converged within 20 iterations on 2 of 100 steps at 1e-8, 31 at 1e-3: slower).
inline RelaxReport DrapeSolver::relax(const RelaxOptions& ro) {
    using namespace tapeline::vec3;
    const auto start = std::chrono::steady_clock::now();
    check_relax_options(ro, "DrapeSolver::relax");
    if (failed_) {
        throw SolverFailure("relax: the solver failed earlier; call reset()");
    }
    const std::size_t n = x_.size();
    RelaxReport rep;
    std::vector<std::int64_t> dof(n, -1);
    std::size_t m = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (w_[i] > 0) {
            dof[i] = static_cast<std::int64_t>(m++);
        }
    }
    auto finish = [&] {
        rep.seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return rep;
    };
    if (m == 0) {
        rep.converged = true;
        rep.stop = "converged";
        return finish();
    }
    // Block pattern: free vertices that share a triangle, a hinge or a stitch (and the diagonal).
    std::vector<std::vector<std::uint32_t>> adj(m);
    auto link = [&](std::uint32_t a, std::uint32_t b) {
        if (dof[a] >= 0 && dof[b] >= 0) {
            adj[std::size_t(dof[a])].push_back(b);
        }
    };
    for (std::size_t i = 0; i < n; ++i) {
        link(std::uint32_t(i), std::uint32_t(i));
    }
    for (const TriangleConstraint& c : tris_) {
        for (int k = 0; k < 3; ++k) {
            for (int l = 0; l < 3; ++l) {
                link(c.v[k], c.v[l]);
            }
        }
    }
    for (const BendConstraint& c : bends_) {
        for (int k = 0; k < 4; ++k) {
            for (int l = 0; l < 4; ++l) {
                link(c.v[k], c.v[l]);
            }
        }
    }
    for (const Stitch& st : stitches_) {
        link(st.a, st.b);
        link(st.b, st.a);
    }
    std::vector<std::size_t> row_start(m + 1, 0);
    std::vector<std::uint32_t> cols;
    for (std::size_t r = 0; r < m; ++r) {
        std::sort(adj[r].begin(), adj[r].end());
        adj[r].erase(std::unique(adj[r].begin(), adj[r].end()), adj[r].end());
        row_start[r + 1] = row_start[r] + adj[r].size();
        cols.insert(cols.end(), adj[r].begin(), adj[r].end());
    }
    adj = {};
    std::vector<double> blocks(9 * cols.size()), system(9 * cols.size());
    auto block_index = [&](std::uint32_t a, std::uint32_t b) {
        const std::size_t r = std::size_t(dof[a]);
        const auto it = std::lower_bound(cols.begin() + std::ptrdiff_t(row_start[r]),
                                         cols.begin() + std::ptrdiff_t(row_start[r + 1]), b);
        return 9 * std::size_t(it - cols.begin());
    };
    // The stiffest triangle term per mm of vertex motion sets hard stitches, hard attachments and
    // the contact penalty k_c a thousand times stiffer.
    double k_ref = 0;
    for (const TriangleConstraint& c : tris_) {
        double c2 = 0;
        for (int k = 0; k < 3; ++k) {
            c2 = std::max({c2, c.c1[k] * c.c1[k], c.c2[k] * c.c2[k]});
        }
        for (double al : {c.alpha_warp, c.alpha_weft, c.alpha_shear}) {
            if (al > 0) {
                k_ref = std::max(k_ref, c2 / al);
            }
        }
    }
    if (!(k_ref > 0)) {
        k_ref = 1;
    }
    const double hard_alpha = 1e-3 / k_ref, kc = 1e3 * k_ref;
    auto alpha_or_hard = [&](double al) { return al > 0 ? al : hard_alpha; };

    // Contact points: every free vertex (clearance c), every edge midpoint (c/2), then a slot
    // per body point (set_body_points): the point of the cloth triangle over it, at c/2 above
    // it along its normal (paired with a triangle by pair_body(); none: count 0).
    constexpr std::size_t kNoBody = std::size_t(-1);
    struct ContactPoint {
        std::uint32_t v[3];
        double w[3];
        double clearance;
        int count;                   // vertices in use: 1, 2, 3 (a triangle's point), 0 (none)
        std::size_t body = kNoBody;  // body_points_ index of a body point's slot
    };
    std::vector<ContactPoint> points;
    if (collider_) {
        for (std::size_t i = 0; i < n; ++i) {
            if (dof[i] >= 0) {
                const std::uint32_t v = std::uint32_t(i);
                points.push_back({{v, v, v}, {1.0, 0.0, 0.0}, clearance_, 1});
            }
        }
        for (const auto& [a, b] : edge_list_) {
            if (dof[a] >= 0 || dof[b] >= 0) {
                points.push_back({{a, b, b}, {0.5, 0.5, 0.0}, 0.5 * clearance_, 2});
            }
        }
    }
    const std::size_t np_cloth = points.size();
    for (std::size_t j = 0; collider_ && j < body_points_.size(); ++j) {
        points.push_back({{0, 0, 0}, {0.0, 0.0, 0.0}, 0.5 * clearance_, 0, j});
    }
    const std::size_t np = points.size();
    std::vector<Vec3> normal(np);
    std::vector<double> dist(np);
    auto point_of = [&](const ContactPoint& c, const std::vector<Vec3>& x) {
        Vec3 p{0, 0, 0};
        for (int a = 0; a < c.count; ++a) {
            p = add(p, scale(x[c.v[a]], c.w[a]));
        }
        return p;
    };
    auto query_points = [&](const std::vector<Vec3>& x) {
        tbb::parallel_for(
            tbb::blocked_range<std::size_t>(0, np, 512),
            [&](const tbb::blocked_range<std::size_t>& rg) {
                for (std::size_t k = rg.begin(); k != rg.end(); ++k) {
                    const ContactPoint& c = points[k];
                    if (c.body == kNoBody) {
                        dist[k] = collider_->signed_distance(point_of(c, x), &normal[k]);
                        continue;
                    }
                    normal[k] = body_normals_[c.body];
                    dist[k] = c.count == 0
                                  ? std::numeric_limits<double>::max()
                                  : dot(normal[k], sub(point_of(c, x), body_points_[c.body]));
                }
            });
    };
    // Pairs each body point with the cloth triangle that the line along its normal meets first
    // (lowest) between body_reach_ below it and clearance + body_reach_ above it: the triangle
    // that must stay above it. Its point there, by barycentric weights, is the slot's contact
    // point until the next pairing (once per accepted step).
    const auto pair_body = [&](const std::vector<Vec3>& x) {
        if (np == np_cloth) {
            return;
        }
        using K = CGAL::Exact_predicates_inexact_constructions_kernel;
        using TriIt = std::vector<K::Triangle_3>::const_iterator;
        using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_triangle_primitive<K, TriIt>>>;
        std::vector<K::Triangle_3> tri;
        std::vector<std::size_t> tri_id;
        Vec3 lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
                std::numeric_limits<double>::max()};
        Vec3 hi = scale(lo, -1);
        for (std::size_t f = 0; f < model_.triangles.size(); ++f) {
            const Tri& t = model_.triangles[f];
            if (dof[t[0]] < 0 && dof[t[1]] < 0 && dof[t[2]] < 0) {
                continue;
            }
            K::Point_3 c[3];
            for (int k = 0; k < 3; ++k) {
                const Vec3& q = x[t[k]];
                c[k] = K::Point_3(q[0], q[1], q[2]);
                for (int r = 0; r < 3; ++r) {
                    lo[r] = std::min(lo[r], q[r]);
                    hi[r] = std::max(hi[r], q[r]);
                }
            }
            if (!K::Triangle_3(c[0], c[1], c[2]).is_degenerate()) {
                tri.emplace_back(c[0], c[1], c[2]);
                tri_id.push_back(f);
            }
        }
        Tree tree(tri.cbegin(), tri.cend());
        tree.build();  // before the parallel queries
        const double up = clearance_ + body_reach_, margin = up + body_reach_;
        tbb::parallel_for(
            tbb::blocked_range<std::size_t>(np_cloth, np, 256),
            [&](const tbb::blocked_range<std::size_t>& rg) {
                std::vector<Tree::Primitive_id> hits;
                for (std::size_t k = rg.begin(); k != rg.end(); ++k) {
                    ContactPoint& c = points[k];
                    c.count = 0;
                    const Vec3 &b = body_points_[c.body], &nn = body_normals_[c.body];
                    bool near = !tri.empty();
                    for (int r = 0; r < 3 && near; ++r) {
                        near = b[r] > lo[r] - margin && b[r] < hi[r] + margin;
                    }
                    if (!near) {
                        continue;
                    }
                    const Vec3 s0 = sub(b, scale(nn, body_reach_)), s1 = add(b, scale(nn, up));
                    hits.clear();
                    tree.all_intersected_primitives(K::Segment_3(K::Point_3(s0[0], s0[1], s0[2]),
                                                                 K::Point_3(s1[0], s1[1], s1[2])),
                                                    std::back_inserter(hits));
                    double best = std::numeric_limits<double>::max();
                    for (const auto& id : hits) {
                        const Tri& t = model_.triangles[tri_id[std::size_t(id - tri.cbegin())]];
                        // The line b + s·n against the plane of t (Möller–Trumbore).
                        const Vec3 e1 = sub(x[t[1]], x[t[0]]), e2 = sub(x[t[2]], x[t[0]]);
                        const Vec3 pv = cross(nn, e2);
                        const double det = dot(e1, pv);
                        if (std::abs(det) < 1e-12) {
                            continue;
                        }
                        // Only a triangle over b's side of the body: at each of its vertices
                        // the collider's gradient within 60° of b's normal. Cloth that passes
                        // through a hand or between the arm and the side has its vertices on
                        // opposite sides; pushing it out along one side's normal pulls it into
                        // the other (on brian's cuffs that made the solve diverge).
                        bool same_side = true;
                        for (int j = 0; j < 3 && same_side; ++j) {
                            Vec3 g{0, 0, 0};
                            collider_->signed_distance(x[t[j]], &g);
                            same_side = dot(g, nn) >= 0.5 * norm(g);
                        }
                        if (!same_side) {
                            continue;
                        }
                        const Vec3 tv = sub(b, x[t[0]]), qv = cross(tv, e1);
                        const double u = dot(tv, pv) / det, v = dot(nn, qv) / det;
                        const double along = dot(e2, qv) / det;
                        if (along < best) {
                            best = along;
                            const double uu = std::clamp(u, 0.0, 1.0),
                                         vv = std::clamp(v, 0.0, 1.0 - uu);
                            c.v[0] = t[0];
                            c.v[1] = t[1];
                            c.v[2] = t[2];
                            c.w[0] = 1 - uu - vv;
                            c.w[1] = uu;
                            c.w[2] = vv;
                            c.count = 3;
                        }
                    }
                }
            });
    };

    std::vector<double> grad(3 * m);
    // Coulomb friction at the vertices resting on the body (the fabric's coefficient μ): a
    // tangential spring of stiffness 10·k_ref to an anchor, which slips when the spring's force
    // exceeds μ times the normal force (a return mapping after each step). It acts from
    // iteration RelaxOptions::friction_from_iteration on: before, the cloth slides to give up
    // the stretch that the sub-stepped drape left at the contacts (anchors set at once would
    // keep it).
    bool friction = false;
    const double kt = 10 * k_ref;
    std::vector<Vec3> anchor(n);
    std::vector<std::uint8_t> anchored(n, 0);
    std::vector<std::size_t> vertex_point(n, std::size_t(-1));
    for (std::size_t k = 0; k < points.size(); ++k) {
        if (points[k].count == 1) {
            vertex_point[points[k].v[0]] = k;
        }
    }
    // One term ½·C²/α with the gradients grads[k] of C at the vertices v[k].
    auto term = [&](double C, double inv_alpha, const std::uint32_t* v, const Vec3* grads, int k,
                    bool with_grad, bool hessian) {
        for (int a = 0; a < k && with_grad; ++a) {
            if (dof[v[a]] >= 0) {
                double* g = &grad[3 * std::size_t(dof[v[a]])];
                for (int r = 0; r < 3; ++r) {
                    g[r] += inv_alpha * C * grads[a][r];
                }
            }
        }
        for (int a = 0; a < k && hessian; ++a) {
            for (int b = 0; b < k; ++b) {
                if (dof[v[a]] < 0 || dof[v[b]] < 0) {
                    continue;
                }
                double* B = &blocks[block_index(v[a], v[b])];
                for (int r = 0; r < 3; ++r) {
                    for (int q = 0; q < 3; ++q) {
                        B[3 * r + q] += inv_alpha * grads[a][r] * grads[b][q];
                    }
                }
            }
        }
        return 0.5 * inv_alpha * C * C;
    };
    // E(x); with_grad fills grad, hessian the blocks (elastic part only), both query the body.
    auto energy = [&](const std::vector<Vec3>& x, bool with_grad, bool hessian) {
        if (with_grad) {
            std::fill(grad.begin(), grad.end(), 0.0);
        }
        if (hessian) {
            std::fill(blocks.begin(), blocks.end(), 0.0);
        }
        double e = 0;
        for (const TriangleConstraint& c : tris_) {
            Vec3 f[2] = {{0, 0, 0}, {0, 0, 0}};
            for (int k = 0; k < 3; ++k) {
                f[0] = add(f[0], scale(x[c.v[k]], c.c1[k]));
                f[1] = add(f[1], scale(x[c.v[k]], c.c2[k]));
            }
            const double* coefs[2] = {c.c1, c.c2};
            const double alphas[2] = {c.alpha_warp, c.alpha_weft};
            const double len[2] = {norm(f[0]), norm(f[1])};
            for (int d = 0; d < 2; ++d) {
                if (alphas[d] < 0 || len[d] < 1e-12) {
                    continue;
                }
                const Vec3 u = scale(f[d], 1 / len[d]);
                const Vec3 g[3] = {scale(u, coefs[d][0]), scale(u, coefs[d][1]),
                                   scale(u, coefs[d][2])};
                e += term(len[d] - 1, 1 / alphas[d], c.v, g, 3, with_grad, hessian);
                // Geometric stiffness of a stretched fibre, (C/α)·∇²C with ∇²C = c_k·c_l·(I −
                // u·uᵀ)/|f|.
                if (!hessian || len[d] <= 1) {
                    continue;
                }
                const double sg = (len[d] - 1) / (alphas[d] * len[d]);
                for (int a = 0; a < 3; ++a) {
                    for (int b = 0; b < 3; ++b) {
                        if (dof[c.v[a]] < 0 || dof[c.v[b]] < 0) {
                            continue;
                        }
                        double* B = &blocks[block_index(c.v[a], c.v[b])];
                        const double wt = sg * coefs[d][a] * coefs[d][b];
                        for (int r = 0; r < 3; ++r) {
                            for (int q = 0; q < 3; ++q) {
                                B[3 * r + q] += wt * ((r == q ? 1.0 : 0.0) - u[r] * u[q]);
                            }
                        }
                    }
                }
            }
            if (c.alpha_shear >= 0 && len[0] > 1e-12 && len[1] > 1e-12) {
                const Vec3 u1 = scale(f[0], 1 / len[0]), u2 = scale(f[1], 1 / len[1]);
                const double C = dot(u1, u2);
                const Vec3 d1 = scale(sub(u2, scale(u1, C)), 1 / len[0]);
                const Vec3 d2 = scale(sub(u1, scale(u2, C)), 1 / len[1]);
                Vec3 g[3];
                for (int k = 0; k < 3; ++k) {
                    g[k] = add(scale(d1, c.c1[k]), scale(d2, c.c2[k]));
                }
                e += term(C, 1 / c.alpha_shear, c.v, g, 3, with_grad, hessian);
            }
        }
        for (const BendConstraint& c : bends_) {
            double theta;
            Vec3 g[4];
            if (!(c.alpha > 0) ||
                !internal::dihedral(x[c.v[0]], x[c.v[1]], x[c.v[2]], x[c.v[3]], theta, g)) {
                continue;
            }
            e += term(theta, 1 / c.alpha, c.v, g, 4, with_grad, hessian);
        }
        for (std::size_t k = 0; k < stitches_.size(); ++k) {
            const Stitch& st = stitches_[k];
            const std::uint32_t v[2] = {st.a, st.b};
            const double inv_alpha = 1 / alpha_or_hard(stitch_alpha_[k]);
            const Vec3 d = sub(x[st.a], x[st.b]);
            if (st.rest_mm == 0) {  // ½·|d|²/α: one term per axis
                for (int r = 0; r < 3; ++r) {
                    Vec3 g[2] = {{0, 0, 0}, {0, 0, 0}};
                    g[0][r] = 1;
                    g[1][r] = -1;
                    e += term(d[r], inv_alpha, v, g, 2, with_grad, hessian);
                }
            } else if (norm(d) > 1e-12) {
                const Vec3 u = scale(d, 1 / norm(d));
                const Vec3 g[2] = {u, scale(u, -1)};
                e += term(norm(d) - st.rest_mm, inv_alpha, v, g, 2, with_grad, hessian);
            }
        }
        for (std::size_t k = 0; k < attachments_.size(); ++k) {
            const Attachment& at = attachments_[k];
            const double inv_alpha = 1 / alpha_or_hard(attachment_alpha_[k]);
            if (at.axis[0] != 0 || at.axis[1] != 0 || at.axis[2] != 0) {
                e += term(dot(at.axis, sub(x[at.vertex], at.target)), inv_alpha, &at.vertex,
                          &at.axis, 1, with_grad, hessian);
                continue;
            }
            for (int r = 0; r < 3; ++r) {
                Vec3 g{0, 0, 0};
                g[r] = 1;
                e += term(x[at.vertex][r] - at.target[r], inv_alpha, &at.vertex, &g, 1, with_grad,
                          hessian);
            }
        }
        for (std::size_t i = 0; i < n; ++i) {
            if (dof[i] < 0) {
                continue;
            }
            e -= mass_[i] * dot(options_.gravity, x[i]);
            for (int r = 0; r < 3 && with_grad; ++r) {
                grad[3 * std::size_t(dof[i]) + std::size_t(r)] -= mass_[i] * options_.gravity[r];
            }
        }
        if (np > 0) {
            query_points(x);
        }
        for (std::size_t k = 0; k < np; ++k) {
            const double pen = points[k].clearance - dist[k];
            if (!(pen > 0)) {
                continue;
            }
            e += 0.5 * kc * pen * pen;
            for (int a = 0; a < points[k].count && with_grad; ++a) {
                const std::int64_t d = dof[points[k].v[a]];
                if (d >= 0 && points[k].w[a] > 0) {
                    for (int r = 0; r < 3; ++r) {
                        grad[3 * std::size_t(d) + std::size_t(r)] -=
                            kc * pen * points[k].w[a] * normal[k][r];
                    }
                }
            }
        }
        for (std::size_t i = 0; i < n && friction; ++i) {
            if (!anchored[i]) {
                continue;
            }
            const Vec3& nn = normal[vertex_point[i]];
            const Vec3 d = sub(x[i], anchor[i]);
            const Vec3 u = sub(d, scale(nn, dot(d, nn)));
            e += 0.5 * kt * dot(u, u);
            const std::size_t g = 3 * std::size_t(dof[i]);
            for (int r = 0; r < 3 && with_grad; ++r) {
                grad[g + std::size_t(r)] += kt * u[r];
            }
            if (hessian) {
                double* B = &blocks[block_index(std::uint32_t(i), std::uint32_t(i))];
                for (int r = 0; r < 3; ++r) {
                    for (int q = 0; q < 3; ++q) {
                        B[3 * r + q] += kt * ((r == q ? 1.0 : 0.0) - nn[r] * nn[q]);
                    }
                }
            }
        }
        return e;
    };
    // Anchors: vertices within a tenth of their clearance of the body get one (where they are),
    // the others lose theirs; an anchor whose spring pulls harder than μ times the normal force
    // (what the rest of the cloth presses the vertex onto the body with) slips to that limit.
    auto update_anchors = [&](const std::vector<Vec3>& x) {
        bool changed = false;
        for (std::size_t i = 0; i < n && friction; ++i) {
            if (dof[i] < 0) {
                continue;
            }
            const std::size_t k = vertex_point[i];
            const bool touching = dist[k] < 1.1 * points[k].clearance;
            if (!touching) {
                changed |= anchored[i] != 0;
                anchored[i] = 0;
                continue;
            }
            if (!anchored[i]) {
                anchored[i] = 1;
                anchor[i] = x[i];
                changed = true;
                continue;
            }
            const Vec3& nn = normal[k];
            const double* g = &grad[3 * std::size_t(dof[i])];
            const double pen = std::max(points[k].clearance - dist[k], 0.0);
            const double fn = std::max(0.0, g[0] * nn[0] + g[1] * nn[1] + g[2] * nn[2] + kc * pen);
            const Vec3 d = sub(x[i], anchor[i]);
            const Vec3 u = sub(d, scale(nn, dot(d, nn)));
            const double ft = kt * norm(u);
            const double limit = fabric_.friction * fn;
            if (ft > limit) {
                anchor[i] = sub(x[i], scale(u, ft > 0 ? limit / ft : 0.0));
                changed = true;
            }
        }
        return changed;
    };
    // Puts the contact points of x that are inside their clearance back onto it (vertices, then
    // midpoints by moving both ends; a few rounds, the distance being a grid's).
    auto push_out = [&](std::vector<Vec3>& x) {
        for (int round = 0; round < 3; ++round) {
            query_points(x);
            bool any = false;
            for (std::size_t k = 0; k < np; ++k) {
                const double pen = points[k].clearance - dist[k];
                if (!(pen > 0)) {
                    continue;
                }
                any = true;
                for (int a = 0; a < points[k].count; ++a) {
                    const std::uint32_t v = points[k].v[a];
                    if (dof[v] >= 0 && points[k].w[a] > 0) {
                        x[v] = add(x[v], scale(normal[k], pen));
                    }
                }
            }
            if (!any) {
                break;
            }
        }
    };

    std::vector<Vec3> x = x_, trial(n);
    using SpMat = Eigen::SparseMatrix<double>;
    const Eigen::Index dim = Eigen::Index(3 * m);
    std::vector<Eigen::Triplet<double>> trip;
    trip.reserve(9 * cols.size());
    SpMat K(dim, dim);
    Eigen::CholmodSupernodalLLT<SpMat> llt;
    // A factorization that fails (not positive definite) is answered below by a shorter step;
    // CHOLMOD's own warning on stderr would only be noise.
    llt.cholmod().print = 0;
    bool analysed = false;
    double h = ro.initial_step_seconds;
    double trust = 1;  // mm: the largest vertex move of a step; grows while whole steps succeed
    pair_body(x);
    double e = energy(x, true, true);
    rep.energy_before_j = e * 1e-6;
    const int friction_from = ro.friction_from_iteration;
    std::vector<std::uint8_t> held(np, 0);
    Eigen::VectorXd rhs(dim), step(dim);
    int rejected_in_a_row = 0, settled_in_a_row = 0;
    rep.stop = "iterations";
    for (int it = 0; it < ro.max_iterations; ++it) {
        rep.iterations = it + 1;
        if (it == friction_from && collider_ && fabric_.friction > 0) {
            friction = true;
            update_anchors(x);
            e = energy(x, true, true);
        }
        const double inv_h2 = 1 / (h * h);
        // Active set, updated once per iteration: every point inside its clearance, and those the
        // last solve took into the body or did not pull off it while they are still within a
        // tenth of their clearance of it.
        for (std::size_t k = 0; k < np; ++k) {
            held[k] =
                (held[k] && dist[k] < 1.1 * points[k].clearance) || dist[k] < points[k].clearance;
        }
        bool solved = false;
        {
            // The system: elastic blocks, M/h², and for every held point the linearised contact
            // n·Δ = c − d as a stiff spring ½·k_c·(n·Δ − (c − d))².
            system = blocks;
            for (std::size_t i = 0; i < n; ++i) {
                if (dof[i] >= 0) {
                    double* B = &system[block_index(std::uint32_t(i), std::uint32_t(i))];
                    for (int r = 0; r < 3; ++r) {
                        B[4 * r] += mass_[i] * inv_h2;
                    }
                }
            }
            for (Eigen::Index k = 0; k < dim; ++k) {
                rhs[k] = -grad[std::size_t(k)];
            }
            for (std::size_t k = 0; k < np; ++k) {
                if (!held[k]) {
                    continue;
                }
                const ContactPoint& c = points[k];
                const double pen = c.clearance - dist[k];
                const int ends = c.count;
                for (int a = 0; a < ends; ++a) {
                    if (dof[c.v[a]] < 0) {
                        continue;
                    }
                    // E's own penalty already pushes a point inside its clearance out.
                    if (pen < 0) {
                        for (int r = 0; r < 3; ++r) {
                            rhs[Eigen::Index(3 * dof[c.v[a]] + r)] +=
                                kc * pen * c.w[a] * normal[k][r];
                        }
                    }
                    for (int b = 0; b < ends; ++b) {
                        if (dof[c.v[b]] < 0) {
                            continue;
                        }
                        double* B = &system[block_index(c.v[a], c.v[b])];
                        const double wt = kc * c.w[a] * c.w[b];
                        for (int r = 0; r < 3; ++r) {
                            for (int q = 0; q < 3; ++q) {
                                B[3 * r + q] += wt * normal[k][r] * normal[k][q];
                            }
                        }
                    }
                }
            }
            trip.clear();
            for (std::size_t r = 0; r < m; ++r) {
                for (std::size_t j = row_start[r]; j < row_start[r + 1]; ++j) {
                    const std::size_t c = std::size_t(dof[cols[j]]);
                    for (int a = 0; a < 3; ++a) {
                        for (int b = 0; b < 3; ++b) {
                            trip.emplace_back(Eigen::Index(3 * r + std::size_t(a)),
                                              Eigen::Index(3 * c + std::size_t(b)),
                                              system[9 * j + std::size_t(3 * a + b)]);
                        }
                    }
                }
            }
            K.setFromTriplets(trip.begin(), trip.end());
            if (!analysed) {
                llt.analyzePattern(K);
                analysed = true;
            }
            llt.factorize(K);
            solved = llt.info() == Eigen::Success;
            if (solved) {
                step = llt.solve(rhs);
            }
            // Release the held points the solution pulls off the body; hold the free ones it
            // takes into it (from the next iteration on). From release_until_iteration on
            // points are only added: the set stops changing and Newton converges (a point the
            // cloth would lift off by then stays on the body).
            const bool may_release = it < ro.release_until_iteration;
            for (std::size_t k = 0; k < np && solved; ++k) {
                double out = 0;
                for (int a = 0; a < points[k].count; ++a) {
                    const std::int64_t d = dof[points[k].v[a]];
                    if (d >= 0 && points[k].w[a] > 0) {
                        for (int r = 0; r < 3; ++r) {
                            out += points[k].w[a] * normal[k][r] * step[Eigen::Index(3 * d + r)];
                        }
                    }
                }
                const double pen = points[k].clearance - dist[k];
                if (may_release && held[k] && out > pen + 1e-6 && pen <= 0) {
                    held[k] = 0;
                } else if (!held[k] && out < pen - 1e-6) {
                    held[k] = 1;
                }
            }
        }
        if (!solved) {
            h *= 0.25;
            if (h < 1e-9) {
                rep.stop = "damping";
                break;
            }
            continue;
        }
        double longest = 0;
        for (std::size_t r = 0; r < m; ++r) {
            longest = std::max(longest, step.segment<3>(Eigen::Index(3 * r)).norm());
        }
        const bool limited = longest > trust;
        if (limited) {
            step *= trust / longest;
        }
        bool accepted = false;
        double t = 1;
        for (int ls = 0; ls < 8; ++ls, t *= 0.5) {
            for (std::size_t i = 0; i < n; ++i) {
                trial[i] = x[i];
                if (dof[i] >= 0) {
                    const Eigen::Index k = Eigen::Index(3 * dof[i]);
                    trial[i] = {x[i][0] + t * step[k], x[i][1] + t * step[k + 1],
                                x[i][2] + t * step[k + 2]};
                }
            }
            if (np > 0) {
                push_out(trial);
            }
            const double e_new = energy(trial, false, false);
            if (std::isfinite(e_new) && e_new < e) {
                accepted = true;
                break;
            }
        }
        if (!accepted) {
            h *= 0.25;
            trust *= 0.25;
            energy(x, true, true);  // the distances and normals of x again
            if (h < 1e-9) {
                rep.stop = "damping";
                break;
            }
            ++rejected_in_a_row;
            if (ro.stall_rejections > 0 && rejected_in_a_row >= ro.stall_rejections) {
                rep.stop = "stalled";
                break;
            }
            continue;
        }
        rejected_in_a_row = 0;
        double max_move = 0;
        std::size_t moving = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const double d = norm(sub(trial[i], x[i]));
            max_move = std::max(max_move, d);
            moving += d > 0.3 ? 1 : 0;
        }
        x.swap(trial);
        pair_body(x);
        e = energy(x, true, true);
        if (update_anchors(x)) {
            e = energy(x, true, true);
        }
        rep.last_max_move_mm = max_move;
        rep.moving_fraction = double(moving) / double(n);
        h = std::min(2 * h, 10.0);
        if (t == 1) {
            trust = limited ? std::min(2 * trust, 50.0) : std::max(trust, 2 * longest);
        }
        // Converged: a whole Newton step (cut neither by the trust radius nor by the line
        // search) that moved no vertex more than the tolerance.
        if (t == 1 && !limited && max_move < ro.tolerance_mm) {
            rep.converged = true;
            rep.stop = "converged";
            break;
        }
        settled_in_a_row =
            it >= ro.release_until_iteration && double(moving) <= ro.settle_fraction * double(n)
                ? settled_in_a_row + 1
                : 0;
        if (ro.settle_iterations > 0 && settled_in_a_row >= ro.settle_iterations) {
            rep.stop = "settled";
            break;
        }
    }
    // Self-check: the net force left on each free vertex against its weight. The body's reaction
    // balances a push into it at a vertex that rests on it: that part is not a residual.
    std::vector<Vec3> force(n, Vec3{0, 0, 0});
    for (std::size_t i = 0; i < n; ++i) {
        if (dof[i] >= 0) {
            const double* g = &grad[3 * std::size_t(dof[i])];
            force[i] = {-g[0], -g[1], -g[2]};
        }
    }
    for (std::size_t k = 0; k < np; ++k) {
        if (dist[k] > 1.01 * points[k].clearance) {
            continue;
        }
        ++(points[k].body == kNoBody ? rep.contacts : rep.body_point_contacts);
        for (int a = 0; a < points[k].count; ++a) {
            const std::uint32_t v = points[k].v[a];
            if (dof[v] < 0 || points[k].w[a] == 0) {
                continue;
            }
            const double into = dot(force[v], normal[k]);
            if (into < 0) {
                force[v] = sub(force[v], scale(normal[k], into));
            }
        }
    }
    const double gmag = norm(options_.gravity);
    Vec3 total{0, 0, 0};
    double weight = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (dof[i] < 0) {
            continue;
        }
        total = add(total, force[i]);
        weight += mass_[i] * gmag;
        if (gmag > 0) {
            rep.max_residual_of_weight =
                std::max(rep.max_residual_of_weight, norm(force[i]) / (mass_[i] * gmag));
        }
    }
    rep.total_residual_of_weight = weight > 0 ? norm(total) / weight : 0;
    rep.energy_after_j = e * 1e-6;
    x_ = x;
    p_ = x;
    std::fill(v_.begin(), v_.end(), Vec3{0, 0, 0});
    return finish();
}

}  // namespace tapeline::garment
