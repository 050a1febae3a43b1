// The grading problem built from a pattern: nodes (every distinct control point, named point and
// line end lying on or inside a piece), the terms of grading/README.md, the smoothness graph, and
// the map from a displacement back to a pattern.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/grading/grading_types.h>
#include <tapeline/grading/internal/terms.h>
#include <tapeline/pattern/pattern.h>
#include <tapeline/sizes/catalogue.h>
#include <tapeline/sizes/measurement_set.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace tapeline::grading::internal {

namespace tp = tapeline::pattern;

/// Displacement of every node and its 2×2 gradient (row-major), the local affine model that
/// carries points that are not nodes (d(q) = d_n + A_n (q − p_n), n the nearest node).
struct Solution {
    std::vector<tp::Point2> d;
    std::vector<std::array<double, 4>> A;
};

struct EdgeNodes {
    std::size_t kind = 0;  // 0 line, 1 cubic, 2 arc
    std::array<std::size_t, 4> n{0, 0, 0, 0};
};

struct PieceModel {
    std::size_t first = 0, count = 0;
    tp::Point2 centroid;
    double radius = 1;
    std::vector<EdgeNodes> outline;
    bool trim = false;      // a long narrow strip (GradingOptions::trim_aspect)
    tp::Point2 axis{1, 0};  // its long axis
};

struct BindingInfo {
    std::string measurement, where;
    double target = 0, ease = 0;
};

struct Model {
    std::vector<tp::Point2> base;
    std::vector<std::size_t> piece_of;
    std::vector<PieceModel> pieces;
    std::vector<std::pair<std::size_t, std::size_t>> graph;
    std::vector<LengthTerm> fit, seams;
    std::vector<LengthTerm> shares;  // girth split between pieces (GradingOptions::split_girths)
    std::vector<double> seam_ratio;
    std::vector<BindingInfo> bindings;
    std::vector<std::string> seam_names;
    std::vector<TurnTerm> turns;
    std::vector<GrainTerm> grains;
    std::vector<CurveTerm> curves;
    std::vector<ProportionTerm> proportions;
    double node_tolerance = 1e-4;
};

/// Named points up to this far outside a piece are nodes (FreeSewing's cbHps sits just above the
/// back neckline); farther ones belong to other parts of the draft.
constexpr double near_piece_mm = 25;

inline double piece_distance_inside(const tp::Outline& o, const tp::Point2& q) {
    // ≤ 0 inside or on the outline (within the polyline's tolerance), else the distance outside.
    const std::vector<tp::Point2> ring = tp::sample(o, 0.05).points;
    int winding = 0;
    double best = 1e300;
    for (std::size_t k = 0; k + 1 < ring.size(); ++k) {
        const tp::Point2 a = ring[k], b = ring[k + 1];
        best = std::min(best, tp::internal::distance_to_segment(q, a, b));
        if ((a.y <= q.y) != (b.y <= q.y)) {
            const double x = a.x + (q.y - a.y) / (b.y - a.y) * (b.x - a.x);
            if (x > q.x) {
                winding += 1;
            }
        }
    }
    return (winding % 2 == 1) ? 0.0 : best;
}

class ModelBuilder {
public:
    ModelBuilder(const tp::Pattern& p, Model& m) : p_(p), m_(m) {}

    /// Node of piece `pi` at q (an existing one within the tolerance, else a new one).
    std::size_t node(std::size_t pi, const tp::Point2& q) {
        const PieceModel& pm = m_.pieces[pi];
        for (std::size_t k = pm.first; k < m_.base.size(); ++k) {
            if (tp::distance(m_.base[k], q) <= m_.node_tolerance) {
                return k;
            }
        }
        m_.base.push_back(q);
        m_.piece_of.push_back(pi);
        ++m_.pieces[pi].count;
        return m_.base.size() - 1;
    }

    void build_nodes() {
        for (std::size_t pi = 0; pi < p_.pieces.size(); ++pi) {
            const tp::Piece& piece = p_.pieces[pi];
            PieceModel pm;
            pm.first = m_.base.size();
            m_.pieces.push_back(pm);
            for (const tp::Edge& e : piece.outline.edges) {
                EdgeNodes en;
                if (const auto* l = std::get_if<tp::Line>(&e.curve)) {
                    en.kind = 0;
                    en.n[0] = node(pi, l->a);
                    en.n[1] = node(pi, l->b);
                } else if (const auto* c = std::get_if<tp::CubicBezier>(&e.curve)) {
                    en.kind = 1;
                    en.n = {node(pi, c->p0), node(pi, c->p1), node(pi, c->p2), node(pi, c->p3)};
                } else {
                    const auto& a = std::get<tp::Arc>(e.curve);
                    en.kind = 2;
                    en.n[0] = node(pi, a.a);
                    en.n[1] = node(pi, a.b);
                }
                m_.pieces[pi].outline.push_back(en);
            }
            // Other points become nodes only on or inside the piece: FreeSewing carries the
            // points of the whole draft into every part (a yoke knows the waist).
            auto maybe = [&](const tp::Point2& q) {
                if (piece_distance_inside(piece.outline, q) <= near_piece_mm) {
                    node(pi, q);
                }
            };
            for (const auto& [name, q] : piece.points) {
                maybe(q);
            }
            if (piece.grain) {
                maybe(piece.grain->from);
                maybe(piece.grain->to);
            }
            PieceModel& out = m_.pieces[pi];
            tp::Point2 c{0, 0};
            for (std::size_t k = out.first; k < out.first + out.count; ++k) {
                c = c + m_.base[k];
            }
            out.centroid = (1.0 / std::max<std::size_t>(1, out.count)) * c;
            double r = 1;
            for (std::size_t k = out.first; k < out.first + out.count; ++k) {
                r = std::max(r, tp::distance(m_.base[k], out.centroid));
            }
            out.radius = r;
        }
    }

    /// Marks straight strips: the principal axes of the outline (sampled every 1 mm, so that
    /// control points do not weigh) have extents whose ratio is at least `aspect`, and the piece
    /// fills at least 80 % of that box.
    void mark_trims(double aspect) {
        if (aspect <= 0) {
            return;
        }
        for (std::size_t pi = 0; pi < p_.pieces.size(); ++pi) {
            const std::vector<tp::Point2> ring = tp::sample(p_.pieces[pi].outline, 1.0).points;
            if (ring.size() < 3) {
                continue;
            }
            tp::Point2 c{0, 0};
            for (const tp::Point2& q : ring) {
                c = c + q;
            }
            c = (1.0 / ring.size()) * c;
            double sxx = 0, sxy = 0, syy = 0;
            for (const tp::Point2& q : ring) {
                sxx += (q.x - c.x) * (q.x - c.x);
                sxy += (q.x - c.x) * (q.y - c.y);
                syy += (q.y - c.y) * (q.y - c.y);
            }
            const double th = 0.5 * std::atan2(2 * sxy, sxx - syy);
            const tp::Point2 u{std::cos(th), std::sin(th)}, v{-u.y, u.x};
            double lo_u = 1e300, hi_u = -1e300, lo_v = 1e300, hi_v = -1e300;
            for (const tp::Point2& q : ring) {
                lo_u = std::min(lo_u, tp::dot(q, u));
                hi_u = std::max(hi_u, tp::dot(q, u));
                lo_v = std::min(lo_v, tp::dot(q, v));
                hi_v = std::max(hi_v, tp::dot(q, v));
            }
            // Straight strips only: a curved band (a collar) fills little of its box, and its
            // "across" direction turns along it.
            double area = 0;
            for (std::size_t k = 0; k + 1 < ring.size(); ++k) {
                area += 0.5 * tp::cross(ring[k] - c, ring[k + 1] - c);
            }
            const double box = (hi_u - lo_u) * (hi_v - lo_v);
            if (hi_u - lo_u >= aspect * std::max(1e-9, hi_v - lo_v) &&
                std::abs(area) >= 0.8 * box) {
                m_.pieces[pi].trim = true;
                m_.pieces[pi].axis = u;
            }
        }
    }

    /// Node of a named point of piece `pi` that lies on or inside it, or npos.
    std::size_t named_node(std::size_t pi, const std::string& name) const {
        const auto it = p_.pieces[pi].points.find(name);
        if (it == p_.pieces[pi].points.end()) {
            return npos;
        }
        const PieceModel& pm = m_.pieces[pi];
        for (std::size_t k = pm.first; k < pm.first + pm.count; ++k) {
            if (tp::distance(m_.base[k], it->second) <= m_.node_tolerance) {
                return k;
            }
        }
        return npos;
    }

    void add_edge_items(std::size_t pi, std::size_t edge, double coef, LengthTerm& t) {
        const EdgeNodes& en = m_.pieces[pi].outline.at(edge);
        LengthItem item;
        item.coef = coef;
        if (en.kind == 0) {
            item.kind = LengthItem::span;
            item.slot = {slot(t, en.n[0]), slot(t, en.n[1]), 0, 0};
        } else if (en.kind == 1) {
            item.kind = LengthItem::cubic;
            item.slot = {slot(t, en.n[0]), slot(t, en.n[1]), slot(t, en.n[2]), slot(t, en.n[3])};
        } else {
            item.kind = LengthItem::arc;
            item.slot = {slot(t, en.n[0]), slot(t, en.n[1]), 0, 0};
            const tp::Edge& e = p_.pieces[pi].outline.edges[edge];
            const auto& a = std::get<tp::Arc>(e.curve);
            item.arc_ratio = tp::length(e) / std::max(1e-9, tp::distance(a.a, a.b));
        }
        t.items.push_back(item);
    }

    // A target further than max_target_ratio from the base value either way is no grade of
    // this draft (a unit mistake, garbage): refused before Ceres sees it.
    void check_target_ratio(const std::string& name, const std::optional<double>& base,
                            double target, double limit, const sizes::MeasurementSet& from,
                            const sizes::MeasurementSet& to) const {
        if (!std::isfinite(target) || (!sizes::is_angle_measurement(name) && target <= 0)) {
            throw InvalidInput("target set '" + to.name + "': measurement '" + name + "' is " +
                               ratio_text(target) + "; a bound length must be a positive number");
        }
        if (!base || *base <= 0 || sizes::is_angle_measurement(name) || !(limit > 0)) {
            return;
        }
        const double r = target / *base;
        if (!(r <= limit && r >= 1 / limit)) {
            throw InvalidInput("target set '" + to.name + "': measurement '" + name + "' is " +
                               ratio_text(target) + " mm, " + ratio_text(r) +
                               " times the base set '" + from.name + "''s " + ratio_text(*base) +
                               " mm; a grade beyond " + ratio_text(limit) +
                               " times either way is refused (max_target_ratio)");
        }
    }

    static std::string ratio_text(double v) {
        std::ostringstream s;
        s.precision(4);
        s << v;
        return s.str();
    }

    void build_bindings(const sizes::MeasurementSet& from, const sizes::MeasurementSet& to,
                        EaseMode ease, double weight, bool split_girths, double max_target_ratio) {
        for (const tp::MeasurementBinding& b : p_.bindings) {
            LengthTerm t;
            t.weight = weight;
            std::string where;
            for (const tp::BoundFeature& f : b.features) {
                const std::size_t pi = piece_index(f.piece, "binding '" + b.measurement + "'");
                if (where.find(f.piece) == std::string::npos) {
                    where += (where.empty() ? "" : ", ") + f.piece;
                }
                if (!f.edges.empty()) {
                    for (std::size_t e : f.edges) {
                        if (e >= m_.pieces[pi].outline.size()) {
                            throw InvalidInput("binding '" + b.measurement + "': piece '" +
                                               f.piece + "' has no edge " + std::to_string(e));
                        }
                        add_edge_items(pi, e, f.count, t);
                    }
                } else {
                    const std::size_t a = named_node(pi, f.from_point);
                    const std::size_t c = named_node(pi, f.to_point);
                    if (a == npos || c == npos) {
                        throw InvalidInput("binding '" + b.measurement + "': piece '" + f.piece +
                                           "' has no point '" +
                                           (a == npos ? f.from_point : f.to_point) +
                                           "' on or inside its outline");
                    }
                    LengthItem item;
                    item.kind = LengthItem::span;
                    item.coef = f.count;
                    item.slot = {slot(t, a), slot(t, c), 0, 0};
                    t.items.push_back(item);
                }
            }
            const std::optional<double> base = from.get(b.measurement);
            const std::optional<double> target = to.get(b.measurement);
            if (!target) {
                throw InvalidInput("target set '" + to.name + "': no measurement '" +
                                   b.measurement + "', which the pattern binds (" + where + ")");
            }
            check_target_ratio(b.measurement, base, *target, max_target_ratio, from, to);
            double e = b.ease_mm;
            if (ease == EaseMode::proportional) {
                if (!base || *base <= 0) {
                    throw InvalidInput("base set '" + from.name + "': no measurement '" +
                                       b.measurement + "' (needed for proportional ease; " +
                                       "give it or use ease keep_mm)");
                }
                e = b.ease_mm * *target / *base;
            }
            t.constant = *target + e;
            // Split: each piece's part grows in proportion to its base share of the girth.
            if (split_girths && b.features.size() > 1) {
                std::vector<LengthTerm> parts;
                std::map<std::string, std::size_t> part_of;
                const LengthTerm& all = t;
                // Items were added feature by feature, in order; regroup them per piece.
                std::size_t item = 0;
                for (const tp::BoundFeature& f : b.features) {
                    const std::size_t n_items = f.edges.empty() ? 1 : f.edges.size();
                    auto [pos, fresh] = part_of.insert({f.piece, parts.size()});
                    if (fresh) {
                        parts.emplace_back();
                        parts.back().weight = weight;
                    }
                    LengthTerm& part = parts[pos->second];
                    for (std::size_t k = 0; k < n_items; ++k, ++item) {
                        LengthItem li = all.items[item];
                        for (std::size_t s = 0; s < 4; ++s) {
                            if (li.kind == LengthItem::cubic || s < 2) {
                                li.slot[s] = slot(part, all.idx[li.slot[s]]);
                            }
                        }
                        part.items.push_back(li);
                    }
                }
                if (parts.size() > 1) {
                    const double total0 = length_at_base(all);
                    for (LengthTerm& part : parts) {
                        part.constant = t.constant * length_at_base(part) / total0;
                        m_.shares.push_back(std::move(part));
                    }
                }
            }
            m_.fit.push_back(std::move(t));
            m_.bindings.push_back({b.measurement, where, *target, e});
        }
    }

    /// Seams: the pattern's own and those of `extra` the pattern does not hold (by name: an
    /// imported FreeSewing pattern holds some of its design's seams already). Sides equal in the
    /// base draft (within `tolerance`) are held equal; otherwise the base ratio a/b is kept (a
    /// deliberate difference such as sleeve-cap ease). Residual w (len(a) − ratio · len(b)).
    void build_seams(double weight, double tolerance, const std::vector<SeamSpec>& extra) {
        std::vector<SeamSpec> all;
        for (const tp::Seam& s : p_.seams) {
            all.push_back({s.name.empty() ? s.a.piece + "/" + s.b.piece : s.name, {s.a}, {s.b}});
        }
        const std::size_t own = all.size();
        for (const SeamSpec& s : extra) {
            if (std::none_of(all.begin(), all.begin() + own,
                             [&](const SeamSpec& q) { return q.name == s.name; })) {
                all.push_back(s);
            }
        }
        for (const SeamSpec& s : all) {
            LengthTerm side[2];
            for (int k = 0; k < 2; ++k) {
                const std::vector<tp::EdgeRange>& ranges = k == 0 ? s.a : s.b;
                if (ranges.empty()) {
                    throw InvalidInput("seam '" + s.name + "': side " + (k == 0 ? "a" : "b") +
                                       " has no edges");
                }
                for (const tp::EdgeRange& r : ranges) {
                    const std::size_t pi = piece_index(r.piece, "seam '" + s.name + "'");
                    const std::size_t n = m_.pieces[pi].outline.size();
                    if (r.count == 0 || r.count > n || r.first_edge >= n) {
                        throw InvalidInput("seam '" + s.name + "': piece '" + r.piece +
                                           "' has no edges " + std::to_string(r.first_edge) +
                                           " + " + std::to_string(r.count));
                    }
                    for (std::size_t e = 0; e < r.count; ++e) {
                        add_edge_items(pi, (r.first_edge + e) % n, 1.0, side[k]);
                    }
                }
            }
            const double la = length_at_base(side[0]), lb = length_at_base(side[1]);
            const double ratio = (std::abs(la - lb) <= tolerance || lb <= 0) ? 1.0 : la / lb;
            LengthTerm t = side[0];
            t.weight = weight;
            for (LengthItem it : side[1].items) {
                for (std::size_t q = 0; q < 4; ++q) {
                    if (it.kind == LengthItem::cubic || q < 2) {
                        it.slot[q] = slot(t, side[1].idx[it.slot[q]]);
                    }
                }
                it.coef = -ratio;
                t.items.push_back(it);
            }
            m_.seams.push_back(std::move(t));
            m_.seam_names.push_back(s.name);
            m_.seam_ratio.push_back(ratio);
        }
    }

    void build_style(const GradingWeights& w, double lref) {
        for (std::size_t pi = 0; pi < p_.pieces.size(); ++pi) {
            const auto& out = m_.pieces[pi].outline;
            const std::size_t n = out.size();
            for (std::size_t e = 0; e < n; ++e) {
                const EdgeNodes& cur = out[e];
                const EdgeNodes& next = out[(e + 1) % n];
                // Tangent nodes: the last control point before the vertex that is not the vertex.
                const std::size_t v = cur.kind == 1 ? cur.n[3] : cur.n[1];
                std::size_t a = npos, b = npos;
                if (cur.kind == 1) {
                    a = cur.n[2] != v ? cur.n[2] : (cur.n[1] != v ? cur.n[1] : cur.n[0]);
                } else {
                    a = cur.n[0];
                }
                if (next.kind == 1) {
                    b = next.n[1] != v ? next.n[1] : (next.n[2] != v ? next.n[2] : next.n[3]);
                } else {
                    b = next.n[1];
                }
                if (a == v || b == v || a == npos || b == npos) {
                    continue;
                }
                const tp::Point2 t1 = m_.base[v] - m_.base[a], t2 = m_.base[b] - m_.base[v];
                const double th = std::atan2(tp::cross(t1, t2), tp::dot(t1, t2));
                TurnTerm t;
                t.idx = {a, v, b};
                t.sin0 = std::sin(th);
                t.cos0 = std::cos(th);
                t.weight = w.angle * lref;
                m_.turns.push_back(t);
            }
            for (const EdgeNodes& en : out) {
                if (en.kind != 1) {
                    continue;
                }
                const tp::Point2 p0 = m_.base[en.n[0]], p1 = m_.base[en.n[1]],
                                 p2 = m_.base[en.n[2]], p3 = m_.base[en.n[3]];
                CurveTerm c;
                c.idx = {en.n[0], en.n[1], en.n[2], en.n[3]};
                c.shape0 = curve_shape(p0.x, p0.y, p1.x, p1.y, p2.x, p2.y, p3.x, p3.y);
                c.weight = w.curve * tp::distance(p0, p3);
                if (tp::distance(p0, p3) > 1e-6) {
                    m_.curves.push_back(c);
                }
            }
            const tp::Piece& piece = p_.pieces[pi];
            if (piece.grain) {
                const PieceModel& pm = m_.pieces[pi];
                std::size_t a = npos, b = npos;
                for (std::size_t k = pm.first; k < pm.first + pm.count; ++k) {
                    if (tp::distance(m_.base[k], piece.grain->from) <= m_.node_tolerance) {
                        a = k;
                    }
                    if (tp::distance(m_.base[k], piece.grain->to) <= m_.node_tolerance) {
                        b = k;
                    }
                }
                if (a != npos && b != npos && a != b) {
                    const tp::Point2 g = m_.base[b] - m_.base[a];
                    const double th = std::atan2(g.y, g.x);
                    m_.grains.push_back({{a, b}, std::sin(th), std::cos(th), w.grain * lref});
                }
            }
        }
    }

    void build_graph(std::size_t k, double proportion_weight) {
        std::set<std::pair<std::size_t, std::size_t>> edges;
        auto add = [&](std::size_t a, std::size_t b) {
            if (a != b) {
                edges.insert({std::min(a, b), std::max(a, b)});
            }
        };
        for (std::size_t pi = 0; pi < m_.pieces.size(); ++pi) {
            const PieceModel& pm = m_.pieces[pi];
            for (const EdgeNodes& en : pm.outline) {
                const std::size_t last = en.kind == 1 ? 3 : 1;
                for (std::size_t s = 0; s < last; ++s) {
                    add(en.n[s], en.n[s + 1]);
                }
            }
            std::vector<std::pair<double, std::size_t>> near;
            for (std::size_t i = pm.first; i < pm.first + pm.count; ++i) {
                near.clear();
                for (std::size_t j = pm.first; j < pm.first + pm.count; ++j) {
                    if (j != i) {
                        near.push_back({tp::distance(m_.base[i], m_.base[j]), j});
                    }
                }
                const std::size_t kk = std::min(k, near.size());
                std::partial_sort(near.begin(), near.begin() + kk, near.end());
                for (std::size_t q = 0; q < kk; ++q) {
                    add(i, near[q].second);
                }
            }
        }
        m_.graph.assign(edges.begin(), edges.end());
        for (const auto& [i, j] : m_.graph) {
            m_.proportions.push_back(
                {i, j, m_.piece_of[i], tp::distance(m_.base[i], m_.base[j]), proportion_weight});
        }
    }

    static constexpr std::size_t npos = static_cast<std::size_t>(-1);

private:
    std::size_t piece_index(const std::string& name, const std::string& what) const {
        for (std::size_t i = 0; i < p_.pieces.size(); ++i) {
            if (p_.pieces[i].name == name) {
                return i;
            }
        }
        throw InvalidInput(what + ": no piece '" + name + "'");
    }

    double length_at_base(const LengthTerm& t) const {
        auto pos = [&](std::size_t k) {
            const tp::Point2& q = m_.base[t.idx[k]];
            return V2<double>{q.x, q.y};
        };
        return t.template length<double>(pos);
    }

    static std::size_t slot(LengthTerm& t, std::size_t node) {
        for (std::size_t k = 0; k < t.idx.size(); ++k) {
            if (t.idx[k] == node) {
                return k;
            }
        }
        t.idx.push_back(node);
        return t.idx.size() - 1;
    }

    const tp::Pattern& p_;
    Model& m_;
};

/// Builds the whole problem. Bindings must name measurements of `to` (InvalidInput otherwise).
inline Model build_model(const tp::Pattern& p, const sizes::MeasurementSet& from,
                         const sizes::MeasurementSet& to, const GradingOptions& o,
                         const std::vector<SeamSpec>& seams = {}) {
    Model m;
    ModelBuilder b(p, m);
    b.build_nodes();
    b.mark_trims(o.trim_aspect);
    b.build_bindings(from, to, o.ease, o.weights.fit, o.split_girths, o.max_target_ratio);
    b.build_seams(o.weights.seam, o.tolerances.seam_mm, seams);
    b.build_style(o.weights, o.reference_length_mm);
    b.build_graph(o.neighbours, o.weights.proportion);
    return m;
}

// --- evaluation in double -----------------------------------------------------------------------

template <typename Term>
void eval_term(const Term& t, const std::vector<tp::Point2>& x, double* r) {
    auto pos = [&](std::size_t k) {
        const tp::Point2& q = x[t.idx[k]];
        return V2<double>{q.x, q.y};
    };
    t.template operator()<double>(pos, r);
}

inline double length_of(const LengthTerm& t, const std::vector<tp::Point2>& x) {
    auto pos = [&](std::size_t k) {
        const tp::Point2& q = x[t.idx[k]];
        return V2<double>{q.x, q.y};
    };
    return t.template length<double>(pos);
}

/// Per-piece least-squares uniform scale of the proportion pairs at positions x.
inline std::vector<double> piece_scales(const Model& m, const std::vector<tp::Point2>& x) {
    std::vector<double> num(m.pieces.size(), 0), den(m.pieces.size(), 0);
    for (const ProportionTerm& t : m.proportions) {
        num[t.piece] += tp::distance(x[t.i], x[t.j]) * t.l0;
        den[t.piece] += t.l0 * t.l0;
    }
    std::vector<double> s(m.pieces.size(), 1);
    for (std::size_t i = 0; i < s.size(); ++i) {
        s[i] = den[i] > 0 ? num[i] / den[i] : 1;
    }
    return s;
}

struct Objectives {
    double fit = 0;    // RMS over bindings and seams (mm)
    double style = 0;  // RMS over the style residuals
    double max_fit = 0, max_seam = 0;
};

inline Objectives objectives(const Model& m, const std::vector<tp::Point2>& x) {
    Objectives o;
    double s2 = 0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < m.fit.size(); ++i) {
        const double e = length_of(m.fit[i], x) - m.fit[i].constant;
        s2 += e * e;
        ++n;
        o.max_fit = std::max(o.max_fit, std::abs(e));
    }
    for (const LengthTerm& t : m.seams) {
        const double e = length_of(t, x);
        s2 += e * e;
        ++n;
        o.max_seam = std::max(o.max_seam, std::abs(e));
    }
    for (const LengthTerm& t : m.shares) {
        const double e = length_of(t, x) - t.constant;
        s2 += e * e;
        ++n;
    }
    o.fit = n ? std::sqrt(s2 / n) : 0;
    double st = 0;
    std::size_t ns = 0;
    double r[4];
    for (const TurnTerm& t : m.turns) {
        eval_term(t, x, r);
        st += r[0] * r[0];
        ++ns;
    }
    for (const GrainTerm& t : m.grains) {
        eval_term(t, x, r);
        st += r[0] * r[0];
        ++ns;
    }
    for (const CurveTerm& t : m.curves) {
        eval_term(t, x, r);
        st += r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3];
        ns += 4;
    }
    const std::vector<double> s = piece_scales(m, x);
    for (const ProportionTerm& t : m.proportions) {
        const double e = t.weight * (tp::distance(x[t.i], x[t.j]) - s[t.piece] * t.l0);
        st += e * e;
        ++ns;
    }
    o.style = ns ? std::sqrt(st / ns) : 0;
    return o;
}

inline std::vector<tp::Point2> positions(const Model& m, const Solution& s) {
    std::vector<tp::Point2> x(m.base.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
        x[i] = m.base[i] + s.d[i];
    }
    return x;
}

// --- back to a pattern --------------------------------------------------------------------------

/// Moves a point of piece `pi`: a node moves with its displacement, anything else with the local
/// affine model of its nearest node.
inline tp::Point2 deform(const Model& m, const Solution& s, std::size_t pi, const tp::Point2& q) {
    const PieceModel& pm = m.pieces[pi];
    std::size_t best = pm.first;
    double bd = 1e300;
    for (std::size_t k = pm.first; k < pm.first + pm.count; ++k) {
        const double d = tp::distance(m.base[k], q);
        if (d < bd) {
            bd = d;
            best = k;
        }
    }
    if (pm.count == 0) {
        return q;
    }
    const tp::Point2 r = q - m.base[best];
    const auto& A = s.A[best];
    if (bd <= m.node_tolerance) {
        return q + s.d[best];
    }
    return q + s.d[best] + tp::Point2{A[0] * r.x + A[1] * r.y, A[2] * r.x + A[3] * r.y};
}

inline tp::Curve deform_curve(const Model& m, const Solution& s, std::size_t pi,
                              const tp::Curve& c) {
    auto f = [&](const tp::Point2& q) { return deform(m, s, pi, q); };
    if (const auto* l = std::get_if<tp::Line>(&c)) {
        return tp::Line{f(l->a), f(l->b)};
    }
    if (const auto* b = std::get_if<tp::CubicBezier>(&c)) {
        return tp::CubicBezier{f(b->p0), f(b->p1), f(b->p2), f(b->p3)};
    }
    tp::Arc a = std::get<tp::Arc>(c);
    const double chord0 = tp::distance(a.a, a.b);
    a.a = f(a.a);
    a.b = f(a.b);
    if (chord0 > 0) {
        a.radius *= tp::distance(a.a, a.b) / chord0;
    }
    return a;
}

inline tp::Pattern apply(const tp::Pattern& base, const Model& m, const Solution& s) {
    tp::Pattern out = base;
    for (std::size_t pi = 0; pi < out.pieces.size(); ++pi) {
        tp::Piece& piece = out.pieces[pi];
        const tp::Piece& p0 = base.pieces[pi];
        auto f = [&](const tp::Point2& q) { return deform(m, s, pi, q); };
        for (tp::Edge& e : piece.outline.edges) {
            e.curve = deform_curve(m, s, pi, e.curve);
        }
        // Outline ends are shared nodes, so the deformed edges still join exactly.
        for (std::size_t k = 0; k < piece.notches.size(); ++k) {
            tp::Notch& n = piece.notches[k];
            const double l0 = tp::length(p0.outline.edges.at(n.edge));
            const double l1 = tp::length(piece.outline.edges.at(n.edge));
            if (l0 > 0) {
                n.offset *= l1 / l0;
            }
        }
        for (auto& [name, q] : piece.points) {
            q = f(q);
        }
        if (piece.grain) {
            piece.grain->from = f(piece.grain->from);
            piece.grain->to = f(piece.grain->to);
        }
        if (piece.fold) {
            piece.fold->line.a = f(piece.fold->line.a);
            piece.fold->line.b = f(piece.fold->line.b);
        }
        for (tp::InternalLine& l : piece.internal_lines) {
            for (tp::Edge& e : l.edges) {
                e.curve = deform_curve(m, s, pi, e.curve);
            }
        }
        for (tp::Dart& d : piece.darts) {
            for (tp::Edge& e : d.edges) {
                e.curve = deform_curve(m, s, pi, e.curve);
            }
        }
    }
    return out;
}

}  // namespace tapeline::grading::internal
