// Dressing a body: place the pieces of a pattern around it (placement.h), sew them along
// geodesic strings (stitching.h), drape them under gravity with the cloth solver
// (drape_solver.h) against the body's signed-distance grid (collider.h), weld the seams and
// measure the result (quality.h).
//
// The simulation runs in two phases. Sewing: gravity off, each stitch pair pulled along its string
// to the string's middle over SewingOptions::sew_seconds (garment tools sew before they drape,
// so that unsewn pieces do not fall off the body). Drape: the pairs the sewing closed (within
// SewingOptions::weld_within_mm) are welded into single vertices, the others are held by
// zero-length stitches, and a new solver with gravity on runs from the sewn state for
// settle_seconds and then, with the damping raised to settle_damping_per_second, until at most
// 1 % of the vertices still move more than 0.3 mm per frame (or max_extra_seconds more).
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/core/progress.h>
#include <tapeline/draw/mesh_render.h>
#include <tapeline/garment/collider.h>
#include <tapeline/garment/drape_solver.h>
#include <tapeline/garment/garment_types.h>
#include <tapeline/garment/openings.h>
#include <tapeline/garment/placement.h>
#include <tapeline/garment/quality.h>
#include <tapeline/garment/stitching.h>
#include <tapeline/garment/unfold.h>
#include <tapeline/garment/waistband.h>
#include <tapeline/measurement/body.h>
#include <tapeline/pattern/meshing.h>
#include <tapeline/pattern/validate.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace tapeline::garment {

/// The draped garment and how it was made.
struct DressResult {
    GarmentMesh garment;          ///< welded, canonical mm of the body
    std::vector<Vec3> placed;     ///< cloth after placement (unwelded), canonical mm
    ClothModel cloth;             ///< the unwelded cloth the solver ran on
    std::vector<Vec3> draped;     ///< cloth after the drape (unwelded)
    std::vector<double> stretch;  ///< per garment triangle: largest principal stretch
    SewingPlan sewing;            ///< pairs and strings
    /// What was done, how long it took and the quality gates.
    DressReport report;
};

namespace internal {

inline double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// Cloth edges crossing cloth triangles of another piece (placement check).
inline std::size_t piece_crossings(const std::vector<Vec3>& x, const std::vector<Tri>& tris,
                                   const std::vector<std::uint32_t>& tri_piece) {
    // Pieces are disjoint meshes here: an edge of one crossing a triangle of another is two
    // pieces meeting before they are sewn. The piece of an edge: that of any triangle holding it.
    std::vector<std::uint32_t> piece_of_vertex(x.size(), 0);
    for (std::size_t f = 0; f < tris.size(); ++f) {
        for (int k = 0; k < 3; ++k) {
            piece_of_vertex[tris[f][k]] = tri_piece[f];
        }
    }
    std::size_t n = 0;
    for_each_edge_triangle_crossing(x, tris, [&](std::uint32_t a, std::uint32_t, std::size_t t) {
        n += piece_of_vertex[a] != tri_piece[t] ? 1 : 0;
    });
    return n;
}

/// The mean position of each weld class.
inline std::vector<Vec3> welded_positions(const std::vector<Vec3>& x, const Welding& w) {
    std::vector<Vec3> out(w.count, Vec3{0, 0, 0});
    std::vector<int> count(w.count, 0);
    for (std::size_t v = 0; v < x.size(); ++v) {
        out[w.weld_map[v]] = vec3::add(out[w.weld_map[v]], x[v]);
        ++count[w.weld_map[v]];
    }
    for (std::size_t v = 0; v < w.count; ++v) {
        out[v] = vec3::scale(out[v], 1.0 / count[v]);
    }
    return out;
}

/// Each triangle of `triangles` with its corners' weld classes, those whose corners stay in three
/// classes only: a triangle two of whose corners the weld merges (a seam pulled shut across it,
/// where two stitch pairs share a triangle's edge) has no area, and kept it would be a degenerate
/// face in the solver, in the files written and in every check of the mesh.
inline std::vector<std::pair<std::size_t, Tri>> welded_triangles(const std::vector<Tri>& triangles,
                                                                 const Welding& w) {
    std::vector<std::pair<std::size_t, Tri>> out;
    out.reserve(triangles.size());
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        const Tri& c = triangles[t];
        const Tri r{w.weld_map[c[0]], w.weld_map[c[1]], w.weld_map[c[2]]};
        if (r[0] != r[1] && r[1] != r[2] && r[0] != r[2]) {
            out.push_back({t, r});
        }
    }
    return out;
}

/// The cloth with the vertices of each weld class merged at their mean, its collapsed triangles
/// left out (welded_triangles). Rest shapes and grain stay per triangle.
inline ClothModel welded_cloth(const ClothModel& cloth, const Welding& w) {
    ClothModel m;
    m.positions = welded_positions(cloth.positions, w);
    for (const auto& [t, r] : welded_triangles(cloth.triangles, w)) {
        m.triangles.push_back(r);
        m.rest_uv.push_back(cloth.rest_uv[t]);
        m.grain.push_back(cloth.grain[t]);
    }
    return m;
}

/// The garment of `cloth` at positions `x` (per cloth vertex) with the vertices of each weld
/// class merged at their mean, its collapsed triangles left out (welded_triangles). Pattern
/// coordinates, grain and piece stay with each triangle kept.
inline GarmentMesh welded_garment(const ClothModel& cloth, const std::vector<Vec3>& x,
                                  const Welding& w, const std::vector<std::uint32_t>& tri_piece) {
    GarmentMesh g;
    g.positions = welded_positions(x, w);
    for (const auto& [t, r] : welded_triangles(cloth.triangles, w)) {
        g.triangles.push_back(r);
        g.uv.push_back(cloth.rest_uv[t]);
        g.grain.push_back(cloth.grain[t]);
        g.triangle_piece.push_back(tri_piece[t]);
    }
    return g;
}

}  // namespace internal

/// Dresses `body` (canonical mm, closed: make_body fills small holes) whose landmarks are
/// `landmarks` in `pattern` (graded or not, mm). See the file comment.
///
/// \throws InvalidInput naming the pattern or piece: no seams, a piece with no body region (leave
///         it out with DressOptions::without_pieces), an unknown piece to leave out, a landmark
///         placement needs that was not found, bad options.
/// \throws SolverFailure naming the frame when the simulation blows up.
inline DressResult dress(const measurement::Body& body, const measurement::LandmarkSet& landmarks,
                         pattern::Pattern pattern, const DressOptions& o) {
    using Clock = std::chrono::steady_clock;
    const auto t_start = Clock::now();
    DressResult out;
    DressReport& rep = out.report;
    const std::string where = "dress: pattern '" + pattern.name + "'";
    if (!(o.resolution_mm >= 2 && o.resolution_mm <= 100)) {
        throw InvalidInput(where + ": resolution " + std::to_string(o.resolution_mm) +
                           " mm is outside [2, 100] mm");
    }
    if (o.fold_cycles < 1) {
        throw InvalidInput("dress: fold_cycles must be >= 1, got " + std::to_string(o.fold_cycles));
    }
    check_relax_options(o.relax_options, "dress: relax_options");
    check_relax_options(o.relax_again_options, "dress: relax_again_options");
    check_fold_options(o.fold_options, "dress: fold_options");
    if (!(std::isfinite(o.waistband_sag_mm) && o.waistband_sag_mm > 0)) {
        throw InvalidInput("dress: waistband_sag_mm must be finite and > 0, got " +
                           std::to_string(o.waistband_sag_mm));
    }
    // Pieces left out, with their seams.
    for (const std::string& name : o.without_pieces) {
        if (!pattern::find_piece(pattern, name)) {
            throw InvalidInput(where + " has no piece '" + name + "' to leave out");
        }
    }
    const auto left_out = [&](const std::string& n) {
        return std::find(o.without_pieces.begin(), o.without_pieces.end(), n) !=
               o.without_pieces.end();
    };
    pattern.pieces.erase(std::remove_if(pattern.pieces.begin(), pattern.pieces.end(),
                                        [&](const pattern::Piece& p) { return left_out(p.name); }),
                         pattern.pieces.end());
    pattern.seams.erase(std::remove_if(pattern.seams.begin(), pattern.seams.end(),
                                       [&](const pattern::Seam& s) {
                                           return left_out(s.a.piece) || left_out(s.b.piece);
                                       }),
                        pattern.seams.end());
    pattern.bindings.clear();    // they may name pieces left out; dressing does not use them
    split_chain_seams(pattern);  // FreeSewing's sleeve cap against two armholes, ...
    if (pattern.pieces.empty()) {
        throw InvalidInput(where + " has no pieces left to dress");
    }
    if (pattern.seams.empty()) {
        throw InvalidInput(where +
                           " has no seams: there is nothing to sew the pieces together "
                           "with (a pattern without seams cannot be dressed)");
    }
    pattern = unfold_pieces(std::move(pattern));
    std::vector<Region> regions;
    for (const pattern::Piece& p : pattern.pieces) {
        std::string why;
        const auto r = piece_region(p, why);
        if (!r) {
            throw InvalidInput(where + ": piece '" + p.name + "' has no body region (" + why +
                               "); leave it out with --without '" + p.name + "'");
        }
        regions.push_back(*r);
    }
    // --- mesh, place
    auto t0 = Clock::now();
    pattern::MeshingOptions mo;
    mo.target_edge_mm = o.resolution_mm;
    const pattern::PatternMesh pm = pattern::mesh_pattern(pattern, mo);
    const BodyShape shape = body_shape(body.points(), body.triangles(), body.height(), landmarks);
    std::vector<std::vector<pattern::Point2>> uv;
    for (const auto& piece_mesh : pm.pieces) {
        uv.push_back(piece_mesh.uv);
    }
    const LayoutHeights heights = layout_heights(pattern, regions, uv, shape, o.placement.gap_mm);
    std::vector<PieceLayout> layouts;
    for (std::size_t i = 0; i < pattern.pieces.size(); ++i) {
        layouts.push_back(piece_layout(pattern.pieces[i], pm.pieces[i], regions[i], heights.top_y,
                                       heights.waist_y, heights.gc_shift,
                                       sleeve_front_sign(pattern, i, regions)));
    }
    std::vector<std::vector<Vec3>> xyz;
    wrap_pieces(shape, layouts, pm, o.placement, xyz);
    // --- the cloth
    ClothModel& cloth = out.cloth;
    std::vector<std::uint32_t> tri_piece;
    const auto offsets = piece_offsets(pm);
    for (std::size_t i = 0; i < pm.pieces.size(); ++i) {
        const pattern::PieceMesh& m = pm.pieces[i];
        const pattern::Piece& piece = pattern.pieces[i];
        UV grain{0, 1};
        if (piece.grain) {
            const double gx = piece.grain->to.x - piece.grain->from.x;
            const double gy = piece.grain->to.y - piece.grain->from.y;
            const double gl = std::hypot(gx, gy);
            if (gl > 1e-9) {
                grain = {gx / gl, gy / gl};
            }
        }
        for (std::size_t v = 0; v < m.uv.size(); ++v) {
            cloth.positions.push_back(xyz[i][v]);
        }
        for (const auto& t : m.triangles) {
            cloth.triangles.push_back({offsets[i] + t[0], offsets[i] + t[1], offsets[i] + t[2]});
            cloth.rest_uv.push_back({UV{m.uv[t[0]].x, m.uv[t[0]].y}, UV{m.uv[t[1]].x, m.uv[t[1]].y},
                                     UV{m.uv[t[2]].x, m.uv[t[2]].y}});
            cloth.grain.push_back(grain);
            tri_piece.push_back(std::uint32_t(i));
        }
        rep.pieces.push_back({piece.name, to_string(regions[i]), m.uv.size(), m.triangles.size()});
    }
    // The open waist edges held at their height during the drape (waistband.h).
    const std::vector<std::uint32_t> waist =
        o.waistband ? waistband_vertices(pattern, pm, offsets) : std::vector<std::uint32_t>{};
    rep.cloth_vertices = cloth.positions.size();
    rep.cloth_triangles = cloth.triangles.size();
    rep.placement_seconds = internal::seconds_since(t0);
    // --- the body's signed distance
    t0 = Clock::now();
    ColliderOptions co;
    co.cell_mm = o.sdf_cell_mm;
    const SignedDistanceGrid sdf(body.points(), body.triangles(), co);
    rep.sdf_seconds = internal::seconds_since(t0);
    // The wrap keeps its distance from the trunk and the arms' axes, not from every bump of the
    // skin: a vertex that still ends up closer than half the gap (or inside: a bust, a shoulder
    // blade, a hand near the hip) is moved out along the distance gradient to half the gap.
    for (Vec3& x : cloth.positions) {
        Vec3 grad{0, 0, 0};
        const double d = sdf.signed_distance(x, &grad);
        if (d < 0.5 * o.placement.gap_mm) {
            x = vec3::add(x, vec3::scale(grad, 0.5 * o.placement.gap_mm - d));
        }
    }
    out.placed = cloth.positions;
    for (std::size_t i = 0; i < pm.pieces.size(); ++i) {
        std::size_t inside = 0;
        for (std::uint32_t v = offsets[i]; v < offsets[i + 1]; ++v) {
            inside += sdf.signed_distance(cloth.positions[v], nullptr) < 0 ? 1 : 0;
        }
        rep.placement_vertices_inside += inside;
        rep.pieces[i].placed_inside = inside;
    }
    rep.placement_piece_intersections =
        internal::piece_crossings(cloth.positions, cloth.triangles, tri_piece);
    // --- strings
    t0 = Clock::now();
    out.sewing = sewing_pairs(pm);
    SewingPlan& plan = out.sewing;
    std::vector<std::uint8_t> cloth_limb(cloth.positions.size(), 0);
    for (std::size_t i = 0; i < pm.pieces.size(); ++i) {
        if (is_sleeve(regions[i])) {
            std::fill(cloth_limb.begin() + offsets[i], cloth_limb.begin() + offsets[i + 1], 1);
        }
    }
    compute_strings(plan, cloth.positions, body.points(), body.triangles(), sdf,
                    o.sewing.string_offset_mm, shape.is_arm, cloth_limb);
    rep.strings_seconds = internal::seconds_since(t0);
    for (std::size_t s = 0; s < pattern.seams.size(); ++s) {
        const pattern::Seam& seam = pattern.seams[s];
        SeamReport sr;
        sr.name = seam.name;
        sr.side_a_mm = pattern::length(*pattern::find_piece(pattern, seam.a.piece), seam.a);
        sr.side_b_mm = pattern::length(*pattern::find_piece(pattern, seam.b.piece), seam.b);
        double sum = 0;
        for (std::size_t k = 0; k < plan.pairs.size(); ++k) {
            if (plan.seam_of_pair[k] == s) {
                ++sr.pairs;
                sum += plan.strings[k].length();
            }
        }
        sr.string_mm = sr.pairs ? sum / double(sr.pairs) : 0;
        const double longer = std::max(sr.side_a_mm, sr.side_b_mm);
        if (longer > 0 &&
            std::abs(sr.side_a_mm - sr.side_b_mm) > o.sewing.length_mismatch * longer) {
            sr.closable = false;
            sr.problem = "its sides differ by " +
                         std::to_string(int(std::lround(std::abs(sr.side_a_mm - sr.side_b_mm)))) +
                         " mm (" + std::to_string(int(std::lround(sr.side_a_mm))) + " against " +
                         std::to_string(int(std::lround(sr.side_b_mm))) + " mm)";
        }
        rep.seams.push_back(sr);
    }
    // --- sewing phase (no gravity), then drape
    t0 = Clock::now();
    const double frame = o.drape.frame_seconds;
    // A straight cloth edge of length L held at distance c from skin curved to radius R dips
    // L²/(8R) − c into it: a sixth of the edge length (at least the fabric's thickness) keeps
    // edges out of skin curved down to R = 3L/4.
    DrapeOptions drape_options = o.drape;
    if (drape_options.body_clearance_mm == 0) {
        drape_options.body_clearance_mm = std::max(o.fabric.thickness_mm, o.resolution_mm / 6);
    }
    rep.body_clearance_mm = drape_options.body_clearance_mm;
    DrapeOptions sew_options = drape_options;
    sew_options.gravity = {0, 0, 0};
    // While the pieces are pulled together their seam edges cross each other by design (the
    // sewing solver knows no stitch partners): untangling starts with the drape.
    sew_options.untangle = false;
    StepReport last;
    std::size_t frames = 0;
    double relax_seconds = 0;  // every static solve's wall time
    {
        DrapeSolver sew(cloth, o.fabric, sew_options, &sdf);
        const std::size_t n = std::size_t(std::ceil(o.sewing.sew_seconds / frame));
        Progress progress("dress: sewing", n);
        // Each frame's targets against the last: a target that jumps (more than a stitch pull
        // moves in a frame) makes a hard pull, and is named when the sewing blows up.
        std::map<std::uint32_t, Vec3> previous;
        SewingTargetState target_state;  // a lifted target moves with its mean (no jumps)
        for (std::size_t f = 0; f < n; ++f) {
            const double sigma = double(f + 1) / double(n);
            const std::vector<Attachment> targets = sewing_targets(
                plan, sigma, o.sewing.compliance, &sdf, o.sewing.string_offset_mm, &target_state);
            double jump = 0;
            std::uint32_t jumper = 0;
            for (const Attachment& at : targets) {
                const auto it = previous.find(at.vertex);
                if (it != previous.end()) {
                    const double dj = vec3::norm(vec3::sub(at.target, it->second));
                    if (dj > jump) {
                        jump = dj;
                        jumper = at.vertex;
                    }
                }
                previous[at.vertex] = at.target;
            }
            sew.set_attachments(targets);
            try {
                last = sew.step();
            } catch (const SolverFailure& e) {
                throw SolverFailure(std::string("sewing ") + e.what() +
                                    " (largest move of a pull target into this frame: " +
                                    std::to_string(int(std::lround(jump))) + " mm, vertex " +
                                    std::to_string(jumper) + ")");
            }
            ++frames;
            progress.note("t " + std::to_string(last.simulated_seconds).substr(0, 5) +
                          " s, moving " + std::to_string(int(100 * last.moving_fraction)) + " %");
            progress.advance();
        }
        cloth.positions = sew.positions();
    }
    double simulated = frames * frame;
    // Placement only (no sewing, no drape): nothing is welded, the pieces stay as placed, so that
    // they can be looked at.
    const bool placement_only = o.sewing.sew_seconds == 0 && o.sewing.settle_seconds == 0 &&
                                o.sewing.max_extra_seconds == 0;
    {
        // Pairs the sewing brought together are welded into one vertex before the drape (a seam
        // then cannot open, and bending acts across it); pairs still apart stay stitches.
        const double weld_within =
            o.sewing.weld_within_mm > 0 ? o.sewing.weld_within_mm : 0.5 * o.resolution_mm;
        std::vector<Stitch> closed, open;
        for (const Stitch& s : placement_only ? std::vector<Stitch>{} : plan.pairs) {
            const double g = vec3::norm(vec3::sub(cloth.positions[s.a], cloth.positions[s.b]));
            (g <= weld_within ? closed : open).push_back(s);
        }
        rep.pairs_welded_before_drape = closed.size();
        const Welding pre = weld_pairs(cloth.positions.size(), closed);
        const ClothModel welded = internal::welded_cloth(cloth, pre);
        DrapeSolver drape(welded, o.fabric, drape_options, &sdf);
        if (o.body_points && o.relax) {
            // Outward unit normals (area-weighted, turned along the grid's gradient there);
            // vertices on no face of positive area are left out.
            const std::vector<Vec3> normals = draw::vertex_normals(body.points(), body.triangles());
            std::vector<Vec3> bp, bn;
            for (std::size_t v = 0; v < normals.size(); ++v) {
                if (vec3::norm(normals[v]) < 0.5) {
                    continue;
                }
                Vec3 grad{0, 0, 0};
                sdf.signed_distance(body.points()[v], &grad);
                bp.push_back(body.points()[v]);
                bn.push_back(vec3::dot(grad, normals[v]) < 0 ? vec3::scale(normals[v], -1)
                                                             : normals[v]);
            }
            drape.set_body_points(std::move(bp), std::move(bn), o.sdf_cell_mm);
        }
        std::vector<Stitch> stitches;
        for (const Stitch& s : open) {
            const std::uint32_t a = pre.weld_map[s.a], b = pre.weld_map[s.b];
            if (a != b) {
                stitches.push_back({a, b, 0.0, 0.0});
            }
        }
        drape.set_stitches(stitches);
        {
            std::vector<std::uint32_t> held;
            for (std::uint32_t v : waist) {
                held.push_back(pre.weld_map[v]);
            }
            std::sort(held.begin(), held.end());
            held.erase(std::unique(held.begin(), held.end()), held.end());
            rep.waistband_vertices = held.size();
            if (!placement_only && !held.empty()) {
                // The garment's weight under the drape's gravity (mm/s² → m/s²).
                const double weight_n =
                    drape.total_mass_kg() * vec3::norm(drape_options.gravity) * 1e-3;
                drape.set_attachments(waistband_attachments(
                    welded.positions, held,
                    waistband_compliance(weight_n, held.size(), o.waistband_sag_mm)));
            }
        }
        const std::size_t n_settle = std::size_t(std::ceil(o.sewing.settle_seconds / frame));
        const std::size_t n_max =
            n_settle + std::size_t(std::ceil(o.sewing.max_extra_seconds / frame));
        Progress progress("dress: draping", n_settle);
        for (std::size_t f = 0; f < n_max; ++f) {
            last = drape.step();
            ++frames;
            progress.note("t " + std::to_string(last.simulated_seconds).substr(0, 5) +
                          " s, moving " + std::to_string(int(100 * last.moving_fraction)) +
                          " %, cloth crossings " + std::to_string(last.cloth_crossings));
            progress.advance();
            if (f + 1 >= n_settle && last.moving_fraction <= 0.01) {
                break;
            }
            if (f + 1 == n_settle) {
                drape.set_damping(
                    std::max(o.drape.damping_per_second, o.sewing.settle_damping_per_second));
                // The crossings the untangling could undo are undone within the settling time
                // (on the shirt at 20 mm: 1541 at its start, 330 from the twelfth frame on); its
                // moves on what is left would keep the cloth from coming to rest.
                drape.set_untangle(false);
            }
        }
        simulated += double(drape.positions().empty() ? 0 : last.frame) * frame;
        // Fold-overs (DrapeSolver::smooth_fold_overs) are flattened before the static solve;
        // where the solve, which knows no cloth–cloth contact, folds cloth over again, they are
        // flattened and the solve runs again (fold_cycles solves at most). When the last flattening
        // had something to flatten, its moves count as moving in the static gate: the garment
        // is then not where a solve left it.
        const bool smooth = o.smooth_folds && !placement_only;
        const auto flatten = [&] {
            rep.folds.push_back(drape.smooth_fold_overs(o.fold_options));
            return rep.folds.back().crossings_before > 0;
        };
        const auto count_last_flattening = [&] {
            last.moving_fraction += double(rep.folds.back().vertices_moved) /
                                    double(std::max<std::size_t>(1, welded.positions.size()));
        };
        if (smooth) {
            flatten();
        }
        if (o.relax && !placement_only) {
            for (int cycle = 0;; ++cycle) {
                Progress progress("dress: static solve");
                rep.relax = drape.relax(cycle == 0 ? o.relax_options : o.relax_again_options);
                rep.relax_solves.push_back(rep.relax);
                rep.relax_runs += 1;
                relax_seconds += rep.relax.seconds;
                progress.note(std::to_string(rep.relax.iterations) + " iterations, last move " +
                              std::to_string(rep.relax.last_max_move_mm).substr(0, 6) + " mm");
                progress.finish();
                // The garment ends where the static solve left it: the static gate takes its
                // last iteration's moves (a further frame of the sub-stepped solver would sag it
                // again).
                last.moving_fraction = rep.relax.moving_fraction;
                if (!smooth || !flatten()) {
                    break;
                }
                if (cycle + 1 >= o.fold_cycles) {
                    count_last_flattening();
                    break;
                }
            }
        } else if (smooth && rep.folds.back().crossings_before > 0) {
            count_last_flattening();
        }
        out.draped.resize(cloth.positions.size());
        for (std::size_t v = 0; v < cloth.positions.size(); ++v) {
            out.draped[v] = drape.positions()[pre.weld_map[v]];
        }
    }
    rep.drape_seconds = internal::seconds_since(t0);
    rep.frames = frames;
    rep.simulated_seconds = simulated;
    // Per solver frame: the static solves' time is not a frame's.
    rep.ms_per_step_per_10k = (rep.drape_seconds - relax_seconds) * 1000.0 /
                              double(std::max<std::size_t>(frames, 1)) * 10000.0 /
                              double(std::max<std::size_t>(cloth.positions.size(), 1));
    // --- seam gaps, welding
    double gap_max = 0;
    for (std::size_t k = 0; k < plan.pairs.size(); ++k) {
        const double g =
            vec3::norm(vec3::sub(out.draped[plan.pairs[k].a], out.draped[plan.pairs[k].b]));
        SeamReport& sr = rep.seams[plan.seam_of_pair[k]];
        sr.gap_mean_mm += g / double(std::max<std::size_t>(sr.pairs, 1));
        sr.gap_max_mm = std::max(sr.gap_max_mm, g);
        gap_max = std::max(gap_max, g);
    }
    const Welding w =
        weld_pairs(out.draped.size(), placement_only ? std::vector<Stitch>{} : plan.pairs);
    GarmentMesh& g = out.garment;
    g = internal::welded_garment(cloth, out.draped, w, tri_piece);
    for (const auto& p : pattern.pieces) {
        g.piece_names.push_back(p.name);
    }
    rep.garment_vertices = w.count;
    rep.openings = garment_openings(g.positions, g.triangles);
    std::sort(rep.openings.begin(), rep.openings.end(),
              [](const Opening& a, const Opening& b) { return a.height_mm < b.height_mm; });
    for (Opening& op : rep.openings) {
        op.clearance_max_mm = -std::numeric_limits<double>::infinity();
        for (std::uint32_t v : op.loop) {
            const double d = sdf.signed_distance(g.positions[v], nullptr);
            op.clearance_mean_mm += d / double(op.loop.size());
            op.clearance_max_mm = std::max(op.clearance_max_mm, d);
        }
    }
    rep.boundary_loops = rep.openings.size();
    // --- quality
    t0 = Clock::now();
    // The cloth rests at the clearance from the skin: a triangle within twice that lies on it.
    rep.quality = garment_quality(body.points(), body.triangles(), g, last.moving_fraction, gap_max,
                                  2 * rep.body_clearance_mm);
    rep.quality.top_drop_mm = top_drop_mm(out.placed, out.draped);
    out.stretch = triangle_stretch(g.positions, g.triangles, g.uv);
    rep.gates = quality_gates(rep.quality);
    rep.passed =
        std::all_of(rep.gates.begin(), rep.gates.end(), [](const Gate& x) { return x.passed; });
    rep.quality_seconds = internal::seconds_since(t0);
    rep.threads = o.drape.threads;
    rep.total_seconds = internal::seconds_since(t_start);
    return out;
}

}  // namespace tapeline::garment
