// Files of a dressed body: the garment as Wavefront OBJ (seams welded, one group per piece,
// per-corner UVs = pattern coordinates in mm) and as PLY with per-vertex stretch, and the report
// as JSON. Positions are written through a caller-given map so that the garment lands in the
// body's own coordinates and unit and loads together with the body in any viewer.
#pragma once

#include <tapeline/core/atomic_write.h>
#include <tapeline/core/errors.h>
#include <tapeline/garment/garment_types.h>
#include <tapeline/garment/quality.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace tapeline::garment {

/// Maps a garment position (canonical mm) to the coordinates written.
using PositionMap = std::function<Vec3(const Vec3&)>;

/// OBJ: `v` per welded vertex, `vt` per triangle corner (pattern mm), `g` per piece followed by
/// the comment `# grain gx gy` (the piece's unit warp direction in its pattern coordinates; every
/// OBJ reader skips it, read_garment_obj() reads it), `f v/vt`.
inline void write_garment_obj(std::ostream& out, const GarmentMesh& g, const PositionMap& map) {
    char buf[160];
    out << "# Tapeline draped garment: v in the body's coordinates, vt = pattern coordinates "
           "(mm)\n";
    for (const Vec3& p : g.positions) {
        const Vec3 q = map(p);
        std::snprintf(buf, sizeof buf, "v %.9g %.9g %.9g\n", q[0], q[1], q[2]);
        out << buf;
    }
    for (const auto& corners : g.uv) {
        for (const UV& t : corners) {
            std::snprintf(buf, sizeof buf, "vt %.9g %.9g\n", t[0], t[1]);
            out << buf;
        }
    }
    std::uint32_t current = std::uint32_t(-1);
    for (std::size_t f = 0; f < g.triangles.size(); ++f) {
        if (g.triangle_piece[f] != current) {
            current = g.triangle_piece[f];
            std::string name = current < g.piece_names.size() ? g.piece_names[current] : "piece";
            for (char& c : name) {
                c = (c == ' ' || c == '\t' || c == '\n' || c == '\r') ? '_' : c;
            }
            out << "g " << name << '\n';
            if (f < g.grain.size()) {
                std::snprintf(buf, sizeof buf, "# grain %.9g %.9g\n", g.grain[f][0], g.grain[f][1]);
                out << buf;
            }
        }
        const Tri& t = g.triangles[f];
        out << "f";
        for (int k = 0; k < 3; ++k) {
            out << ' ' << t[k] + 1 << '/' << 3 * f + k + 1;
        }
        out << '\n';
    }
}

/// Reads a garment OBJ as write_garment_obj() writes it: `v` positions (returned as read, in the
/// file's unit), `vt` pattern coordinates (mm), `g` pieces with their `# grain gx gy` comment
/// (absent: +y), triangles `f v/vt v/vt v/vt` (1-based or negative, relative indices; normals
/// after a second slash are ignored). Other lines (`vn`, `o`, `s`, `usemtl`, comments) are
/// skipped. Throws InvalidInput naming the file and line: a face that is not a triangle or has
/// no `vt`, an index out of range, a number that does not parse or is not finite, a grain of
/// zero length, no faces at all.
inline GarmentMesh read_garment_obj(const std::string& path) {
    std::ifstream in(path);
    if (!in) {
        throw InvalidInput(path + ": cannot open the garment OBJ");
    }
    GarmentMesh g;
    std::vector<UV> vt;
    UV grain{0, 1};
    bool grouped = false;
    std::string line;
    std::size_t line_no = 0;
    auto fail = [&](const std::string& what) {
        throw InvalidInput(path + ":" + std::to_string(line_no) + ": " + what);
    };
    auto number = [&](std::istringstream& ls, const char* what) {
        std::string tok;
        if (!(ls >> tok)) {
            fail(std::string("missing ") + what);
        }
        char* end = nullptr;
        const double v = std::strtod(tok.c_str(), &end);
        if (end == tok.c_str() || *end != '\0' || !std::isfinite(v)) {
            fail(std::string(what) + " '" + tok + "' is not a finite number");
        }
        return v;
    };
    auto index = [&](const std::string& tok, std::size_t count, const char* what) {
        char* end = nullptr;
        const long k = std::strtol(tok.c_str(), &end, 10);
        if (end == tok.c_str() || *end != '\0' || k == 0) {
            fail(std::string("bad ") + what + " index '" + tok + "'");
        }
        const long i = k > 0 ? k - 1 : long(count) + k;
        if (i < 0 || std::size_t(i) >= count) {
            fail(std::string(what) + " index " + tok + " out of range (" + std::to_string(count) +
                 " so far)");
        }
        return std::uint32_t(i);
    };
    while (std::getline(in, line)) {
        ++line_no;
        std::istringstream ls(line);
        std::string key;
        if (!(ls >> key)) {
            continue;
        }
        if (key == "v") {
            const double x = number(ls, "x"), y = number(ls, "y"), z = number(ls, "z");
            g.positions.push_back({x, y, z});
        } else if (key == "vt") {
            const double u = number(ls, "u"), v = number(ls, "v");
            vt.push_back({u, v});
        } else if (key == "g") {
            std::string name;
            std::getline(ls >> std::ws, name);
            g.piece_names.push_back(name.empty() ? "piece" : name);
            grain = {0, 1};
            grouped = true;
        } else if (key == "#") {
            std::string what;
            if (ls >> what && what == "grain") {
                const double gx = number(ls, "grain x"), gy = number(ls, "grain y");
                const double gl = std::hypot(gx, gy);
                if (!(gl > 1e-12)) {
                    fail("grain direction of zero length");
                }
                grain = {gx / gl, gy / gl};
            }
        } else if (key == "f") {
            std::vector<std::string> corners;
            for (std::string c; ls >> c;) {
                corners.push_back(c);
            }
            if (corners.size() != 3) {
                fail("face with " + std::to_string(corners.size()) +
                     " corners (a garment OBJ holds triangles)");
            }
            Tri t{};
            std::array<UV, 3> uv{};
            for (int k = 0; k < 3; ++k) {
                const std::string& c = corners[std::size_t(k)];
                const std::size_t slash = c.find('/');
                if (slash == std::string::npos || slash + 1 >= c.size() || c[slash + 1] == '/') {
                    fail("face corner '" + c +
                         "' has no pattern coordinate (vt): not a garment "
                         "OBJ with pattern coordinates");
                }
                const std::size_t slash2 = c.find('/', slash + 1);
                t[std::size_t(k)] = index(c.substr(0, slash), g.positions.size(), "vertex");
                uv[std::size_t(k)] =
                    vt[index(c.substr(slash + 1, slash2 == std::string::npos ? std::string::npos
                                                                             : slash2 - slash - 1),
                             vt.size(), "vt")];
            }
            if (!grouped) {
                g.piece_names.push_back("piece");
                grouped = true;
            }
            g.triangles.push_back(t);
            g.uv.push_back(uv);
            g.grain.push_back(grain);
            g.triangle_piece.push_back(std::uint32_t(g.piece_names.size() - 1));
        }
    }
    if (g.triangles.empty()) {
        line_no = 0;
        throw InvalidInput(path + ": no triangles (not a garment OBJ)");
    }
    return g;
}

/// ASCII PLY: x y z (body coordinates) and `stretch` per vertex (the largest principal stretch of
/// its triangles); faces with their `piece` index.
inline void write_garment_ply(std::ostream& out, const GarmentMesh& g,
                              const std::vector<double>& triangle_stretch, const PositionMap& map) {
    std::vector<double> vs(g.positions.size(), 0.0);
    for (std::size_t f = 0; f < g.triangles.size(); ++f) {
        for (std::uint32_t v : g.triangles[f]) {
            vs[v] = std::max(vs[v], triangle_stretch[f]);
        }
    }
    out << "ply\nformat ascii 1.0\ncomment Tapeline draped garment; stretch = largest principal "
           "stretch of the vertex's triangles against the pattern\n";
    for (std::size_t i = 0; i < g.piece_names.size(); ++i) {
        out << "comment piece " << i << ' ' << g.piece_names[i] << '\n';
    }
    out << "element vertex " << g.positions.size()
        << "\nproperty double x\nproperty double y\nproperty double z\nproperty double stretch\n"
           "element face "
        << g.triangles.size() << "\nproperty list uchar int vertex_indices\nproperty int piece\n"
        << "end_header\n";
    char buf[160];
    for (std::size_t v = 0; v < g.positions.size(); ++v) {
        const Vec3 q = map(g.positions[v]);
        std::snprintf(buf, sizeof buf, "%.9g %.9g %.9g %.6g\n", q[0], q[1], q[2], vs[v]);
        out << buf;
    }
    for (std::size_t f = 0; f < g.triangles.size(); ++f) {
        const Tri& t = g.triangles[f];
        out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << ' ' << g.triangle_piece[f] << '\n';
    }
}

/// The report as JSON (mm, seconds).
inline nlohmann::ordered_json dress_report_json(const DressReport& r, const FabricParams& fabric,
                                                const DressOptions& o) {
    nlohmann::ordered_json j;
    j["passed"] = r.passed;
    nlohmann::ordered_json gates = nlohmann::ordered_json::array();
    for (const Gate& g : r.gates) {
        gates.push_back(
            {{"name", g.name}, {"value", g.value}, {"limit", g.limit}, {"passed", g.passed}});
    }
    j["gates"] = gates;
    const QualityFigures& q = r.quality;
    j["quality"] = {{"stitch_gap_max_mm", q.stitch_gap_max_mm},
                    {"vertices_inside_body", q.vertices_inside_body},
                    {"max_depth_mm", q.max_depth_mm},
                    {"edges_crossing_body", q.edges_crossing_body},
                    {"self_intersections", q.self_intersections},
                    {"stretch_median", q.stretch_median},
                    {"stretch_p95", q.stretch_p95},
                    {"stretch_max", q.stretch_max},
                    {"stretch_above_105_percent", q.stretch_above_105_percent},
                    {"stretch_p95_on_body", q.stretch_p95_on_body},
                    {"stretch_p95_off_body", q.stretch_p95_off_body},
                    {"triangles_on_body_percent", q.triangles_on_body_percent},
                    {"moving_fraction", q.moving_fraction},
                    {"top_drop_mm", q.top_drop_mm}};
    // Where the first crossings are, in the body's canonical frame (mm; x to the body's left, y
    // up from the floor, z to the front).
    nlohmann::ordered_json crossings = nlohmann::ordered_json::array();
    for (const Vec3& p : q.body_crossing_points) {
        crossings.push_back({std::lround(p[0]), std::lround(p[1]), std::lround(p[2])});
    }
    j["quality"]["body_crossings_canonical_mm"] = crossings;
    nlohmann::ordered_json self_crossings = nlohmann::ordered_json::array();
    for (const Vec3& p : q.self_crossing_points) {
        self_crossings.push_back({std::lround(p[0]), std::lround(p[1]), std::lround(p[2])});
    }
    j["quality"]["self_crossings_canonical_mm"] = self_crossings;
    nlohmann::ordered_json by_pieces = nlohmann::ordered_json::object();
    for (const auto& [pieces, n] : q.self_crossings_by_pieces) {
        by_pieces[pieces] = n;
    }
    j["quality"]["self_crossings_by_pieces"] = by_pieces;
    nlohmann::ordered_json seams = nlohmann::ordered_json::array();
    for (const SeamReport& s : r.seams) {
        seams.push_back({{"name", s.name},
                         {"pairs", s.pairs},
                         {"side_a_mm", s.side_a_mm},
                         {"side_b_mm", s.side_b_mm},
                         {"string_mm", s.string_mm},
                         {"gap_mean_mm", s.gap_mean_mm},
                         {"gap_max_mm", s.gap_max_mm},
                         {"closable", s.closable},
                         {"problem", s.problem}});
    }
    j["seams"] = seams;
    nlohmann::ordered_json pieces = nlohmann::ordered_json::array();
    for (const PieceReport& p : r.pieces) {
        pieces.push_back({{"name", p.name},
                          {"region", p.region},
                          {"vertices", p.vertices},
                          {"triangles", p.triangles},
                          {"placed_inside", p.placed_inside}});
    }
    j["pieces"] = pieces;
    j["placement"] = {{"vertices_inside_body", r.placement_vertices_inside},
                      {"piece_crossings", r.placement_piece_intersections}};
    j["mesh"] = {{"cloth_vertices", r.cloth_vertices},
                 {"cloth_triangles", r.cloth_triangles},
                 {"garment_vertices", r.garment_vertices},
                 {"boundary_loops", r.boundary_loops},
                 {"pairs_welded_before_drape", r.pairs_welded_before_drape},
                 {"waistband_vertices", r.waistband_vertices}};
    nlohmann::ordered_json openings = nlohmann::ordered_json::array();
    for (const Opening& op : r.openings) {
        nlohmann::ordered_json loop = nlohmann::ordered_json::array();
        for (const Vec3& p : op.points) {
            loop.push_back({std::round(p[0] * 10) / 10, std::round(p[1] * 10) / 10,
                            std::round(p[2] * 10) / 10});
        }
        openings.push_back({{"vertices", op.loop.size()},
                            {"height_mm", op.height_mm},
                            {"length_mm", op.length_mm},
                            {"width_mm", op.width_mm},
                            {"depth_mm", op.depth_mm},
                            {"normal", {op.normal[0], op.normal[1], op.normal[2]}},
                            {"hull_perimeter_mm", op.hull_perimeter_mm},
                            {"folds", op.folds},
                            {"deepest_fold_mm", op.deepest_fold_mm},
                            {"clearance_mean_mm", op.clearance_mean_mm},
                            {"clearance_max_mm", op.clearance_max_mm},
                            {"loop_canonical_mm", loop}});
    }
    j["openings"] = openings;
    nlohmann::ordered_json folds = nlohmann::ordered_json::array();
    for (const FoldReport& f : r.folds) {
        folds.push_back({{"crossings_before", f.crossings_before},
                         {"crossings_after", f.crossings_after},
                         {"rounds", f.rounds},
                         {"vertices_moved", f.vertices_moved},
                         {"max_move_mm", f.max_move_mm},
                         {"seconds", f.seconds}});
    }
    nlohmann::ordered_json each = nlohmann::ordered_json::array();
    for (const RelaxReport& s : r.relax_solves) {
        each.push_back({{"iterations", s.iterations},
                        {"stop", s.stop},
                        {"last_max_move_mm", s.last_max_move_mm},
                        {"moving_fraction", s.moving_fraction},
                        {"seconds", s.seconds}});
    }
    j["simulation"] = {{"frames", r.frames},
                       {"simulated_seconds", r.simulated_seconds},
                       {"ms_per_step_per_10k_vertices", r.ms_per_step_per_10k},
                       {"threads", r.threads},
                       {"body_clearance_mm", r.body_clearance_mm},
                       {"static_solve",
                        {{"ran", r.relax.iterations > 0},
                         {"iterations", r.relax.iterations},
                         {"converged", r.relax.converged},
                         {"stop", r.relax.stop},
                         {"last_max_move_mm", r.relax.last_max_move_mm},
                         {"energy_before_j", r.relax.energy_before_j},
                         {"energy_after_j", r.relax.energy_after_j},
                         {"max_residual_of_weight", r.relax.max_residual_of_weight},
                         {"total_residual_of_weight", r.relax.total_residual_of_weight},
                         {"contacts", r.relax.contacts},
                         {"body_point_contacts", r.relax.body_point_contacts},
                         {"seconds", r.relax.seconds}}},
                       {"static_solves", r.relax_runs},
                       {"static_solve_each", each},
                       {"fold_smoothing", folds}};
    j["timings_seconds"] = {{"measure", r.measure_seconds},     {"sdf", r.sdf_seconds},
                            {"placement", r.placement_seconds}, {"strings", r.strings_seconds},
                            {"drape", r.drape_seconds},         {"quality", r.quality_seconds},
                            {"total", r.total_seconds}};
    j["options"] = {
        {"resolution_mm", o.resolution_mm},
        {"gap_mm", o.placement.gap_mm},
        {"sew_seconds", o.sewing.sew_seconds},
        {"settle_seconds", o.sewing.settle_seconds},
        {"frame_seconds", o.drape.frame_seconds},
        {"substeps", o.drape.substeps},
        {"iterations", o.drape.iterations},
        {"self_collision", o.drape.self_collision},
        {"edge_edge_collision", o.drape.edge_edge_collision},
        {"untangle", o.drape.untangle},
        {"static_solve", o.relax},
        {"static_solve_iterations", o.relax_options.max_iterations},
        {"static_solve_settle", o.relax_options.settle_iterations},
        {"static_solve_friction_from", o.relax_options.friction_from_iteration},
        {"static_solve_releases", o.relax_options.release_until_iteration},
        {"static_solve_again_friction_from", o.relax_again_options.friction_from_iteration},
        {"static_solve_again_releases", o.relax_again_options.release_until_iteration},
        {"body_points", o.body_points},
        {"fold_smoothing", o.smooth_folds},
        {"fold_cycles", o.fold_cycles},
        {"waistband", o.waistband},
        {"waistband_sag_mm", o.waistband_sag_mm},
        {"sdf_cell_mm", o.sdf_cell_mm},
        {"without", o.without_pieces},
        {"damping_per_second", o.drape.damping_per_second},
        {"max_extra_seconds", o.sewing.max_extra_seconds},
        {"settle_damping_per_second", o.sewing.settle_damping_per_second},
        {"weld_within_mm", o.sewing.weld_within_mm}};
    j["fabric"] = {{"name", fabric.name},
                   {"density_g_m2", fabric.density_g_m2},
                   {"stretch_warp_n_m", fabric.stretch_warp_n_m},
                   {"stretch_weft_n_m", fabric.stretch_weft_n_m},
                   {"shear_n_m", fabric.shear_n_m},
                   {"bending_un_m", fabric.bending_un_m},
                   {"friction", fabric.friction},
                   {"thickness_mm", fabric.thickness_mm}};
    return j;
}

}  // namespace tapeline::garment
