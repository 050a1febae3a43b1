// Import of FreeSewing drafts exported as JSON (../shared/data/patterns/freesewing): per piece the
// `seam` path as move/line/curve/close operations in mm with y down, named points, and macro paths
// (cut-on-fold bracket, grain line). Coordinates are flipped to y up.
//
// What becomes what:
//   seam path            → outline (a missing closing segment is added as a line; noted)
//   points               → named points (names starting with "_" are FreeSewing internals: skipped)
//   __macro_cutonfold_*  → fold (the bracket's end points; the outline line lying on it is marked)
//   __macro_grainline_*  → grain line
//   *notch* points       → notches where the point lies within 0.5 mm of the outline
//   path named *dart*    → dart; other visible, non-macro paths → internal lines (kind = class)
//   measurements         → measurements_used; help paths named after a measurement (chest,
//                          waist, ...) whose ends are named points → measurement bindings, the
//                          ease being what the draft realises (count 2 on pieces cut on the fold)
// Pieces without a seam path (FreeSewing's `has_seam_path: false`, e.g. Simon's plackets, which
// are drawn on other pieces) are skipped and noted.
//   (no seams in the file) → the seams of the design (freesewing_designs.h) that hold one edge
//                          range per side; a seam rule whose points this draft lacks is noted
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/pattern/freesewing_designs.h>
#include <tapeline/pattern/internal/json_helpers.h>
#include <tapeline/pattern/pattern.h>

#include <cctype>
#include <map>
#include <string>
#include <vector>

namespace tapeline::pattern {

namespace internal {

/// FreeSewing's y-down coordinates → the model's y-up.
inline Point2 fs_point(const Json& j, const Where& w) {
    Point2 p = point(j, w);
    p.y = -p.y;
    return p;
}

/// The subpaths of a FreeSewing path's ops as edge lists; `closed[k]` when subpath k ended with
/// a close op.
struct FsSubpaths {
    std::vector<std::vector<Edge>> edges;
    std::vector<Point2> starts;
    std::vector<bool> closed;
};

inline FsSubpaths fs_ops(const Json& ops, const Where& w) {
    require_array(ops, w);
    FsSubpaths out;
    Point2 cur, start;
    bool have = false;
    for (std::size_t i = 0; i < ops.size(); ++i) {
        const Where wi = w.index(i);
        const Json& op = ops[i];
        const std::string type = string(field(op, "type", wi), wi.key("type"));
        if (type == "move") {
            cur = start = fs_point(field(op, "to", wi), wi.key("to"));
            out.edges.emplace_back();
            out.starts.push_back(start);
            out.closed.push_back(false);
            have = true;
            continue;
        }
        if (!have) {
            throw InvalidInput(wi.str() + ": '" + type + "' before any 'move'");
        }
        if (type == "line") {
            const Point2 to = fs_point(field(op, "to", wi), wi.key("to"));
            if (to != cur) {
                out.edges.back().push_back({Line{cur, to}, ""});
            }
            cur = to;
        } else if (type == "curve") {
            const Point2 c1 = fs_point(field(op, "cp1", wi), wi.key("cp1"));
            const Point2 c2 = fs_point(field(op, "cp2", wi), wi.key("cp2"));
            const Point2 to = fs_point(field(op, "to", wi), wi.key("to"));
            if (!(to == cur && c1 == cur && c2 == cur)) {
                out.edges.back().push_back({CubicBezier{cur, c1, c2, to}, ""});
            }
            cur = to;
        } else if (type == "close") {
            if (cur != start) {
                out.edges.back().push_back({Line{cur, start}, ""});
            }
            cur = start;
            out.closed.back() = true;
        } else {
            throw InvalidInput(wi.str() + ": unknown path operation '" + type +
                               "' (expected move, line, curve or close)");
        }
    }
    return out;
}

inline std::string lower(std::string s) {
    for (char& c : s) {
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return s;
}

inline bool starts_with(const std::string& s, const std::string& prefix) {
    return s.compare(0, prefix.size(), prefix) == 0;
}

inline std::string fs_garment_type(const std::string& design) {
    static const std::map<std::string, std::string> types = {
        {"aaron", "tank top"},  {"brian", "body block"}, {"simon", "shirt"},
        {"teagan", "t-shirt"},  {"titan", "trousers"},   {"bella", "bodice block"},
        {"bent", "body block"}, {"charlie", "trousers"}, {"sandy", "skirt"}};
    const auto it = types.find(design);
    return it == types.end() ? std::string() : it->second;
}

/// Index of the outline line edge lying on the segment [a, b]'s supporting line and overlapping
/// it, within `tol` mm.
inline std::optional<std::size_t> edge_on_line(const Outline& o, Point2 a, Point2 b, double tol) {
    const Point2 d = b - a;
    const double len = norm(d);
    if (len == 0) {
        return std::nullopt;
    }
    const Point2 u = (1.0 / len) * d;
    for (std::size_t i = 0; i < o.edges.size(); ++i) {
        const auto* l = std::get_if<Line>(&o.edges[i].curve);
        if (!l) {
            continue;
        }
        const double da = std::abs(cross(u, l->a - a)), db = std::abs(cross(u, l->b - a));
        const double ta = dot(u, l->a - a), tb = dot(u, l->b - a);
        if (da <= tol && db <= tol && std::max(ta, tb) > 0 && std::min(ta, tb) < len) {
            return i;
        }
    }
    return std::nullopt;
}

}  // namespace internal

/// Builds a pattern from a parsed FreeSewing export; `source` names it in messages.
///
/// \param doc the parsed export, a JSON object.
/// \param source the export's name in messages (a file name, say).
/// \param report when not null, receives the counts and notes of the import.
/// \throws InvalidInput naming the source and the JSON path: a member of the wrong type, an
///         unknown unit or path operation, an operation before any move, a seam path without
///         edges or with several subpaths.
inline Pattern freesewing_from_json(const nlohmann::json& doc, const std::string& source,
                                    ImportReport* report = nullptr) {
    using namespace internal;
    ImportReport local;
    ImportReport& rep = report ? *report : local;
    const Where top{source, ""};
    require_object(doc, top);

    // The unit note reads "mm; x right, y DOWN ..."; anything else is a unit we do not know.
    if (const Json* units = optional_field(doc, "units")) {
        const std::string u = string(*units, top.key("units"));
        if (!starts_with(lower(u), "mm")) {
            throw InvalidInput(top.key("units").str() + ": unknown unit '" + u +
                               "' (FreeSewing exports are in mm)");
        }
    }
    Pattern pat;
    pat.source = source;
    const std::string design =
        optional_field(doc, "design") ? string(doc["design"], top.key("design")) : "";
    const std::string size = optional_field(doc, "measurement_set")
                                 ? string(doc["measurement_set"], top.key("measurement_set"))
                                 : "";
    pat.name = design.empty() ? "freesewing" : design + (size.empty() ? "" : "_" + size);
    pat.designer = "FreeSewing";
    pat.garment_type = fs_garment_type(design);
    pat.size = size;
    pat.tags = {"freesewing"};
    if (!design.empty()) {
        pat.tags.push_back(design);
    }
    if (const Json* m = optional_field(doc, "measurements")) {
        const Where wm = top.key("measurements");
        require_object(*m, wm);
        for (const auto& [k, v] : m->items()) {
            pat.measurements_used[k] = number(v, wm.key(k));
        }
    }

    const Json& pieces = field(doc, "pieces", top);
    const Where wp = top.key("pieces");
    require_array(pieces, wp);
    std::map<std::string, std::vector<BoundFeature>> features;  // measurement → features
    for (std::size_t pi = 0; pi < pieces.size(); ++pi) {
        const Where w = wp.index(pi);
        const Json& jp = pieces[pi];
        Piece piece;
        piece.name = string(field(jp, "name", w), w.key("name"));
        const Where wpiece{source, "piece '" + piece.name + "'"};
        const Json& paths = field(jp, "paths", w);
        require_object(paths, w.key("paths"));
        const Json* seam = optional_field(paths, "seam");
        if (!seam) {
            ++rep.skipped_pieces;
            rep.notes.push_back("piece '" + piece.name + "': no seam path, skipped");
            continue;
        }
        const Where ws = wpiece.key("paths.seam");
        FsSubpaths sub = fs_ops(field(*seam, "ops", ws), ws.key("ops"));
        if (sub.edges.size() != 1) {
            throw InvalidInput(ws.str() + ": seam path has " + std::to_string(sub.edges.size()) +
                               " subpaths; an outline is one closed path");
        }
        std::vector<Edge>& edges = sub.edges.front();
        if (edges.empty()) {
            throw InvalidInput(ws.str() + ": seam path has no edges");
        }
        if (!sub.closed.front() && end_point(edges.back()) != sub.starts.front()) {
            edges.push_back({Line{end_point(edges.back()), sub.starts.front()}, ""});
            rep.notes.push_back("piece '" + piece.name +
                                "': seam path not closed; closed with a straight line");
        }
        piece.outline.edges = std::move(edges);

        if (const Json* pts = optional_field(jp, "points")) {
            require_object(*pts, w.key("points"));
            for (const auto& [k, v] : pts->items()) {
                if (!starts_with(k, "_")) {
                    piece.points[k] = fs_point(v, wpiece.key("points." + k));
                }
            }
        }
        for (const auto& [pname, jpath] : paths.items()) {
            if (pname == "seam") {
                continue;
            }
            const Where wpath = wpiece.key("paths." + pname);
            const std::string cls =
                optional_field(jpath, "class") ? string(jpath["class"], wpath.key("class")) : "";
            const bool hidden =
                optional_field(jpath, "hidden") && boolean(jpath["hidden"], wpath.key("hidden"));
            if (starts_with(pname, "__macro_cutonfold")) {
                const FsSubpaths f = fs_ops(field(jpath, "ops", wpath), wpath.key("ops"));
                if (!f.edges.empty() && !f.edges.front().empty()) {
                    const Point2 a = start_point(f.edges.front().front());
                    const Point2 b = end_point(f.edges.front().back());
                    piece.fold = Fold{Line{a, b}, edge_on_line(piece.outline, a, b, 0.01)};
                    piece.cut_count = 1;
                }
                continue;
            }
            if (starts_with(pname, "__macro_grainline")) {
                const FsSubpaths g = fs_ops(field(jpath, "ops", wpath), wpath.key("ops"));
                if (!g.edges.empty() && !g.edges.front().empty()) {
                    piece.grain = GrainLine{start_point(g.edges.front().front()),
                                            end_point(g.edges.front().back())};
                }
                continue;
            }
            if (starts_with(pname, "__") || hidden || cls == "hidden" ||
                cls.find("scalebox") != std::string::npos) {
                continue;
            }
            const FsSubpaths s = fs_ops(field(jpath, "ops", wpath), wpath.key("ops"));
            std::vector<Edge> all;
            for (const auto& part : s.edges) {
                all.insert(all.end(), part.begin(), part.end());
            }
            if (all.empty()) {
                continue;
            }
            if (lower(pname).find("dart") != std::string::npos) {
                piece.darts.push_back({pname, std::move(all)});
                continue;
            }
            // A help line named after a measurement ("chest", "waist") is where the draft
            // realises that measurement: bind it when its ends are named points.
            if (cls.find("help") != std::string::npos && pat.measurements_used.count(pname) &&
                s.edges.size() == 1) {
                const Point2 a = start_point(all.front()), b = end_point(all.back());
                std::string from, to;
                for (const auto& [k, p] : piece.points) {
                    if (from.empty() && distance(p, a) <= 0.01) {
                        from = k;
                    }
                    if (to.empty() && distance(p, b) <= 0.01) {
                        to = k;
                    }
                }
                if (!from.empty() && !to.empty()) {
                    features[pname].push_back({piece.name, {}, from, to, 1});
                }
            }
            piece.internal_lines.push_back({pname, cls, std::move(all)});
        }
        for (auto& [m, fs] : features) {
            for (BoundFeature& f : fs) {
                if (f.piece == piece.name && piece.fold) {
                    f.count = 2;
                }
            }
        }
        for (const auto& [k, p] : piece.points) {
            if (lower(k).find("notch") == std::string::npos) {
                continue;
            }
            if (const auto pos = project(piece.outline, p, 0.01); pos && pos->distance <= 0.5) {
                piece.notches.push_back({pos->edge, pos->offset, k, "slit"});
            }
        }
        ++rep.pieces;
        pat.pieces.push_back(std::move(piece));
    }
    for (auto& [m, fs] : features) {
        MeasurementBinding b;
        b.measurement = m;
        b.features = fs;
        double total = 0;
        for (const BoundFeature& f : fs) {
            const Piece* piece = find_piece(pat, f.piece);
            total +=
                f.count * distance(piece->points.at(f.from_point), piece->points.at(f.to_point));
        }
        b.ease_mm = total - pat.measurements_used.at(m);
        pat.bindings.push_back(std::move(b));
    }
    std::vector<std::string> skipped;
    rep.seams += add_freesewing_seams(pat, &skipped);
    for (const std::string& rule : skipped) {
        rep.notes.push_back("seam '" + rule + "' not derived: a chain end is not an outline " +
                            "vertex of this draft");
    }
    skipped.clear();
    apply_label_rules(pat, freesewing_label_rules(), &skipped);
    for (const std::string& rule : skipped) {
        rep.notes.push_back("edge label '" + rule + "' not given: a chain end is not an outline " +
                            "vertex of this draft");
    }
    return pat;
}

/// Reads a FreeSewing JSON export (see the file comment for the mapping).
///
/// \throws InvalidInput naming the file when it cannot be read or is not JSON.
/// \throws InvalidInput also as freesewing_from_json.
inline Pattern read_freesewing(const std::string& path, ImportReport* report = nullptr) {
    return freesewing_from_json(internal::parse_json_file(path), path, report);
}

}  // namespace tapeline::pattern
