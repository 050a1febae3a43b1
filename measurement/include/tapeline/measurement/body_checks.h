// Refusal of meshes that are not one upright human body, before and after the landmark search.
// Each refusal is an InvalidInput with one line naming the mesh, what looks wrong and what to try
// (`--units`, `--up`), so that nothing is measured on a 15.9 m person or a body lying on its side.
//
// The proportion bands are deliberately wide (several standard deviations of adult populations,
// wide enough for children): they catch a wrong unit, a wrong axis or a mesh that is not a body,
// not an unusual person. Sources:
//  - segment lengths as fractions of stature H after Drillis & Contini (1966), "Body segment
//    parameters", Report 1166-03, New York University, as tabulated in D. A. Winter,
//    "Biomechanics and Motor Control of Human Movement", 4th ed. (2009), Fig. 4.1: shoulder
//    (acromion) height 0.818 H, chin 0.870 H, upper arm 0.186 H, forearm 0.146 H, hip (greater
//    trochanter) height 0.530 H, knee height 0.285 H;
//  - stature 0.5-2.5 m covers small children to the tallest adults.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/measurement/body.h>
#include <tapeline/measurement/internal/sections.h>
#include <tapeline/measurement/measurement_types.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

namespace tapeline::measurement {

namespace internal {

inline std::string fmt(const char* f, double a, double b = 0, double c = 0) {
    char buf[160];
    std::snprintf(buf, sizeof buf, f, a, b, c);
    return buf;
}

/// Connected components (by shared vertices) of a triangle soup: per component its bounding box
/// (min, max) and vertex count.
struct ComponentBox {
    Vec3 lo, hi;
    std::size_t vertices = 0;
};

inline std::vector<ComponentBox> component_boxes(const BodyMesh& m) {
    std::vector<std::uint32_t> parent(m.points.size());
    std::iota(parent.begin(), parent.end(), 0u);
    auto root = [&parent](std::uint32_t v) {
        while (parent[v] != v) {
            parent[v] = parent[parent[v]];
            v = parent[v];
        }
        return v;
    };
    for (const auto& t : m.triangles) {
        for (int k = 1; k < 3; ++k) {
            const std::uint32_t a = root(t[0]), b = root(t[static_cast<std::size_t>(k)]);
            if (a != b) {
                parent[b] = a;
            }
        }
    }
    std::vector<int> index(m.points.size(), -1);
    std::vector<ComponentBox> out;
    for (std::uint32_t v = 0; v < m.points.size(); ++v) {
        const std::uint32_t r = root(v);
        if (index[r] < 0) {
            index[r] = static_cast<int>(out.size());
            out.push_back({m.points[v], m.points[v], 0});
        }
        ComponentBox& c = out[static_cast<std::size_t>(index[r])];
        for (int k = 0; k < 3; ++k) {
            c.lo[k] = std::min(c.lo[k], m.points[v][k]);
            c.hi[k] = std::max(c.hi[k], m.points[v][k]);
        }
        ++c.vertices;
    }
    return out;
}

/// Sections of a horizontal cut whose tape is longer than `min_perimeter`.
inline int significant_sections(const BodyMesh& m, double y, double min_perimeter) {
    CutWorkspace ws;
    const PlaneSection ps = section(m, Plane::horizontal(y), ws);
    int n = 0;
    for (const auto& s : ps.sections) {
        n += s.perimeter > min_perimeter ? 1 : 0;
    }
    return n;
}

}  // namespace internal

/// Refuses a mesh that cannot be one upright human body, from its shape alone: stature outside
/// 0.5-2.5 m, separate bodies, the longest extent not along the up axis, the feet at the top.
inline void check_body_shape(const Body& body) {
    using internal::fmt;
    const std::string& name = body.mesh.name;
    const double h = body.frame.height;
    const auto& pts = body.mesh.points;
    Vec3 lo = pts.front(), hi = pts.front();
    for (const auto& p : pts) {
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], p[k]);
            hi[k] = std::max(hi[k], p[k]);
        }
    }
    // Several parts are fine when they overlap (a body given as a union of parts); parts of
    // significant size (a tenth of the height across) that are apart are separate bodies.
    auto boxes = internal::component_boxes(body.mesh);
    boxes.erase(std::remove_if(boxes.begin(), boxes.end(),
                               [h](const internal::ComponentBox& c) {
                                   return internal::dist(c.lo, c.hi) < 0.1 * h;
                               }),
                boxes.end());
    std::vector<std::size_t> group(boxes.size());
    std::iota(group.begin(), group.end(), std::size_t{0});
    const double slack = 0.01 * h;
    for (bool changed = true; changed;) {
        changed = false;
        for (std::size_t i = 0; i < boxes.size(); ++i) {
            for (std::size_t j = i + 1; j < boxes.size(); ++j) {
                bool overlap = group[i] != group[j];
                for (int k = 0; k < 3 && overlap; ++k) {
                    overlap = boxes[i].lo[k] <= boxes[j].hi[k] + slack &&
                              boxes[j].lo[k] <= boxes[i].hi[k] + slack;
                }
                if (overlap) {
                    const std::size_t g = std::min(group[i], group[j]);
                    group[i] = group[j] = g;
                    changed = true;
                }
            }
        }
    }
    std::vector<std::size_t> groups = group;
    std::sort(groups.begin(), groups.end());
    groups.erase(std::unique(groups.begin(), groups.end()), groups.end());
    if (groups.size() > 1) {
        // Lateral centre of each group, for the message.
        std::string where;
        for (std::size_t g : groups) {
            double x0 = std::numeric_limits<double>::infinity(), x1 = -x0;
            for (std::size_t i = 0; i < boxes.size(); ++i) {
                if (group[i] == g) {
                    x0 = std::min(x0, boxes[i].lo[0]);
                    x1 = std::max(x1, boxes[i].hi[0]);
                }
            }
            where += (where.empty() ? "" : ", ") + fmt("%.0f", 0.5 * (x0 + x1));
        }
        throw InvalidInput(name + ": not one body: " + std::to_string(groups.size()) +
                           " separate parts of body size (centred at x = " + where +
                           " mm across); measure one body per file");
    }
    // Upright: a standing body is taller than it is wide or deep; a T-pose arm span is about the
    // stature, so sideways up to 1.2 times the height is accepted there.
    const double width = hi[0] - lo[0], depth = hi[2] - lo[2];
    // Arms spread sideways: the hands (the mesh's lateral extremes) near shoulder height. In
    // MakeHuman's A-pose they are at 0.50-0.57 of the stature (209 bodies), in GarmentMeasurements'
    // mean body at 0.55, in SMPL's and SMPL-X's T-poses at 0.75-0.80. Measured as an A-pose, a
    // T-pose loses its armpits and takes its shoulder points out along the arms.
    if (body.frame.pose == Pose::a_pose && width >= 0.6 * h && width <= 1.2 * h && depth <= h) {
        double y_lo = 0, y_hi = 0;
        for (const auto& p : pts) {
            if (p[0] == lo[0]) {
                y_lo = p[1];
            }
            if (p[0] == hi[0]) {
                y_hi = p[1];
            }
        }
        const double hands = (std::min(y_lo, y_hi) - lo[1]) / h;
        if (hands >= 0.65) {
            throw InvalidInput(name + ": the arms are spread sideways as in a T-pose (the hands " +
                               fmt("at %.2f of the stature, ", hands) +
                               fmt("the mesh %.0f mm wide); pass --pose T", width));
        }
    }
    const double max_side = body.frame.pose == Pose::t_pose ? 1.2 * h : h;
    if (width > max_side || depth > h) {
        const bool wide = width >= depth;
        throw InvalidInput(
            name + ": not upright: the mesh is " + fmt("%.0f mm ", wide ? width : depth) +
            (wide ? "wide" : "deep") + fmt(" but only %.0f mm tall along the up axis ", h) +
            body.frame.up.to_string() + "; pass the axis the body stands along with --up");
    }
    if (h < 500 || h > 2500) {
        throw InvalidInput(name + ": stature " + fmt("%.3g m", h / 1000) + " with --units " +
                           to_string(body.frame.unit) +
                           " is not a human height (0.5-2.5 m); check the mesh's unit and pass "
                           "the right --units (m, dm, cm or mm)");
    }
    // Feet at the bottom: near the floor a standing body is two feet (or one pair of them), near
    // the top one head; upside down it is the other way round.
    const double min_perimeter = 0.05 * h;
    const int bottom = internal::significant_sections(body.mesh, lo[1] + 0.02 * h, min_perimeter);
    const int top = internal::significant_sections(body.mesh, hi[1] - 0.02 * h, min_perimeter);
    if (top >= 2 && bottom <= 1) {
        throw InvalidInput(name + ": upside down: " + std::to_string(top) +
                           " parts near the top (feet?) and " + std::to_string(bottom) +
                           " near the bottom along the up axis " + body.frame.up.to_string() +
                           "; pass the opposite axis with --up");
    }
}

/// One proportion check: a length as a fraction of stature and its accepted band.
struct ProportionBand {
    /// The length, as messages name it ("leg length (crotch height)").
    const char* what;
    /// Lowest and highest accepted value, fractions of stature.
    ///@{
    double lo, hi;
    ///@}
};

/// Refuses a body whose landmarks give proportions no human has (head, legs, arms as fractions
/// of stature, bands around Drillis & Contini's means, see the top of this file), or on which
/// none of legs, arms and neck was found.
inline void check_body_proportions(const Body& body, const LandmarkSet& set) {
    using internal::fmt;
    const std::string& name = body.mesh.name;
    const double h = body.frame.height;
    // Landmarks found on the mesh only: a wrong unit, axis or mesh shows in them, while a point
    // the user placed (an override) is the user's word, checked by the self-checks instead.
    auto found = [&set](const std::string& landmark) -> std::optional<Vec3> {
        const Landmark* l = set.find(landmark);
        if (l == nullptr || l->status != LandmarkStatus::found) {
            return std::nullopt;
        }
        return l->point;
    };
    const auto crotch = found("crotch");
    const auto snp_l = found("side_neck_left"), snp_r = found("side_neck_right");
    const bool arms = found("armpit_left") || found("armpit_right");
    if (!crotch && !arms && !snp_l && !snp_r) {
        throw InvalidInput(name +
                           ": does not look like a body: no legs (crotch), arms (armpits) "
                           "or neck found; check --up and --front, or the mesh");
    }
    std::vector<std::string> bad;
    auto band = [&](const char* what, double value, double lo, double hi) {
        if (value < lo || value > hi) {
            bad.push_back(std::string(what) +
                          fmt(" %.2f of the stature (expected %.2f-%.2f)", value, lo, hi));
        }
    };
    if (crotch) {
        band("leg length (crotch height)", (*crotch)[1] / h, 0.36, 0.58);
    }
    if (snp_l || snp_r) {
        const double y = snp_l && snp_r ? 0.5 * ((*snp_l)[1] + (*snp_r)[1])
                                        : (snp_l ? (*snp_l)[1] : (*snp_r)[1]);
        band("head and neck length (top of head to side neck point)", (h - y) / h, 0.07, 0.26);
    }
    for (const char* side : {"left", "right"}) {
        const auto ac = found(std::string("acromion_") + side);
        const auto wr = found(std::string("wrist_") + side);
        if (ac && wr) {
            band((std::string(side) + " arm length (acromion to wrist)").c_str(),
                 internal::dist(*ac, *wr) / h, 0.22, 0.45);
        }
    }
    if (!bad.empty()) {
        throw InvalidInput(name + ": implausible proportions for a human body: " + bad.front() +
                           "; check --up, --front and --units, or the mesh");
    }
}

}  // namespace tapeline::measurement
