// Import of GarmentCode pattern specifications (Korosteleva & Sorkine-Hornung, "GarmentCode:
// Programming Parametric Sewing Patterns", ACM TOG 42(6), 2023; the JSON of pygarment 2.x).
//
// A panel is a loop of edges over its `vertices` (units: 1 m / `units_in_meter`, i.e. cm; y up).
// Curvature control points are relative to the edge (properties.curvature_coords = "relative"):
// for an edge from s to e, the control point (u, v) is s + u·(e − s) + v·perp(e − s), perp being
// e − s turned a quarter turn counter-clockwise. Read from the data: under this convention every
// panel outline of the shared files is simple, stitched edges have equal lengths (the sign of v
// cannot change a length), and necklines bend into the bodice (the opposite sign bends them out).
// `quadratic` has one control point (elevated to an exact cubic), `cubic` two, `circle` is
// [radius, large_arc, right]: an arc bulging to the right of s→e, i.e. counter-clockwise.
// Each panel's 3D placement (translation, Euler XYZ rotation in degrees) is kept; each stitch
// [{panel, edge}, {panel, edge}] becomes a seam whose direction is read from that placement
// (`same` when the two edges' chords point the same way in 3D).
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/pattern/internal/json_helpers.h>
#include <tapeline/pattern/pattern.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace tapeline::pattern {

/// R·(x, y, 0) + t for a placement (rotation order "XYZ": intrinsic, R = Rx·Ry·Rz).
inline std::array<double, 3> placed_point(const Placement3D& pl, const Point2& p) {
    const double d2r = M_PI / 180.0;
    const double a = pl.rotation_deg[0] * d2r, b = pl.rotation_deg[1] * d2r,
                 c = pl.rotation_deg[2] * d2r;
    // Rz·p, then Ry, then Rx.
    std::array<double, 3> v = {p.x * std::cos(c) - p.y * std::sin(c),
                               p.x * std::sin(c) + p.y * std::cos(c), 0.0};
    v = {v[0] * std::cos(b) + v[2] * std::sin(b), v[1], -v[0] * std::sin(b) + v[2] * std::cos(b)};
    v = {v[0], v[1] * std::cos(a) - v[2] * std::sin(a), v[1] * std::sin(a) + v[2] * std::cos(a)};
    return {v[0] + pl.translation[0], v[1] + pl.translation[1], v[2] + pl.translation[2]};
}

namespace internal {

inline std::string gc_garment_type(const std::string& name) {
    const std::string first = name.substr(0, name.find('_'));
    if (first == "js") {
        return "jumpsuit";
    }
    return first;
}

inline Point2 gc_relative(const Point2& s, const Point2& e, const Point2& uv) {
    const Point2 d = e - s;
    return s + uv.x * d + uv.y * left_normal(d);
}

}  // namespace internal

/// Builds a pattern from a parsed GarmentCode specification; `name` becomes the pattern name and
/// `source` names it in messages.
///
/// \param doc the parsed specification, a JSON object.
/// \param source the specification's name in messages (a file name, say).
/// \param name the pattern's name.
/// \param report when not null, receives the counts and notes of the import.
/// \throws InvalidInput naming the source and the JSON path: a member of the wrong type, an
///         unknown unit or curvature type, a bad edge, placement or stitch, a stitch or panel
///         order naming a panel or edge that does not exist.
inline Pattern garmentcode_from_json(const nlohmann::json& doc, const std::string& source,
                                     const std::string& name = "garmentcode",
                                     ImportReport* report = nullptr) {
    using namespace internal;
    ImportReport local;
    ImportReport& rep = report ? *report : local;
    const Where top{source, ""};
    require_object(doc, top);

    double units_in_meter = 100;
    if (const Json* props = optional_field(doc, "properties")) {
        const Where wp = top.key("properties");
        if (const Json* u = optional_field(*props, "units_in_meter")) {
            units_in_meter = number(*u, wp.key("units_in_meter"));
            if (units_in_meter <= 0) {
                throw InvalidInput(wp.key("units_in_meter").str() + ": unknown unit (" + u->dump() +
                                   " units per metre)");
            }
        }
        if (const Json* cc = optional_field(*props, "curvature_coords")) {
            const std::string c = string(*cc, wp.key("curvature_coords"));
            if (c != "relative") {
                throw InvalidInput(wp.key("curvature_coords").str() + ": '" + c +
                                   "' is not supported (only relative control points)");
            }
        }
    }
    const double scale = 1000.0 / units_in_meter;  // → mm

    const Json& jpat = field(doc, "pattern", top);
    const Where wpat = top.key("pattern");
    const Json& panels = field(jpat, "panels", wpat);
    const Where wpanels = wpat.key("panels");
    require_object(panels, wpanels);
    std::vector<std::string> order;
    if (const Json* po = optional_field(jpat, "panel_order")) {
        require_array(*po, wpat.key("panel_order"));
        for (std::size_t i = 0; i < po->size(); ++i) {
            order.push_back(string((*po)[i], wpat.key("panel_order").index(i)));
        }
    }
    for (const auto& [k, v] : panels.items()) {
        if (std::find(order.begin(), order.end(), k) == order.end()) {
            order.push_back(k);
        }
    }

    Pattern pat;
    pat.source = source;
    pat.name = name;
    pat.designer = "GarmentCode";
    pat.garment_type = gc_garment_type(name);
    pat.tags = {"garmentcode"};
    for (const std::string& pname : order) {
        const auto it = panels.find(pname);
        if (it == panels.end()) {
            throw InvalidInput(wpat.key("panel_order").str() + ": names panel '" + pname +
                               "', which 'panels' does not have");
        }
        const Json& jp = *it;
        const Where w{source, "panel '" + pname + "'"};
        Piece piece;
        piece.name = pname;
        if (const Json* l = optional_field(jp, "label")) {
            piece.label = string(*l, w.key("label"));
        }
        const Json& verts = field(jp, "vertices", w);
        require_array(verts, w.key("vertices"));
        std::vector<Point2> v;
        for (std::size_t i = 0; i < verts.size(); ++i) {
            v.push_back(scale * point(verts[i], w.key("vertices").index(i)));
        }
        const Json& edges = field(jp, "edges", w);
        require_array(edges, w.key("edges"));
        for (std::size_t i = 0; i < edges.size(); ++i) {
            const Where we = w.key("edges").index(i);
            const Json& je = edges[i];
            const Json& ends = field(je, "endpoints", we);
            if (!ends.is_array() || ends.size() != 2) {
                throw InvalidInput(we.key("endpoints").str() + ": expected [start, end], got " +
                                   ends.dump());
            }
            const std::size_t i0 = index_value(ends[0], we.key("endpoints").index(0));
            const std::size_t i1 = index_value(ends[1], we.key("endpoints").index(1));
            if (i0 >= v.size() || i1 >= v.size()) {
                throw InvalidInput(we.key("endpoints").str() + ": vertex " +
                                   std::to_string(std::max(i0, i1)) + " does not exist (" +
                                   std::to_string(v.size()) + " vertices)");
            }
            const Point2 s = v[i0], e = v[i1];
            Edge edge{Line{s, e}, ""};
            if (const Json* l = optional_field(je, "label")) {
                edge.label = string(*l, we.key("label"));
            }
            if (const Json* cv = optional_field(je, "curvature")) {
                const Where wc = we.key("curvature");
                const std::string type = string(field(*cv, "type", wc), wc.key("type"));
                const Json& params = field(*cv, "params", wc);
                const Where wpar = wc.key("params");
                require_array(params, wpar);
                auto need = [&](std::size_t n) {
                    if (params.size() != n) {
                        throw InvalidInput(wpar.str() + ": a " + type + " edge has " +
                                           std::to_string(n) + " parameters, got " +
                                           std::to_string(params.size()));
                    }
                };
                if (type == "quadratic") {
                    need(1);
                    const Point2 c = gc_relative(s, e, point(params[0], wpar.index(0)));
                    edge.curve = cubic_from_quadratic(s, c, e);
                } else if (type == "cubic") {
                    need(2);
                    edge.curve = CubicBezier{s, gc_relative(s, e, point(params[0], wpar.index(0))),
                                             gc_relative(s, e, point(params[1], wpar.index(1))), e};
                } else if (type == "circle") {
                    need(3);
                    Arc arc{s, e, scale * number(params[0], wpar.index(0)),
                            number(params[1], wpar.index(1)) != 0,
                            number(params[2], wpar.index(2)) != 0};
                    edge.curve = arc;
                } else {
                    throw InvalidInput(wc.key("type").str() + ": unknown curvature type '" + type +
                                       "' (expected quadratic, cubic or circle)");
                }
            }
            piece.outline.edges.push_back(std::move(edge));
        }
        Placement3D pl;
        if (const Json* t = optional_field(jp, "translation")) {
            require_array(*t, w.key("translation"));
            if (t->size() != 3) {
                throw InvalidInput(w.key("translation").str() + ": expected [x, y, z]");
            }
            for (std::size_t k = 0; k < 3; ++k) {
                pl.translation[k] = scale * number((*t)[k], w.key("translation").index(k));
            }
        }
        if (const Json* r = optional_field(jp, "rotation")) {
            require_array(*r, w.key("rotation"));
            if (r->size() != 3) {
                throw InvalidInput(w.key("rotation").str() + ": expected 3 Euler angles");
            }
            for (std::size_t k = 0; k < 3; ++k) {
                pl.rotation_deg[k] = number((*r)[k], w.key("rotation").index(k));
            }
        }
        piece.placement = pl;
        ++rep.pieces;
        pat.pieces.push_back(std::move(piece));
    }

    const Json& stitches = field(jpat, "stitches", wpat);
    const Where wst = wpat.key("stitches");
    require_array(stitches, wst);
    for (std::size_t si = 0; si < stitches.size(); ++si) {
        const Where w = wst.index(si);
        const Json& st = stitches[si];
        if (!st.is_array() || st.size() != 2) {
            throw InvalidInput(w.str() + ": expected [{panel, edge}, {panel, edge}], got " +
                               st.dump());
        }
        std::array<EdgeRange, 2> side;
        std::array<const Piece*, 2> piece{};
        for (std::size_t k = 0; k < 2; ++k) {
            const Where ws = w.index(k);
            side[k].piece = string(field(st[k], "panel", ws), ws.key("panel"));
            side[k].first_edge = index_value(field(st[k], "edge", ws), ws.key("edge"));
            piece[k] = find_piece(pat, side[k].piece);
            if (!piece[k]) {
                throw InvalidInput(ws.str() + ": stitch names panel '" + side[k].piece +
                                   "', which the pattern does not have");
            }
            if (side[k].first_edge >= piece[k]->outline.edges.size()) {
                throw InvalidInput(ws.str() + ": stitch names edge " +
                                   std::to_string(side[k].first_edge) + " of panel '" +
                                   side[k].piece + "', which has " +
                                   std::to_string(piece[k]->outline.edges.size()) + " edges");
            }
        }
        Seam seam;
        seam.name = "stitch " + std::to_string(si);
        seam.a = side[0];
        seam.b = side[1];
        const Edge& ea = piece[0]->outline.edges[side[0].first_edge];
        const Edge& eb = piece[1]->outline.edges[side[1].first_edge];
        const auto a0 = placed_point(*piece[0]->placement, start_point(ea));
        const auto a1 = placed_point(*piece[0]->placement, end_point(ea));
        const auto b0 = placed_point(*piece[1]->placement, start_point(eb));
        const auto b1 = placed_point(*piece[1]->placement, end_point(eb));
        // Panels sit apart in 3D (a hood above the bodice), so compare the edges' directions,
        // which do not depend on that offset, rather than the distances between end points.
        const double d = (a1[0] - a0[0]) * (b1[0] - b0[0]) + (a1[1] - a0[1]) * (b1[1] - b0[1]) +
                         (a1[2] - a0[2]) * (b1[2] - b0[2]);
        seam.direction = d >= 0 ? SeamDirection::same : SeamDirection::opposite;
        pat.seams.push_back(std::move(seam));
        ++rep.seams;
    }
    return pat;
}

/// Reads `<name>_specification.json`; the pattern is named after the file (without the suffix).
///
/// \throws InvalidInput naming the file when it cannot be read or is not JSON.
/// \throws InvalidInput also as garmentcode_from_json.
inline Pattern read_garmentcode(const std::string& path, ImportReport* report = nullptr) {
    std::string stem = path.substr(path.find_last_of('/') + 1);
    for (const std::string suffix : {".json", "_specification"}) {
        if (stem.size() > suffix.size() &&
            stem.compare(stem.size() - suffix.size(), suffix.size(), suffix) == 0) {
            stem.erase(stem.size() - suffix.size());
        }
    }
    return garmentcode_from_json(internal::parse_json_file(path), path, stem, report);
}

}  // namespace tapeline::pattern
