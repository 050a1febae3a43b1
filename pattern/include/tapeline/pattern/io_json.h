// The pattern model as JSON ("format": "tapeline-pattern", "format_version": 1).
//
// Every field of the model is written; numbers are written by nlohmann::json's shortest
// round-trip formatting, so write → read gives back bit-identical doubles. Lengths are in the
// file's "units" (mm, cm, m or in; this writer always writes mm); the reader converts to mm.
// Measurements are always mm ("measurements_used_mm"), angles in degrees.
//
//   edge:  {"type": "line",  "a": [x, y], "b": [x, y]}
//          {"type": "cubic", "p": [[x, y], [x, y], [x, y], [x, y]]}
//          {"type": "arc",   "a": [x, y], "b": [x, y], "radius": r, "large_arc": b, "ccw": b}
//          + optional "label"
#pragma once

#include <tapeline/core/atomic_write.h>
#include <tapeline/core/errors.h>
#include <tapeline/core/units.h>
#include <tapeline/pattern/internal/json_helpers.h>
#include <tapeline/pattern/pattern.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <ostream>
#include <string>

namespace tapeline::pattern {

inline constexpr int pattern_json_format_version = 1;

namespace internal {

inline Json bindings_json(const std::vector<MeasurementBinding>& bindings) {
    Json out = Json::array();
    for (const MeasurementBinding& b : bindings) {
        Json jb{{"measurement", b.measurement}, {"ease", b.ease_mm}, {"features", Json::array()}};
        for (const BoundFeature& f : b.features) {
            jb["features"].push_back({{"piece", f.piece},
                                      {"edges", f.edges},
                                      {"from_point", f.from_point},
                                      {"to_point", f.to_point},
                                      {"count", f.count}});
        }
        out.push_back(std::move(jb));
    }
    return out;
}

inline Json point_json(const Point2& p) {
    return Json::array({p.x, p.y});
}

inline Json edge_json(const Edge& e) {
    Json j;
    if (const auto* l = std::get_if<Line>(&e.curve)) {
        j = {{"type", "line"}, {"a", point_json(l->a)}, {"b", point_json(l->b)}};
    } else if (const auto* c = std::get_if<CubicBezier>(&e.curve)) {
        j = {{"type", "cubic"},
             {"p", Json::array({point_json(c->p0), point_json(c->p1), point_json(c->p2),
                                point_json(c->p3)})}};
    } else {
        const Arc& a = std::get<Arc>(e.curve);
        j = {{"type", "arc"},      {"a", point_json(a.a)},     {"b", point_json(a.b)},
             {"radius", a.radius}, {"large_arc", a.large_arc}, {"ccw", a.ccw}};
    }
    if (!e.label.empty()) {
        j["label"] = e.label;
    }
    return j;
}

inline Json edges_json(const std::vector<Edge>& edges) {
    Json j = Json::array();
    for (const Edge& e : edges) {
        j.push_back(edge_json(e));
    }
    return j;
}

inline Json range_json(const EdgeRange& r) {
    return {{"piece", r.piece}, {"first_edge", r.first_edge}, {"count", r.count}};
}

/// Reads coordinates scaled by `s` (the file's unit in mm).
struct ModelReader {
    double s = 1;

    Point2 pt(const Json& j, const Where& w) const { return s * point(j, w); }

    Edge edge(const Json& j, const Where& w) const {
        const std::string type = string(field(j, "type", w), w.key("type"));
        Edge e;
        if (const Json* l = optional_field(j, "label")) {
            e.label = string(*l, w.key("label"));
        }
        if (type == "line") {
            e.curve = Line{pt(field(j, "a", w), w.key("a")), pt(field(j, "b", w), w.key("b"))};
        } else if (type == "cubic") {
            const Json& p = field(j, "p", w);
            if (!p.is_array() || p.size() != 4) {
                throw InvalidInput(w.key("p").str() + ": a cubic has 4 points");
            }
            e.curve = CubicBezier{pt(p[0], w.key("p").index(0)), pt(p[1], w.key("p").index(1)),
                                  pt(p[2], w.key("p").index(2)), pt(p[3], w.key("p").index(3))};
        } else if (type == "arc") {
            e.curve = Arc{pt(field(j, "a", w), w.key("a")), pt(field(j, "b", w), w.key("b")),
                          s * number(field(j, "radius", w), w.key("radius")),
                          boolean(field(j, "large_arc", w), w.key("large_arc")),
                          boolean(field(j, "ccw", w), w.key("ccw"))};
        } else {
            throw InvalidInput(w.key("type").str() + ": unknown edge type '" + type +
                               "' (expected line, cubic or arc)");
        }
        return e;
    }

    std::vector<Edge> edges(const Json& j, const Where& w) const {
        require_array(j, w);
        std::vector<Edge> out;
        for (std::size_t i = 0; i < j.size(); ++i) {
            out.push_back(edge(j[i], w.index(i)));
        }
        return out;
    }
};

inline EdgeRange range_from(const Json& j, const Where& w) {
    return {string(field(j, "piece", w), w.key("piece")),
            index_value(field(j, "first_edge", w), w.key("first_edge")),
            index_value(field(j, "count", w), w.key("count"))};
}

inline std::string opt_string(const Json& j, const char* key, const Where& w) {
    const Json* f = optional_field(j, key);
    return f ? string(*f, w.key(key)) : std::string();
}

/// Millimetres per unit (tapeline/core/units.h), or 0 for a unit we do not know.
inline double unit_scale(const std::string& u) {
    const auto unit = length_unit(u);
    return unit ? millimetres_per(*unit) : 0;
}

/// Checks that document `j` is an object whose "format" is `format`.
inline void require_format(const Json& j, const Where& top, const std::string& format) {
    require_object(j, top);
    const std::string f = string(field(j, "format", top), top.key("format"));
    if (f != format) {
        throw InvalidInput(top.key("format").str() + ": '" + f + "' is not a " + format +
                           " document");
    }
}

/// The factor from the document's "units" to mm.
inline double document_scale(const Json& j, const Where& top) {
    const std::string units = string(field(j, "units", top), top.key("units"));
    const double s = unit_scale(units);
    if (s == 0) {
        throw InvalidInput(top.key("units").str() + ": unknown unit '" + units +
                           "' (expected mm, cm, dm, m or in)");
    }
    return s;
}

/// The bindings of a "bindings" array `j` (lengths scaled by `s` to mm), `w` naming it.
inline std::vector<MeasurementBinding> bindings_from(const Json& j, double s, const Where& w) {
    require_array(j, w);
    std::vector<MeasurementBinding> out;
    for (std::size_t i = 0; i < j.size(); ++i) {
        const Where wb = w.index(i);
        const Json& jb = j[i];
        MeasurementBinding b;
        b.measurement = string(field(jb, "measurement", wb), wb.key("measurement"));
        b.ease_mm = s * number(field(jb, "ease", wb), wb.key("ease"));
        const Json& fs = field(jb, "features", wb);
        require_array(fs, wb.key("features"));
        for (std::size_t k = 0; k < fs.size(); ++k) {
            const Where wf = wb.key("features").index(k);
            BoundFeature f;
            f.piece = string(field(fs[k], "piece", wf), wf.key("piece"));
            if (const Json* es = optional_field(fs[k], "edges")) {
                require_array(*es, wf.key("edges"));
                for (std::size_t e = 0; e < es->size(); ++e) {
                    f.edges.push_back(index_value((*es)[e], wf.key("edges").index(e)));
                }
            }
            f.from_point = opt_string(fs[k], "from_point", wf);
            f.to_point = opt_string(fs[k], "to_point", wf);
            if (const Json* c = optional_field(fs[k], "count")) {
                f.count = number(*c, wf.key("count"));
            }
            b.features.push_back(std::move(f));
        }
        out.push_back(std::move(b));
    }
    return out;
}

}  // namespace internal

/// The pattern as a JSON document.
inline nlohmann::json to_json(const Pattern& p) {
    using namespace internal;
    Json j;
    j["format"] = "tapeline-pattern";
    j["format_version"] = pattern_json_format_version;
    j["units"] = "mm";  // the model always holds mm (validation rejects other units)
    j["name"] = p.name;
    j["designer"] = p.designer;
    j["garment_type"] = p.garment_type;
    j["size"] = p.size;
    j["tags"] = p.tags;
    j["source"] = p.source;
    Json meas = Json::object();
    for (const auto& [k, v] : p.measurements_used) {
        meas[k] = v;
    }
    j["measurements_used_mm"] = meas;
    j["pieces"] = Json::array();
    for (const Piece& piece : p.pieces) {
        Json jp;
        jp["name"] = piece.name;
        jp["label"] = piece.label;
        jp["outline"] = edges_json(piece.outline.edges);
        Json pts = Json::object();
        for (const auto& [k, v] : piece.points) {
            pts[k] = point_json(v);
        }
        jp["points"] = pts;
        if (piece.grain) {
            jp["grain"] = {{"from", point_json(piece.grain->from)},
                           {"to", point_json(piece.grain->to)}};
        }
        jp["notches"] = Json::array();
        for (const Notch& n : piece.notches) {
            jp["notches"].push_back(
                {{"edge", n.edge}, {"offset", n.offset}, {"name", n.name}, {"kind", n.kind}});
        }
        jp["internal_lines"] = Json::array();
        for (const InternalLine& l : piece.internal_lines) {
            jp["internal_lines"].push_back(
                {{"name", l.name}, {"kind", l.kind}, {"edges", edges_json(l.edges)}});
        }
        jp["darts"] = Json::array();
        for (const Dart& d : piece.darts) {
            jp["darts"].push_back({{"name", d.name}, {"edges", edges_json(d.edges)}});
        }
        if (piece.fold) {
            jp["fold"] = {{"a", point_json(piece.fold->line.a)},
                          {"b", point_json(piece.fold->line.b)}};
            if (piece.fold->edge) {
                jp["fold"]["edge"] = *piece.fold->edge;
            }
        }
        jp["cut_count"] = piece.cut_count;
        jp["mirrored"] = piece.mirrored;
        if (piece.placement) {
            jp["placement"] = {{"translation", piece.placement->translation},
                               {"rotation_deg", piece.placement->rotation_deg},
                               {"rotation_order", piece.placement->rotation_order}};
        }
        j["pieces"].push_back(std::move(jp));
    }
    j["seams"] = Json::array();
    for (const Seam& s : p.seams) {
        j["seams"].push_back(
            {{"name", s.name},
             {"a", range_json(s.a)},
             {"b", range_json(s.b)},
             {"direction", s.direction == SeamDirection::same ? "same" : "opposite"}});
    }
    j["bindings"] = internal::bindings_json(p.bindings);
    return j;
}

/// Reads a pattern from its JSON document; `source` names it in messages.
///
/// \throws InvalidInput naming the source and the JSON path: another format, a newer format
///         version, an unknown unit, edge type, rotation order or direction, a member of the
///         wrong type or count.
inline Pattern from_json(const nlohmann::json& j, const std::string& source) {
    using namespace internal;
    const Where top{source, ""};
    require_format(j, top, "tapeline-pattern");
    const Json& ver = field(j, "format_version", top);
    if (!ver.is_number_integer() || ver.get<long long>() < 1 ||
        ver.get<long long>() > pattern_json_format_version) {
        throw InvalidInput(top.key("format_version").str() + ": version " + ver.dump() +
                           " is not supported (this reader knows 1.." +
                           std::to_string(pattern_json_format_version) + ")");
    }
    const double s = document_scale(j, top);
    const ModelReader rd{s};
    Pattern p;
    p.units = "mm";
    p.name = opt_string(j, "name", top);
    p.designer = opt_string(j, "designer", top);
    p.garment_type = opt_string(j, "garment_type", top);
    p.size = opt_string(j, "size", top);
    p.source = opt_string(j, "source", top);
    if (const Json* tags = optional_field(j, "tags")) {
        require_array(*tags, top.key("tags"));
        for (std::size_t i = 0; i < tags->size(); ++i) {
            p.tags.push_back(string((*tags)[i], top.key("tags").index(i)));
        }
    }
    if (const Json* m = optional_field(j, "measurements_used_mm")) {
        require_object(*m, top.key("measurements_used_mm"));
        for (const auto& [k, v] : m->items()) {
            p.measurements_used[k] = number(v, top.key("measurements_used_mm").key(k));
        }
    }
    const Json& pieces = field(j, "pieces", top);
    require_array(pieces, top.key("pieces"));
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        const Json& jp = pieces[i];
        Piece piece;
        piece.name = string(field(jp, "name", top.key("pieces").index(i)),
                            top.key("pieces").index(i).key("name"));
        const Where w{source, "piece '" + piece.name + "'"};
        piece.label = opt_string(jp, "label", w);
        piece.outline.edges = rd.edges(field(jp, "outline", w), w.key("outline"));
        if (const Json* pts = optional_field(jp, "points")) {
            require_object(*pts, w.key("points"));
            for (const auto& [k, v] : pts->items()) {
                piece.points[k] = rd.pt(v, w.key("points." + k));
            }
        }
        if (const Json* g = optional_field(jp, "grain")) {
            piece.grain = GrainLine{rd.pt(field(*g, "from", w.key("grain")), w.key("grain.from")),
                                    rd.pt(field(*g, "to", w.key("grain")), w.key("grain.to"))};
        }
        if (const Json* ns = optional_field(jp, "notches")) {
            require_array(*ns, w.key("notches"));
            for (std::size_t k = 0; k < ns->size(); ++k) {
                const Where wn = w.key("notches").index(k);
                const Json& jn = (*ns)[k];
                piece.notches.push_back({index_value(field(jn, "edge", wn), wn.key("edge")),
                                         s * number(field(jn, "offset", wn), wn.key("offset")),
                                         opt_string(jn, "name", wn), opt_string(jn, "kind", wn)});
            }
        }
        if (const Json* ls = optional_field(jp, "internal_lines")) {
            require_array(*ls, w.key("internal_lines"));
            for (std::size_t k = 0; k < ls->size(); ++k) {
                const Where wl = w.key("internal_lines").index(k);
                const Json& jl = (*ls)[k];
                piece.internal_lines.push_back({opt_string(jl, "name", wl),
                                                opt_string(jl, "kind", wl),
                                                rd.edges(field(jl, "edges", wl), wl.key("edges"))});
            }
        }
        if (const Json* ds = optional_field(jp, "darts")) {
            require_array(*ds, w.key("darts"));
            for (std::size_t k = 0; k < ds->size(); ++k) {
                const Where wd = w.key("darts").index(k);
                const Json& jd = (*ds)[k];
                piece.darts.push_back({opt_string(jd, "name", wd),
                                       rd.edges(field(jd, "edges", wd), wd.key("edges"))});
            }
        }
        if (const Json* f = optional_field(jp, "fold")) {
            const Where wf = w.key("fold");
            Fold fold{Line{rd.pt(field(*f, "a", wf), wf.key("a")),
                           rd.pt(field(*f, "b", wf), wf.key("b"))},
                      std::nullopt};
            if (const Json* e = optional_field(*f, "edge")) {
                fold.edge = index_value(*e, wf.key("edge"));
            }
            piece.fold = fold;
        }
        if (const Json* c = optional_field(jp, "cut_count")) {
            if (!c->is_number_integer()) {
                throw InvalidInput(w.key("cut_count").str() + ": expected an integer, got " +
                                   c->dump());
            }
            piece.cut_count = c->get<int>();
        }
        if (const Json* m = optional_field(jp, "mirrored")) {
            piece.mirrored = boolean(*m, w.key("mirrored"));
        }
        if (const Json* pl = optional_field(jp, "placement")) {
            const Where wpl = w.key("placement");
            Placement3D placement;
            const Json& t = field(*pl, "translation", wpl);
            const Json& r = field(*pl, "rotation_deg", wpl);
            if (!t.is_array() || t.size() != 3 || !r.is_array() || r.size() != 3) {
                throw InvalidInput(wpl.str() + ": translation and rotation_deg have 3 numbers");
            }
            for (std::size_t k = 0; k < 3; ++k) {
                placement.translation[k] = s * number(t[k], wpl.key("translation").index(k));
                placement.rotation_deg[k] = number(r[k], wpl.key("rotation_deg").index(k));
            }
            placement.rotation_order = opt_string(*pl, "rotation_order", wpl);
            if (placement.rotation_order != "XYZ") {
                throw InvalidInput(wpl.key("rotation_order").str() + ": '" +
                                   placement.rotation_order + "' is not supported (XYZ)");
            }
            piece.placement = placement;
        }
        p.pieces.push_back(std::move(piece));
    }
    if (const Json* seams = optional_field(j, "seams")) {
        require_array(*seams, top.key("seams"));
        for (std::size_t i = 0; i < seams->size(); ++i) {
            const Where w = top.key("seams").index(i);
            const Json& js = (*seams)[i];
            Seam seam;
            seam.name = opt_string(js, "name", w);
            seam.a = range_from(field(js, "a", w), w.key("a"));
            seam.b = range_from(field(js, "b", w), w.key("b"));
            const std::string dir = string(field(js, "direction", w), w.key("direction"));
            if (dir != "same" && dir != "opposite") {
                throw InvalidInput(w.key("direction").str() + ": '" + dir +
                                   "' (expected same or opposite)");
            }
            seam.direction = dir == "same" ? SeamDirection::same : SeamDirection::opposite;
            p.seams.push_back(std::move(seam));
        }
    }
    if (const Json* bs = optional_field(j, "bindings")) {
        p.bindings = bindings_from(*bs, s, top.key("bindings"));
    }
    return p;
}

/// Writes the pattern as JSON text (indent < 0: one line).
inline void write_pattern_json(const Pattern& p, std::ostream& out, int indent = 1) {
    out << to_json(p).dump(indent) << '\n';
}

/// Writes the pattern to `path` atomically (a temporary file renamed into place).
///
/// \throws InvalidInput naming `path` when it cannot be written; `path` is left untouched.
inline void write_pattern_json(const Pattern& p, const std::string& path, int indent = 1) {
    write_file_atomically(path, [&](std::ostream& out) { write_pattern_json(p, out, indent); });
}

/// Reads a pattern JSON file (see from_json).
///
/// \throws InvalidInput naming the file when it cannot be read or is not JSON.
/// \throws InvalidInput also as from_json.
inline Pattern read_pattern_json(const std::string& path) {
    return from_json(internal::parse_json_file(path), path);
}

/// A bindings file ("format": "tapeline-bindings", mm): the pattern's name, its measurement
/// bindings (as in the pattern JSON) and, per piece, the named points those bindings use, so that
/// bindings found on a body can be read, edited and given back (apply_bindings_file).
inline nlohmann::json bindings_file_json(const Pattern& p) {
    using internal::Json;
    Json points = Json::object();
    for (const MeasurementBinding& b : p.bindings) {
        for (const BoundFeature& f : b.features) {
            const Piece* piece = find_piece(p, f.piece);
            for (const std::string* name : {&f.from_point, &f.to_point}) {
                if (piece && !name->empty() && piece->points.count(*name)) {
                    points[f.piece][*name] = internal::point_json(piece->points.at(*name));
                }
            }
        }
    }
    return Json{{"format", "tapeline-bindings"},
                {"pattern", p.name},
                {"units", "mm"},
                {"points", points},
                {"bindings", internal::bindings_json(p.bindings)}};
}

/// Gives `p` the bindings of a bindings file `j` read from `source`: its points are added to
/// their pieces (replacing points of the same name), and its bindings of a measurement replace
/// all of the pattern's bindings of that measurement or are added. Returns the measurements it
/// binds.
///
/// \throws InvalidInput naming `source` and the key: not a tapeline-bindings document, an
///         unknown unit, a point on a piece the pattern lacks, a malformed binding; or a
///         binding that names a piece the pattern lacks.
inline std::vector<std::string> apply_bindings_file(Pattern& p, const nlohmann::json& j,
                                                    const std::string& source) {
    using namespace internal;
    const Where top{source, ""};
    require_format(j, top, "tapeline-bindings");
    const double s = document_scale(j, top);
    const ModelReader rd{s};
    std::vector<std::pair<Piece*, std::pair<std::string, Point2>>> points;
    if (const Json* pts = optional_field(j, "points")) {
        require_object(*pts, top.key("points"));
        for (const auto& [piece_name, named] : pts->items()) {
            Piece* piece = find_piece(p, piece_name);
            if (!piece) {
                throw InvalidInput(top.key("points." + piece_name).str() + ": pattern '" + p.name +
                                   "' has no piece '" + piece_name + "'");
            }
            require_object(named, top.key("points." + piece_name));
            for (const auto& [k, v] : named.items()) {
                points.push_back({piece, {k, rd.pt(v, top.key("points." + piece_name + "." + k))}});
            }
        }
    }
    const std::vector<MeasurementBinding> bindings =
        bindings_from(field(j, "bindings", top), s, top.key("bindings"));
    for (const MeasurementBinding& b : bindings) {
        for (const BoundFeature& f : b.features) {
            if (!find_piece(p, f.piece)) {
                throw InvalidInput(top.key("bindings").str() + ": binding '" + b.measurement +
                                   "' names piece '" + f.piece + "', which pattern '" + p.name +
                                   "' lacks");
            }
        }
    }
    for (auto& [piece, named] : points) {
        piece->points[named.first] = named.second;
    }
    // A measurement may be bound several times (a length, once per piece): the file's bindings
    // of a measurement replace all of the pattern's, where its first one stood.
    std::vector<std::string> names;
    for (const MeasurementBinding& b : bindings) {
        if (std::find(names.begin(), names.end(), b.measurement) == names.end()) {
            names.push_back(b.measurement);
        }
    }
    std::vector<MeasurementBinding> merged;
    std::vector<std::string> placed;
    const auto place = [&](const std::string& name) {
        placed.push_back(name);
        for (const MeasurementBinding& b : bindings) {
            if (b.measurement == name) {
                merged.push_back(b);
            }
        }
    };
    for (MeasurementBinding& x : p.bindings) {
        if (std::find(names.begin(), names.end(), x.measurement) == names.end()) {
            merged.push_back(std::move(x));
        } else if (std::find(placed.begin(), placed.end(), x.measurement) == placed.end()) {
            place(x.measurement);
        }
    }
    for (const std::string& name : names) {
        if (std::find(placed.begin(), placed.end(), name) == placed.end()) {
            place(name);
        }
    }
    p.bindings = std::move(merged);
    return names;
}

/// apply_bindings_file with the bindings file at `path`.
inline std::vector<std::string> apply_bindings_file(Pattern& p, const std::string& path) {
    return apply_bindings_file(p, internal::parse_json_file(path), path);
}

}  // namespace tapeline::pattern
