// Options, inputs and reports of the cloth solver (drape_solver.h), without CGAL or Eigen, so that
// loggers, the command-line tool and test facades can include them cheaply (DESIGN.md §3, §5).
//
// Units: positions in millimetres, time in seconds, mass from the fabric's areal density; the
// solver works in whatever frame the caller gives it (the garment module uses the body's canonical
// frame: y up, z to the front).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <string>
#include <vector>

namespace tapeline::garment {

using Vec3 = std::array<double, 3>;
using Tri = std::array<std::uint32_t, 3>;
using UV = std::array<double, 2>;

/// Mechanical parameters of a fabric, as the solver uses them (SI units per metre of width; the
/// fabric catalogue maps lab measurements to these). The defaults are the catalogue's
/// cotton_jersey (fabric_lab.h).
struct FabricParams {
    std::string name = "cotton_jersey";  ///< catalogue name or file
    double density_g_m2 = 180;           ///< areal density, g/m²
    /// Tensile stiffness along the warp (grain) and the weft: force per unit width per unit
    /// strain, N/m.
    ///@{
    double stretch_warp_n_m = 1500, stretch_weft_n_m = 800;
    ///@}
    double shear_n_m = 200;  ///< in-plane shear stiffness, N/m per radian of shear angle
    /// Bending rigidity of a strip cut along the warp (curvature along the warp), µN·m
    /// (= 1e-6 N·m²/m); the rigidity of every direction when the two below are negative.
    double bending_un_m = 2;
    double friction = 0.3;      ///< Coulomb friction coefficient against the body
    double thickness_mm = 1.0;  ///< collision thickness (cloth–body and cloth–cloth)
    /// Bending rigidity of a strip cut along the weft, µN·m; negative: bending_un_m.
    double bending_weft_un_m = -1;
    /// Bending rigidity of a strip cut on the 45° bias, µN·m; negative: the mean of warp and weft.
    double bending_bias_un_m = -1;
    /// Velocity damping of the fabric's own motion, 1/s (0: none). The solver itself takes
    /// DrapeOptions::damping_per_second; callers that build options from a fabric add this.
    double damping_per_second = 0;
};

/// How the solver steps (XPBD with small sub-steps).
struct DrapeOptions {
    double frame_seconds = 1.0 / 30;  ///< one step() advances this much simulated time
    int substeps = 10;                ///< sub-steps per frame
    int iterations = 1;               ///< constraint passes per sub-step
    Vec3 gravity{0, -9810, 0};        ///< mm/s²
    double damping_per_second = 0.5;  ///< velocity damping rate (fraction lost per second)
    /// Distance the cloth keeps from the collider, mm (0: the fabric's thickness). Cloth–cloth
    /// contacts keep the fabric's thickness.
    double body_clearance_mm = 0;
    bool self_collision = true;  ///< cloth–cloth proximity constraints
    /// Edge–edge pairs as well as vertex–triangle ones (with self_collision): catches edges that
    /// cross like an X, which long edges against a thin cloth let through. Off by default: at
    /// 20 mm the drape takes 2.3–4.4 times as long, and garments came out with fewer crossings
    /// on some bodies and more on others (docs/garment.md).
    bool edge_edge_collision = false;
    /// Untangling (with self_collision): at the start of every frame the cloth edges crossing
    /// cloth triangles are found (exact predicates), both sides of every crossing move, at most
    /// four thicknesses, in the direction that shortens the curve along which the cloth cuts
    /// itself (Volino, Magnenat-Thalmann 2006), and the cloth–cloth contacts between vertices on
    /// those crossings rest for the frame, so that the layers can pass back (drape_solver.h,
    /// untangle()). On twelve drapes at 20 mm it leaves half the crossings (docs/garment.md).
    /// On very coarse cloth resting across other cloth it can let it through (the edge–edge test
    /// runs without it).
    bool untangle = true;
    /// Long-range attachments (tethers, Kim, Chentanez, Müller 2012) from the pinned vertices:
    /// every other vertex is kept within `tether_stretch` times its rest distance (shortest path
    /// over the rest edges and stitches) of its nearest pinned vertex. Bounds the stretch that
    /// XPBD's few passes leave in cloth hanging from pins (see the solver's header); 0 (default):
    /// no tethers; otherwise >= 1.
    double tether_stretch = 0;
    int threads = 0;  ///< 0: all cores (TBB default)
    /// A step fails (SolverFailure naming the frame) when a position is not finite, a speed
    /// exceeds this (mm/s), or kinetic energy grows this many times over a frame while no
    /// external work explains it.
    double max_speed_mm_s = 2.0e5;
    /// Kinetic energy may grow at most this many times over a frame beyond what gravity's work
    /// and a floor (the whole cloth moving at 1 m/s) explain.
    double max_energy_growth = 100;
};

/// How the body's signed-distance grid (collider.h) is built.
struct ColliderOptions {
    double cell_mm = 5;  ///< grid spacing, mm
    /// Half-width of the stored band around the surface, mm (0: four cells). Inside it the
    /// distance is interpolated from the grid; outside it see `exact_outside_band`.
    double band_mm = 0;
    int threads = 0;  ///< build threads, 0: all cores (TBB default)
    /// Outside the band: false returns a cheap bound (right sign, magnitude between the band and
    /// the true distance); true queries the triangles exactly (slower, about a microsecond).
    bool exact_outside_band = false;
};

/// A vertex pulled to a point (moving targets are set again between steps).
struct Attachment {
    /// Index of the pulled vertex in ClothModel::positions.
    std::uint32_t vertex = 0;
    /// The point it is pulled to, mm.
    Vec3 target{0, 0, 0};
    double compliance = 0;  ///< XPBD compliance (inverse stiffness), mm/N; 0: hard
    /// Zero: the vertex is pulled to the point. A unit vector: only its offset from the target
    /// along this axis is pulled back (a plane through the target holds it, across which it
    /// slides freely: a waistband held at its height, dress.h).
    Vec3 axis{0, 0, 0};
};

/// Two vertices held at `rest_mm` apart (stitches: the rest length shrinks to zero).
struct Stitch {
    /// Indices of the two vertices in ClothModel::positions (distinct).
    ///@{
    std::uint32_t a = 0, b = 0;
    ///@}
    /// Distance the stitch holds them at, mm (>= 0).
    double rest_mm = 0;
    double compliance = 0;  ///< XPBD compliance, mm/N; 0: hard
};

/// The cloth as the solver sees it: vertices, triangles, and per triangle its rest shape (the 2D
/// pattern triangle, mm) with the warp direction in those coordinates.
struct ClothModel {
    std::vector<Vec3> positions;             ///< initial positions, mm
    std::vector<Tri> triangles;              ///< vertex indices
    std::vector<std::array<UV, 3>> rest_uv;  ///< per triangle corner: pattern coords, mm
    std::vector<UV> grain;                   ///< per triangle: unit warp direction in uv
    std::vector<std::uint8_t> pinned;        ///< per vertex (empty: none); pinned stay put
};

/// How DrapeSolver::relax() looks for the static equilibrium.
struct RelaxOptions {
    int max_iterations = 100;  ///< Newton iterations at most (>= 1); it stops when converged
    /// Coulomb friction holds the vertices resting on the body from this iteration on (>= 0);
    /// before it the cloth slides to give up the stretch the sub-stepped drape left at the
    /// contacts.
    int friction_from_iteration = 30;
    /// Contact points the Newton step pulls off the body leave the active set only before this
    /// iteration (>= 0); afterwards points are only added, the set stops changing and Newton
    /// converges.
    int release_until_iteration = 45;
    /// It has converged when a whole Newton step moved no vertex more than this, mm (> 0).
    double tolerance_mm = 0.1;
    /// Damping of the first iteration: the proximal term M/h² with this h, s (> 0). It doubles
    /// after every step that lowered the energy and is divided by four after one that did not.
    double initial_step_seconds = 1.0 / 30;
    /// It stops, as settled, after this many accepted steps in a row from
    /// release_until_iteration on that each moved at most `settle_fraction` of the vertices more
    /// than 0.3 mm (what the dress report counts as moving). 0 (the default) turns this off, for
    /// solves that must meet their tolerance (the buckling tests); dress() uses 5. (The tank top
    /// at 10 mm spent the last 27 of its 100 iterations on such steps.)
    int settle_iterations = 0;
    double settle_fraction = 0.001;  ///< see settle_iterations; in [0, 1]
    /// It stops, as stalled, once this many steps in a row lowered the energy at none of the
    /// eight lengths the line search tries (down to 1/128 of the step), each with four times the
    /// damping of the one before: at the round-off of the energy, or where the Newton direction
    /// has stopped being one of descent (the active set's hold of points above the body is not
    /// part of the energy). Before this rule such solves ran to max_iterations with steps of
    /// micrometres (on the T-shirt at 10 mm: 35 of its 100 iterations). 0: never.
    int stall_rejections = 4;

    /// Options for `iterations` Newton iterations whose schedule scales with them: friction
    /// from the third of them on, releases during the first half (the schedule of the wrinkle
    /// refinement, whose solves start near rest).
    static RelaxOptions proportional(int iterations) {
        RelaxOptions r;
        r.max_iterations = iterations;
        r.friction_from_iteration = iterations / 3;
        r.release_until_iteration = iterations / 2;
        return r;
    }
};

/// What relax() did.
struct RelaxReport {
    int iterations = 0;      ///< Newton iterations taken
    bool converged = false;  ///< the last iteration moved no vertex more than the tolerance
    /// Why it stopped: "converged", "settled" (RelaxOptions::settle_iterations), "stalled"
    /// (RelaxOptions::stall_rejections), "iterations" (max_iterations reached), "damping" (the
    /// step's damping grew past use after steps that failed).
    std::string stop;
    /// Potential energy (stretch, shear, bending, stitches, attachments, gravity, contact
    /// penalty) before and after, J.
    ///@{
    double energy_before_j = 0, energy_after_j = 0;
    ///@}
    double last_max_move_mm = 0;  ///< largest vertex move of the last iteration
    double moving_fraction = 0;   ///< fraction of vertices that moved more than 0.3 mm in it
    /// Largest net force left on a free vertex, as a fraction of that vertex's weight (the
    /// equilibrium's self-check; the body's push is part of the balance).
    double max_residual_of_weight = 0;
    /// Net force left over the whole cloth, as a fraction of its weight.
    double total_residual_of_weight = 0;
    /// Contact points (vertices and edge midpoints) at the body's clearance at the end.
    std::size_t contacts = 0;
    /// Body points (DrapeSolver::set_body_points) holding a cloth triangle at the end.
    std::size_t body_point_contacts = 0;
    double seconds = 0;  ///< wall time
};

/// Vertex classes after welding the stitch pairs (union–find; the representative is the smallest
/// index): `weld_map[v]` is v's welded index in [0, count).
struct Welding {
    /// Per vertex: its welded index.
    std::vector<std::uint32_t> weld_map;
    /// Number of welded vertices (vertex classes).
    std::size_t count = 0;
};

/// Welds `vertex_count` vertices along the stitch pairs `pairs` (see Welding); rest lengths and
/// compliances are ignored.
inline Welding weld_pairs(std::size_t vertex_count, const std::vector<Stitch>& pairs) {
    std::vector<std::uint32_t> parent(vertex_count);
    std::iota(parent.begin(), parent.end(), 0u);
    const auto find = [&](std::uint32_t v) {
        while (parent[v] != v) {
            parent[v] = parent[parent[v]];
            v = parent[v];
        }
        return v;
    };
    for (const Stitch& s : pairs) {
        const std::uint32_t a = find(s.a), b = find(s.b);
        if (a != b) {
            parent[std::max(a, b)] = std::min(a, b);
        }
    }
    Welding w;
    w.weld_map.assign(vertex_count, 0);
    std::vector<std::uint32_t> index(vertex_count, std::uint32_t(-1));
    for (std::uint32_t v = 0; v < vertex_count; ++v) {
        const std::uint32_t r = find(v);
        if (index[r] == std::uint32_t(-1)) {
            index[r] = std::uint32_t(w.count++);
        }
        w.weld_map[v] = index[r];
    }
    return w;
}

/// Options of DrapeSolver::smooth_fold_overs.
struct FoldOptions {
    int max_rounds = 20;  ///< find-and-smooth rounds at most (>= 0)
    /// Rings of neighbours added around the vertices of each crossing (>= 0); one more ring
    /// every five rounds, so that a fold the patch cannot flatten gets a wider one.
    int rings = 1;
    int sweeps = 5;  ///< smoothing sweeps per round (>= 1)
};

/// What DrapeSolver::smooth_fold_overs did.
struct FoldReport {
    std::size_t crossings_before = 0;  ///< cloth edges crossing cloth triangles before
    std::size_t crossings_after = 0;   ///< and after (0 unless the rounds ran out)
    int rounds = 0;                    ///< find-and-smooth rounds taken
    std::size_t vertices_moved = 0;    ///< vertices moved more than 0.3 mm
    double max_move_mm = 0;            ///< largest vertex move
    double seconds = 0;                ///< wall time
};

/// What one step() did.
struct StepReport {
    std::size_t frame = 0;          ///< frames done so far
    double simulated_seconds = 0;   ///< simulated time so far
    double max_move_mm = 0;         ///< largest vertex displacement over this frame
    double moving_fraction = 0;     ///< fraction of vertices that moved more than 0.3 mm
    double kinetic_energy_j = 0;    ///< at the end of the frame
    std::size_t contacts = 0;       ///< cloth vertices in contact with the collider
    std::size_t self_contacts = 0;  ///< cloth–cloth proximity pairs handled
    /// Cloth edges crossing cloth triangles at the frame's start (with DrapeOptions::untangle;
    /// an edge and a triangle with stitch partners for ends do not count: a seam being closed).
    std::size_t cloth_crossings = 0;
    std::size_t tether_anchors = 0;  ///< pinned vertices the tethers hang from (0: none)
    double seconds = 0;              ///< wall time of the step
};

}  // namespace tapeline::garment
