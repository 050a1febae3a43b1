// A fine drape started from a coarse one: training data for wrinkle synthesis.
//
// A coarse drape (say 20 mm edges) cannot show wrinkles of 30 mm wavelength. Draping the garment
// again at 5 mm from scratch gives wrinkles, but also a different garment-scale equilibrium (two
// independent drapes at 15 and 5 mm differed by 6 mm rms at garment scale, which drowned the
// wrinkles). Here the coarse drape is subdivided instead (subdivide.h: midpoints only, so the
// fine mesh starts exactly on the coarse surface), its vertices are nudged along their normals
// by a small seeded noise that breaks the symmetry of the flat subdivided state (compressed
// cloth that is exactly flat has no reason to buckle one way or the other), and the cloth solver
// (garment/drape_solver.h) finds the fine equilibrium from there: optionally a few sub-stepped
// frames under gravity against the body's signed-distance grid (none by default), then, from their
// state nudged again by the noise, the static solve (DrapeSolver::relax), in which compressed
// cloth buckles. The fine
// drape then differs from the coarse one by what the fine mesh can resolve and the coarse one
// could not: the wrinkles.
//
// Determinism: the noise is drawn from std::mt19937_64 (its output is fixed by the standard) and
// mapped to [-1, 1) here (std::uniform_real_distribution's mapping is not), and the solver gives
// the same result for any thread count, so the same inputs and seed give the same positions.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/core/progress.h>
#include <tapeline/draw/mesh_render.h>
#include <tapeline/garment/collider.h>
#include <tapeline/garment/drape_solver.h>
#include <tapeline/garment/garment_types.h>
#include <tapeline/garment/quality.h>
#include <tapeline/wrinkles/subdivide.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace tapeline::wrinkles {

/// How refine_drape() refines a coarse drape.
struct RefineOptions {
    int levels = 2;  ///< midpoint subdivision levels, 1..4 (each halves the edges)
    /// Largest displacement of the seeded noise along the vertex normals, mm (>= 0): breaks the
    /// symmetry of the flat subdivided state so that compressed cloth can buckle. Drawn before
    /// the frames and, when there were frames, again before the static solve (refine_drape()
    /// says why).
    double noise_mm = 0.2;
    std::uint64_t seed = 1;  ///< of that noise (same seed, same inputs: bit-identical result)
    /// Sub-stepped solver frames under gravity before the static solve. 0 (default): the static
    /// solve alone. On the tank top at 20 mm refined twice (3.4 mm edges), 30 frames of the
    /// sub-stepped solver let the fine cloth sag (p95 stretch 1.157 after a static solve of 40
    /// iterations that did not converge) where the static solve alone converged in 80 iterations
    /// at p95 1.007: the soft sub-stepped solver moves the garment itself, not only its wrinkles.
    int frames = 0;
    /// Solver options. A zero body_clearance_mm becomes the larger of the fabric's thickness and
    /// a sixth of the fine mesh's median edge (as dress() does with its resolution: a straight
    /// edge then stays out of skin curved down to a radius of 3/4 of its length). 40 sub-steps
    /// per frame, as dress() uses: with one constraint pass per sub-step cloth hanging from the
    /// body stretches by about g·h²·N²/2 over N elements (drape_solver.h), and the fine mesh has
    /// four times the elements per level of the coarse one.
    garment::DrapeOptions drape = [] {
        garment::DrapeOptions d;
        d.substeps = 40;
        return d;
    }();
    bool relax = true;  ///< static solve at the end (DrapeSolver::relax)
    /// How the static solve runs.
    garment::RelaxOptions relax_options = garment::RelaxOptions::proportional(80);
    garment::ColliderOptions collider;  ///< the body's signed-distance grid
    /// Coarse vertices held where they are (ClothModel::pinned), e.g. the clamped ends of a test
    /// strip. A fine vertex is held when every coarse corner its barycentric coordinates weigh
    /// is held, so a held coarse edge stays held along its whole length. Held vertices get no
    /// noise.
    std::vector<std::uint32_t> pinned_coarse_vertices;
};

/// What refine_drape() did.
struct RefineReport {
    std::size_t coarse_vertices = 0;  ///< of the input
    /// Of the fine mesh.
    ///@{
    std::size_t fine_vertices = 0, fine_triangles = 0;
    ///@}
    /// Fine vertices held (RefineOptions::pinned_coarse_vertices).
    std::size_t pinned_vertices = 0;
    double median_edge_mm = 0;     ///< median 3D edge of the subdivided mesh before solving
    double body_clearance_mm = 0;  ///< distance the cloth kept from the body, mm
    garment::RelaxReport relax;    ///< the static solve (iterations 0 when it did not run)
    std::size_t frames = 0;        ///< sub-stepped frames run
    /// Wall times, s: all of refine_drape(), and the frames plus the static solve.
    ///@{
    double seconds = 0, solve_seconds = 0;
    ///@}
    /// Quality figures (garment/quality.h) of the subdivided mesh before solving (noise left
    /// out) and of the fine drape; on-body split at twice the clearance, as dress() reports.
    ///@{
    garment::QualityFigures quality_before, quality_after;
    ///@}
};

/// The fine drape, where its vertices came from, and what was done.
struct RefineResult {
    garment::GarmentMesh fine;  ///< the subdivided mesh at the fine equilibrium
    Subdivision subdivision;    ///< the subdivided mesh before solving, and its coarse origins
    RefineReport report;        ///< sizes, timings, quality
};

namespace internal {

/// Uniform double in [-1, 1) from the top 53 bits of one mt19937_64 draw (the standard fixes
/// the engine's output but not std::uniform_real_distribution's).
inline double symmetric_uniform(std::mt19937_64& rng) {
    return 2.0 * (double(rng() >> 11) * 0x1.0p-53) - 1.0;
}

/// Median length of the distinct edges of `triangles` over `positions` (0 when there are none).
inline double median_edge_length(const std::vector<garment::Vec3>& positions,
                                 const std::vector<garment::Tri>& triangles) {
    std::vector<double> lengths;
    for (const auto& [a, b] : garment::internal::unique_edges(triangles)) {
        lengths.push_back(vec3::norm(vec3::sub(positions[a], positions[b])));
    }
    if (lengths.empty()) {
        return 0;
    }
    const auto mid = lengths.begin() + std::ptrdiff_t(lengths.size() / 2);
    std::nth_element(lengths.begin(), mid, lengths.end());
    return *mid;
}

}  // namespace internal

/// Refines the coarse drape `coarse` on the closed body (`body_points`, `body_triangles`: mm, the
/// garment's frame, outward oriented) in `fabric`: subdivides it, nudges it by the seeded noise,
/// runs the solver's frames and its static solve from there (see the file comment).
///
/// \throws InvalidInput naming the field: levels outside [1, 4], noise_mm negative or not
///         finite, frames negative, a pinned coarse vertex out of range; and as subdivide(), the
///         signed-distance grid (also TopologyError: a body that is not closed) and the solver
///         do on a bad coarse mesh, body, fabric or solver options.
/// \throws SolverFailure naming the frame when the simulation blows up.
inline RefineResult refine_drape(const garment::GarmentMesh& coarse,
                                 const std::vector<garment::Vec3>& body_points,
                                 const std::vector<garment::Tri>& body_triangles,
                                 const garment::FabricParams& fabric,
                                 const RefineOptions& options = {}) {
    using Clock = std::chrono::steady_clock;
    const auto seconds_since = [](Clock::time_point t) {
        return std::chrono::duration<double>(Clock::now() - t).count();
    };
    const auto t_start = Clock::now();
    const std::string where = "refine_drape: ";
    if (options.levels < 1 || options.levels > 4) {
        throw InvalidInput(where + "levels must be in [1, 4], got " +
                           std::to_string(options.levels));
    }
    if (!(std::isfinite(options.noise_mm) && options.noise_mm >= 0)) {
        throw InvalidInput(where + "noise_mm must be finite and >= 0, got " +
                           std::to_string(options.noise_mm));
    }
    if (options.frames < 0) {
        throw InvalidInput(where + "frames must be >= 0, got " + std::to_string(options.frames));
    }
    for (std::size_t i = 0; i < options.pinned_coarse_vertices.size(); ++i) {
        const std::uint32_t v = options.pinned_coarse_vertices[i];
        if (v >= coarse.positions.size()) {
            throw InvalidInput(where + "pinned_coarse_vertices[" + std::to_string(i) +
                               "] names vertex " + std::to_string(v) + " of " +
                               std::to_string(coarse.positions.size()));
        }
    }

    RefineResult out;
    RefineReport& rep = out.report;
    out.subdivision = subdivide(coarse, options.levels);
    const Subdivision& sub = out.subdivision;
    const garment::GarmentMesh& mesh = sub.mesh;
    const std::size_t n = mesh.positions.size();
    rep.coarse_vertices = coarse.positions.size();
    rep.fine_vertices = n;
    rep.fine_triangles = mesh.triangles.size();
    rep.median_edge_mm = internal::median_edge_length(mesh.positions, mesh.triangles);

    // The cloth: the fine mesh with its pattern triangles as rest shapes.
    garment::ClothModel cloth;
    cloth.positions = mesh.positions;
    cloth.triangles = mesh.triangles;
    cloth.rest_uv = mesh.uv;
    cloth.grain = mesh.grain.empty()
                      ? std::vector<garment::UV>(mesh.triangles.size(), garment::UV{0, 1})
                      : mesh.grain;
    if (!options.pinned_coarse_vertices.empty()) {
        std::vector<std::uint8_t> coarse_pinned(coarse.positions.size(), 0);
        for (const std::uint32_t v : options.pinned_coarse_vertices) {
            coarse_pinned[v] = 1;
        }
        cloth.pinned.assign(n, 0);
        for (std::size_t v = 0; v < n; ++v) {
            const garment::Tri& t = coarse.triangles[sub.coarse_triangle[v]];
            bool held = false;  // a vertex no triangle names has all-zero weights: not held
            bool all = true;
            for (std::size_t k = 0; k < 3; ++k) {
                if (sub.barycentric[v][k] != 0) {
                    held = true;
                    all = all && coarse_pinned[t[k]];
                }
            }
            cloth.pinned[v] = held && all ? 1 : 0;
            rep.pinned_vertices += cloth.pinned[v];
        }
    }
    // Seeded noise along the area-weighted vertex normals (of the positions it is added to);
    // one draw per vertex, held or not, so that the noise of a vertex does not depend on which
    // others are held.
    std::mt19937_64 rng(options.seed);
    const auto nudge = [&](std::vector<garment::Vec3>& x, const std::vector<std::uint8_t>& held) {
        const std::vector<garment::Vec3> normals = draw::vertex_normals(x, mesh.triangles);
        for (std::size_t v = 0; v < x.size(); ++v) {
            const double r = internal::symmetric_uniform(rng);
            if (held.empty() || !held[v]) {
                x[v] = vec3::add(x[v], vec3::scale(normals[v], options.noise_mm * r));
            }
        }
    };
    nudge(cloth.positions, cloth.pinned);

    garment::DrapeOptions drape_options = options.drape;
    if (drape_options.body_clearance_mm == 0) {
        drape_options.body_clearance_mm = std::max(fabric.thickness_mm, rep.median_edge_mm / 6);
    }
    rep.body_clearance_mm = drape_options.body_clearance_mm;
    const double band = 2 * rep.body_clearance_mm;
    // The grid first: it checks the body (closed, oriented) before the quality figures use it.
    const garment::SignedDistanceGrid sdf(body_points, body_triangles, options.collider);
    rep.quality_before = garment::garment_quality(body_points, body_triangles, mesh, 0, 0, band);
    const auto t_solve = Clock::now();
    auto solver =
        std::make_unique<garment::DrapeSolver>(std::move(cloth), fabric, drape_options, &sdf);
    double moving_fraction = 0;
    {
        Progress progress("refine: draping", std::size_t(options.frames));
        for (int f = 0; f < options.frames; ++f) {
            const garment::StepReport s = solver->step();
            moving_fraction = s.moving_fraction;
            ++rep.frames;
            progress.note("moving " + std::to_string(int(100 * s.moving_fraction)) +
                          " %, cloth crossings " + std::to_string(s.cloth_crossings));
            progress.advance();
        }
    }
    if (options.relax) {
        Progress progress("refine: static solve");
        // The static solve cannot leave an unstable equilibrium: its Hessian leaves out the
        // negative stiffness of compressed fibres, so from a flat compressed state it converges
        // on the spot. The frames can flatten the noise away before anything buckles (a strip
        // held at 95 % on a table, 20 mm coarse: at 5 mm it buckles within the first frame, at
        // 2.5 and 1.25 mm it lies flat on the table after one frame and the static solve stayed
        // there, 0.02 mm high and still 5 % short), so the static solve starts from the frames'
        // state nudged by a second draw of the noise (a new solver: DrapeSolver cannot be given
        // positions).
        if (rep.frames > 0 && options.noise_mm > 0) {
            garment::ClothModel again = solver->model();
            again.positions = solver->positions();
            nudge(again.positions, again.pinned);
            solver = std::make_unique<garment::DrapeSolver>(std::move(again), fabric, drape_options,
                                                            &sdf);
        }
        rep.relax = solver->relax(options.relax_options);
        progress.note(std::to_string(rep.relax.iterations) + " iterations, last move " +
                      std::to_string(rep.relax.last_max_move_mm).substr(0, 6) + " mm");
        progress.finish();
        moving_fraction = rep.relax.moving_fraction;
    }
    rep.solve_seconds = seconds_since(t_solve);

    out.fine = mesh;
    out.fine.positions = solver->positions();
    rep.quality_after =
        garment::garment_quality(body_points, body_triangles, out.fine, moving_fraction, 0, band);
    rep.seconds = seconds_since(t_start);
    return out;
}

}  // namespace tapeline::wrinkles
