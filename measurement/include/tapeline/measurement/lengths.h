// Lengths along the skin between landmarks: shortest paths on the body mesh by the geodesic
// module's curvature flow (GeodesicPathSolver; see geodesic/README.md for the method), the way a
// tape laid on the skin measures a length.
//
// Every length is a chain of waypoints on the surface (landmarks snapped to their nearest surface
// point, or points found by casting a ray from inside the body, which hits the skin of the part
// the ray starts in first), joined by geodesic paths; leg lengths end at the ankle and add the
// ankle's height (the tape then hangs straight down to the floor). The crotch length (cross seam)
// is the exception: a taut tape in the mid-sagittal plane (measure_cross_seam), not a geodesic.
// Definitions: measurement/README.
#pragma once

#include <tapeline/geodesic/curvature_flow.h>
#include <tapeline/geodesic/sources.h>
#include <tapeline/measurement/body.h>
#include <tapeline/measurement/body_types.h>
#include <tapeline/measurement/holes.h>
#include <tapeline/measurement/measurement_types.h>
#include <tapeline/measurement/shoulder_slope.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Polygon_mesh_slicer.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_2.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace tapeline::measurement {

/// One length to take: its names and the surface points the path goes through, in order.
///
/// \tparam TriangleMesh the body mesh type; a model of `FaceGraph`.
template <class TriangleMesh>
struct SkinLength {
    std::string name;                    ///< a catalogue name (tapeline/sizes/catalogue.h)
    std::vector<std::string> landmarks;  ///< the landmarks the path passes, in order
    std::vector<geodesic::FaceLocation<TriangleMesh>> waypoints;  ///< their surface points
    double floor_drop = 0;  ///< mm added after the last waypoint: straight down to the floor
};

/// The lengths that can be taken and those that cannot, with the reason.
///
/// \tparam TriangleMesh the body mesh type; a model of `FaceGraph`.
template <class TriangleMesh>
struct SkinLengthPlan {
    std::vector<SkinLength<TriangleMesh>> lengths;  ///< lengths to take
    std::vector<MissingMeasurement> missing;        ///< lengths that cannot be taken, and why
};

/// Finds surface points of a body mesh from canonical-frame queries (an AABB tree over its faces).
///
/// \tparam TriangleMesh a model of `FaceListGraph` (CGAL::Surface_mesh, ...), every face a
///         triangle.
/// \tparam NamedParameters a sequence of CGAL named parameters; accepted: `vertex_point_map`
///         (a `ReadablePropertyMap` vertex_descriptor -> `geom_traits::Point_3`),
///         `geom_traits` (a CGAL kernel).
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
class SkinLocator {
public:
    using Location = geodesic::FaceLocation<TriangleMesh>;  ///< a face and barycentric coordinates
    /// The kernel of the named parameters.
    using GeomTraits = typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type;
    /// The vertex point map of the named parameters.
    using VertexPointMap =
        typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::const_type;
    /// AABB primitive: one face.
    using Primitive = CGAL::AABB_face_graph_triangle_primitive<TriangleMesh, VertexPointMap>;
    using Tree = CGAL::AABB_tree<CGAL::AABB_traits<GeomTraits, Primitive>>;  ///< the face tree

    /// Builds the tree over the faces of `tm` (which must outlive the locator); `frame` maps
    /// canonical coordinates to the mesh's.
    SkinLocator(const TriangleMesh& tm, const BodyFrame& frame,
                const NamedParameters& np = CGAL::parameters::default_values())
        : tm_(tm), frame_(frame), np_(np) {
        CGAL::Polygon_mesh_processing::build_AABB_tree(tm_, tree_, np_);
    }

    /// The surface point nearest to a canonical point.
    Location nearest(const Vec3& canonical) const {
        const Vec3 p = frame_.to_input(canonical);
        const typename GeomTraits::Point_3 q(p[0], p[1], p[2]);
        return finite(CGAL::Polygon_mesh_processing::locate_with_AABB_tree(q, tree_, tm_, np_), q);
    }
    /// The first surface point hit by the ray from a canonical point along a canonical
    /// direction; nullopt when it hits nothing.
    std::optional<Location> ray(const Vec3& origin, const Vec3& direction) const {
        const Vec3 o = frame_.to_input(origin);
        Vec3 d{0, 0, 0};
        for (int r = 0; r < 3; ++r) {
            for (int k = 0; k < 3; ++k) {
                d[k] += frame_.rows[r][k] * direction[r];
            }
        }
        using Point = typename GeomTraits::Point_3;
        const typename GeomTraits::Ray_3 ray(Point(o[0], o[1], o[2]),
                                             typename GeomTraits::Vector_3(d[0], d[1], d[2]));
        const Location l =
            CGAL::Polygon_mesh_processing::locate_with_AABB_tree(ray, tree_, tm_, np_);
        if (l.first == boost::graph_traits<TriangleMesh>::null_face()) {
            return std::nullopt;
        }
        return finite(l, ray);
    }
    /// `l` itself when its barycentric coordinates are finite; on a zero-area face (a sliver of a
    /// scan or a boolean union), where they are not, the corner of its face nearest to the query
    /// `q` (a point or a ray).
    template <class Query>
    Location finite(Location l, const Query& q) const {
        const auto& b = l.second;
        if (std::isfinite(CGAL::to_double(b[0])) && std::isfinite(CGAL::to_double(b[1])) &&
            std::isfinite(CGAL::to_double(b[2]))) {
            return l;
        }
        const auto vpm = CGAL::parameters::choose_parameter(
            CGAL::parameters::get_parameter(np_, CGAL::internal_np::vertex_point),
            CGAL::get_const_property_map(CGAL::vertex_point, tm_));
        // The corners in the order of the barycentric coordinates (PMP::construct_point).
        const auto h = halfedge(l.first, tm_);
        const std::array<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, 3> corners{
            source(h, tm_), target(h, tm_), target(next(h, tm_), tm_)};
        int best = 0;
        double best_d = std::numeric_limits<double>::infinity();
        for (int k = 0; k < 3; ++k) {
            const double d = CGAL::to_double(CGAL::squared_distance(get(vpm, corners[k]), q));
            if (d < best_d) {
                best_d = d;
                best = k;
            }
        }
        using FT = typename GeomTraits::FT;
        l.second = {FT(best == 0), FT(best == 1), FT(best == 2)};
        return l;
    }
    /// A surface point in the canonical frame.
    Vec3 canonical(const Location& l) const {
        const auto p = CGAL::Polygon_mesh_processing::construct_point(l, tm_, np_);
        return frame_.to_canonical(
            {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
    }

private:
    const TriangleMesh& tm_;
    BodyFrame frame_;
    NamedParameters np_;
    Tree tree_;
};

namespace internal {

inline Vec3 mid(const Vec3& a, const Vec3& b) {
    return {(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2};
}

}  // namespace internal

/// Which lengths can be taken from these landmarks and through which surface points; the others
/// are `missing` with a reason naming the landmark. Limb lengths use the body's right side
/// (the left when a right landmark is missing), like the unsuffixed limb girths.
///
/// \tparam TriangleMesh, NamedParameters as for SkinLocator.
template <class TriangleMesh, class NamedParameters>
SkinLengthPlan<TriangleMesh> plan_skin_lengths(const SkinLocator<TriangleMesh, NamedParameters>& at,
                                               const LandmarkSet& lm) {
    using internal::mid;
    SkinLengthPlan<TriangleMesh> plan;
    // The first landmark of `names` that is not available, as a reason; empty when all are.
    auto lacking = [&](const std::vector<std::string>& names) -> std::string {
        for (const auto& n : names) {
            const Landmark* l = lm.find(n);
            if (!l || !l->available()) {
                return l ? l->reason : n + ": unknown landmark";
            }
        }
        return "";
    };
    // Right side unless one of its landmarks is missing and the left has them all.
    auto side_of = [&](const std::vector<std::string>& stems) {
        std::vector<std::string> right, left;
        for (const auto& s : stems) {
            right.push_back(s + "_right");
            left.push_back(s + "_left");
        }
        return lacking(right).empty() || !lacking(left).empty() ? std::string("right")
                                                                : std::string("left");
    };
    auto P = [&](const std::string& n) { return *lm.point(n); };
    auto add = [&](SkinLength<TriangleMesh> s, const std::vector<std::string>& needs,
                   const auto& build) {
        const std::string why = lacking(needs);
        if (!why.empty()) {
            plan.missing.push_back({s.name, s.name + ": " + why});
            return;
        }
        s.landmarks = needs;
        const std::string fail = build(s);
        if (!fail.empty()) {
            plan.missing.push_back({s.name, s.name + ": " + fail});
            return;
        }
        plan.lengths.push_back(std::move(s));
    };
    auto hit = [&](const Vec3& o, const Vec3& d, SkinLength<TriangleMesh>& s,
                   const std::string& what) {
        const auto l = at.ray(o, d);
        if (!l) {
            return "no skin found for the " + what + " (a ray from inside the body hit nothing)";
        }
        s.waypoints.push_back(*l);
        return std::string();
    };

    // Across-back shoulder width: acromion to acromion through the back midline at their level;
    // the ray starts in the neck base (the side neck points' centre, at the acromions' height).
    add({"shoulder_width_back", {}, {}, 0},
        {"acromion_left", "acromion_right", "side_neck_left", "side_neck_right"}, [&](auto& s) {
            const Vec3 neck = mid(P("side_neck_left"), P("side_neck_right"));
            const Vec3 shoulders = mid(P("acromion_left"), P("acromion_right"));
            s.waypoints.push_back(at.nearest(P("acromion_left")));
            const std::string f = hit({neck[0], shoulders[1], neck[2]}, {0, 0, -1}, s,
                                      "back midline at the shoulders");
            s.waypoints.push_back(at.nearest(P("acromion_right")));
            return f;
        });
    // HPS to waist, back and front: from the side neck point to the waist level straight below
    // it (same x), on the back or front skin.
    for (const bool back : {true, false}) {
        const std::string side = side_of({"side_neck"});
        const std::string hps = "side_neck_" + side;
        add({back ? "hps_to_waist_back" : "hps_to_waist_front", {}, {}, 0},
            {hps, "waist_front", "waist_back"}, [&, hps, back](auto& s) {
                const Vec3 w = mid(P("waist_front"), P("waist_back"));
                s.waypoints.push_back(at.nearest(P(hps)));
                return hit({P(hps)[0], w[1], w[2]}, {0, 0, back ? -1.0 : 1.0}, s,
                           "waist below the side neck point");
            });
    }
    // Arm: acromion to elbow, and on to the wrist (the tape follows the outside of the arm).
    {
        const std::string side = side_of({"acromion", "elbow", "wrist"});
        const std::string a = "acromion_" + side, e = "elbow_" + side, w = "wrist_" + side;
        add({"shoulder_to_elbow", {}, {}, 0}, {a, e}, [&](auto& s) {
            s.waypoints = {at.nearest(P(a)), at.nearest(P(e))};
            return std::string();
        });
        add({"shoulder_to_wrist", {}, {}, 0}, {a, e, w}, [&](auto& s) {
            s.waypoints = {at.nearest(P(a)), at.nearest(P(e)), at.nearest(P(w))};
            return std::string();
        });
    }
    // The waist side: where a ray from the waist centre outwards (out = +1: the body's left)
    // leaves the skin.
    auto waist_side = [&](SkinLength<TriangleMesh>& s, double out) {
        return hit(mid(P("waist_front"), P("waist_back")), {out, 0, 0}, s, "waist side");
    };
    // Legs: inseam from the crotch down the inside of the leg to the inner ankle, outseam from
    // the waist at the side down the outside to the outer ankle; both then straight to the floor.
    {
        const std::string side = side_of({"ankle"});
        const std::string ankle = "ankle_" + side;
        const double out = side == "right" ? -1.0 : 1.0;  // x is the body's left
        auto ankle_point = [&](SkinLength<TriangleMesh>& s, double dir) {
            const Landmark* l = lm.find(ankle);
            const std::string f = hit(l->axis_point, {dir, 0, 0}, s, "ankle");
            if (f.empty()) {
                s.floor_drop = std::max(0.0, at.canonical(s.waypoints.back())[1]);
            }
            return f;
        };
        add({"inseam", {}, {}, 0}, {"crotch", ankle}, [&](auto& s) {
            s.waypoints.push_back(at.nearest(P("crotch")));
            return ankle_point(s, -out);
        });
        add({"outseam", {}, {}, 0}, {"waist_front", "waist_back", ankle}, [&](auto& s) {
            const std::string f = waist_side(s, out);
            return f.empty() ? ankle_point(s, out) : f;
        });
    }
    // Waist to knee: the outseam's start, down the outside of the leg to the knee's level (the
    // point where a ray from the knee's axis point leaves the skin sideways).
    {
        const std::string side = side_of({"knee"});
        const std::string knee = "knee_" + side;
        const double out = side == "right" ? -1.0 : 1.0;  // x is the body's left
        add({"waist_to_knee", {}, {}, 0}, {"waist_front", "waist_back", knee}, [&](auto& s) {
            const std::string f = waist_side(s, out);
            return f.empty() ? hit(lm.find(knee)->axis_point, {out, 0, 0}, s, "knee side") : f;
        });
    }
    // Along the side of the torso: waist to hip level, and armpit down to the waist (the side
    // points are where a ray from the torso's centre at that level leaves the skin sideways).
    {
        const std::string side = side_of({"armpit"});
        const double out = side == "right" ? -1.0 : 1.0;  // x is the body's left
        const std::string armpit = "armpit_" + side;
        // The top hip level is high_hip_girth's plane: halfway between the waist and the hip.
        add({"waist_to_high_hip", {}, {}, 0}, {"waist_front", "waist_back", "hip_back"},
            [&](auto& s) {
                const std::string f = waist_side(s, out);
                if (!f.empty())
                    return f;
                const Vec3 w = mid(P("waist_front"), P("waist_back"));
                return hit({w[0], 0.5 * (P("waist_front")[1] + P("hip_back")[1]), w[2]},
                           {out, 0, 0}, s, "top hip side");
            });
        add({"waist_to_hips", {}, {}, 0}, {"waist_front", "waist_back", "hip_back"}, [&](auto& s) {
            const std::string f = waist_side(s, out);
            if (!f.empty())
                return f;
            const Vec3 w = mid(P("waist_front"), P("waist_back"));
            return hit({w[0], P("hip_back")[1], w[2]}, {out, 0, 0}, s, "hip side");
        });
        add({"waist_to_armpit", {}, {}, 0}, {armpit, "waist_front", "waist_back"}, [&](auto& s) {
            s.waypoints.push_back(at.nearest(P(armpit)));
            return waist_side(s, out);
        });
    }
    // Back neck point (cervicale) to the waist at the back midline (ISO 8559-1 5.4.5), and the
    // front neck point to the waist at the front midline: both ends on the midline, so the
    // shortest path follows the spine / runs down between the breasts.
    add({"back_neck_to_waist", {}, {}, 0}, {"cervicale", "waist_back"}, [&](auto& s) {
        s.waypoints = {at.nearest(P("cervicale")), at.nearest(P("waist_back"))};
        return std::string();
    });
    add({"front_neck_to_waist", {}, {}, 0}, {"front_neck", "waist_front"}, [&](auto& s) {
        s.waypoints = {at.nearest(P("front_neck")), at.nearest(P("waist_front"))};
        return std::string();
    });
    // HPS (side neck point) to the bust point of the same side.
    {
        const std::string side = side_of({"side_neck", "bust"});
        const std::string hps = "side_neck_" + side, bust = "bust_" + side;
        add({"hps_to_bust", {}, {}, 0}, {hps, bust}, [&](auto& s) {
            s.waypoints = {at.nearest(P(hps)), at.nearest(P(bust))};
            return std::string();
        });
    }
    // ISO's across-back shoulder width passes over the back neck point (5.4.3); our
    // shoulder_width_back (FreeSewing's shoulderToShoulder) crosses the back lower, at the
    // acromions' height.
    add({"across_back_shoulder_width", {}, {}, 0}, {"acromion_left", "cervicale", "acromion_right"},
        [&](auto& s) {
            s.waypoints = {at.nearest(P("acromion_left")), at.nearest(P("cervicale")),
                           at.nearest(P("acromion_right"))};
            return std::string();
        });
    // Back neck point over the shoulder point and the elbow to the wrist (ISO 5.4.17, "sleeve
    // length"), on the same side as the arm lengths.
    {
        const std::string side = side_of({"acromion", "elbow", "wrist"});
        const std::string a = "acromion_" + side, e = "elbow_" + side, w = "wrist_" + side;
        add({"back_neck_to_wrist", {}, {}, 0}, {"cervicale", a, e, w}, [&](auto& s) {
            s.waypoints = {at.nearest(P("cervicale")), at.nearest(P(a)), at.nearest(P(e)),
                           at.nearest(P(w))};
            return std::string();
        });
    }
    return plan;
}

/// Takes every length of the plan with `solver` and adds it to `set` (value: the sum of the
/// on-mesh path lengths in mm plus the floor drop; points: the path, canonical mm). A segment
/// whose ends lie on different components of the mesh makes the length missing.
///
/// \tparam TriangleMesh, NamedParameters as for geodesic::GeodesicPathSolver.
/// \throws InvalidInput when a waypoint is not on the solver's mesh.
/// \throws SolverFailure when the linear solve of a flow step fails.
template <class TriangleMesh, class NamedParameters>
void take_skin_lengths(const geodesic::GeodesicPathSolver<TriangleMesh, NamedParameters>& solver,
                       const SkinLocator<TriangleMesh, NamedParameters>& at, const BodyFrame& frame,
                       const SkinLengthPlan<TriangleMesh>& plan, MeasurementSet& set) {
    // Every segment of every length is an independent two-point path: solve them all in one
    // batch (GeodesicPathSolver::paths runs them on TBB's threads; same results as one by one).
    using Solver = geodesic::GeodesicPathSolver<TriangleMesh, NamedParameters>;
    std::vector<typename Solver::PointPair> pairs;
    std::vector<std::vector<std::size_t>> segment_of(plan.lengths.size());  // pair index, or npos
    constexpr std::size_t none = static_cast<std::size_t>(-1);
    for (std::size_t k = 0; k < plan.lengths.size(); ++k) {
        const auto& w = plan.lengths[k].waypoints;
        for (std::size_t i = 0; i + 1 < w.size(); ++i) {
            const Vec3 a = at.canonical(w[i]), b = at.canonical(w[i + 1]);
            if (std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]) < 1e-9) {
                segment_of[k].push_back(none);  // two landmarks on one surface point: no walk
                continue;
            }
            segment_of[k].push_back(pairs.size());
            pairs.push_back({w[i], w[i + 1]});
        }
    }
    const auto paths = solver.paths(pairs);
    for (std::size_t k = 0; k < plan.lengths.size(); ++k) {
        const auto& s = plan.lengths[k];
        Measurement m;
        m.name = s.name;
        m.kind = MeasurementKind::length;
        m.landmarks = s.landmarks;
        double length = 0;
        std::string fail;
        for (const std::size_t j : segment_of[k]) {
            if (j == none) {
                continue;
            }
            const auto& r = paths[j];
            if (!r.on_mesh.found() || !std::isfinite(r.on_mesh.length)) {
                fail = "no path on the skin between its landmarks (on different mesh components)";
                break;
            }
            length += r.on_mesh.length * frame.scale;
            for (const auto& p : r.on_mesh.points) {
                const Vec3 c = frame.to_canonical(
                    {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
                if (m.points.empty() || c != m.points.back()) {
                    m.points.push_back(c);
                }
            }
        }
        if (!fail.empty()) {
            set.add_missing(s.name, s.name + ": " + fail);
            continue;
        }
        if (s.floor_drop > 0 && !m.points.empty()) {
            m.points.push_back({m.points.back()[0], 0.0, m.points.back()[2]});
        }
        m.value = length + s.floor_drop;
        apply_catalogue(m);
        set.add(std::move(m));
    }
    for (const auto& miss : plan.missing) {
        set.add_missing(miss.name, miss.reason);
    }
}

namespace internal {

/// Length of a polyline.
inline double polyline_length(const std::vector<Vec3>& p) {
    double l = 0;
    for (std::size_t i = 0; i + 1 < p.size(); ++i) {
        l += std::hypot(p[i + 1][0] - p[i][0], p[i + 1][1] - p[i][1], p[i + 1][2] - p[i][2]);
    }
    return l;
}

/// The taut tape under a sagittal outline: `arc` runs (z, y) from A down and back up to B, A and
/// B the highest points; the tape is the convex hull of the arc (and `extra` points the tape must
/// pass over) without its top edge A-B, from A to B. Empty when A or B is not on the hull.
inline std::vector<std::array<double, 2>> tape_under(
    const std::vector<std::array<double, 2>>& arc,
    const std::vector<std::array<double, 2>>& extra) {
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    std::vector<K::Point_2> in, hull;
    for (const auto* v : {&arc, &extra}) {
        for (const auto& q : *v) {
            in.emplace_back(q[0], q[1]);
        }
    }
    CGAL::convex_hull_2(in.begin(), in.end(), std::back_inserter(hull));  // counter-clockwise
    const K::Point_2 a(arc.front()[0], arc.front()[1]), b(arc.back()[0], arc.back()[1]);
    const auto ia = std::find(hull.begin(), hull.end(), a) - hull.begin();
    const auto ib = std::find(hull.begin(), hull.end(), b) - hull.begin();
    const auto n = static_cast<std::ptrdiff_t>(hull.size());
    if (ia == n || ib == n || ia == ib) {
        return {};
    }
    // Of the two hull chains from A to B, the one through the lowest hull point.
    std::ptrdiff_t low = 0;
    for (std::ptrdiff_t i = 1; i < n; ++i) {
        low = hull[i].y() < hull[low].y() ? i : low;
    }
    const bool forward = ((low - ia + n) % n) <= ((ib - ia + n) % n);
    std::vector<std::array<double, 2>> out;
    for (std::ptrdiff_t i = ia;; i = (i + (forward ? 1 : n - 1)) % n) {
        out.push_back({hull[i].x(), hull[i].y()});
        if (i == ib) {
            break;
        }
    }
    return out;
}

}  // namespace internal

/// Crotch length (cross seam): the tape from the waist at the front midline down through the
/// crotch and up to the waist at the back midline, held in the mid-sagittal plane (x = the crotch
/// point's x), taut: the convex hull of the body's outline in that plane below the waist, which
/// also passes over the hip tape's back point (the `hip_back` landmark), so it bridges the cleft
/// between the buttocks as a tailor's tape laid across them does. Split where it passes under the
/// crotch point (same z): cross_seam_front and cross_seam_back, whose sum is cross_seam.
/// Measurements that cannot be taken are added to `missing` with the reason.
///
/// \tparam TriangleMesh a model of `FaceListGraph`, every face a triangle.
/// \tparam NamedParameters a sequence of CGAL named parameters; accepted: `vertex_point_map`,
///         `geom_traits`.
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
void measure_cross_seam(const TriangleMesh& tm, const BodyFrame& frame, const LandmarkSet& lm,
                        MeasurementSet& set,
                        const NamedParameters& np = CGAL::parameters::default_values()) {
    const std::vector<std::string> names = {"cross_seam", "cross_seam_front", "cross_seam_back"};
    auto fail = [&](const std::string& why) {
        for (const auto& n : names) {
            set.add_missing(n, n + ": " + why);
        }
    };
    for (const char* n : {"crotch", "waist_front", "waist_back"}) {
        const Landmark* l = lm.find(n);
        if (!l || !l->available()) {
            fail(l ? l->reason : std::string(n) + ": unknown landmark");
            return;
        }
    }
    const Vec3 crotch = *lm.point("crotch"), wf = *lm.point("waist_front"),
               wb = *lm.point("waist_back");
    const double xc = crotch[0], yw = 0.5 * (wf[1] + wb[1]);

    // The section by the plane x = xc (input coordinates: rows[0] . p = xc / scale).
    using GeomTraits = typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type;
    using VertexPointMap =
        typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::const_type;
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    const VertexPointMap vpm =
        choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                         CGAL::get_const_property_map(CGAL::vertex_point, tm));
    const GeomTraits traits =
        choose_parameter<GeomTraits>(get_parameter(np, CGAL::internal_np::geom_traits));
    CGAL::Polygon_mesh_slicer<TriangleMesh, GeomTraits, VertexPointMap> slicer(tm, vpm, traits);
    const auto& r0 = frame.rows[0];
    std::vector<std::vector<typename GeomTraits::Point_3>> polylines;
    slicer(typename GeomTraits::Plane_3(r0[0], r0[1], r0[2], -xc / frame.scale),
           std::back_inserter(polylines));

    // The outline crossing the waist level nearest to both waist points; its arc below the waist.
    using P2 = std::array<double, 2>;  // (z, y)
    std::vector<P2> best_arc;
    double best = std::numeric_limits<double>::infinity();
    for (const auto& pl : polylines) {
        std::vector<P2> q;
        for (const auto& p : pl) {
            const Vec3 c = frame.to_canonical(
                {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
            q.push_back({c[2], c[1]});
        }
        if (q.size() < 4 || q.front() != q.back()) {
            continue;  // open polylines come from an open mesh (measure filled_input_mesh)
        }
        q.pop_back();
        const std::size_t n = q.size();
        // Crossings of y = yw: (edge index, z of the crossing).
        std::vector<std::pair<std::size_t, double>> cross;
        for (std::size_t i = 0; i < n; ++i) {
            const P2 &a = q[i], &b = q[(i + 1) % n];
            if ((a[1] >= yw) != (b[1] >= yw)) {
                const double t = (yw - a[1]) / (b[1] - a[1]);
                cross.push_back({i, a[0] + t * (b[0] - a[0])});
            }
        }
        if (cross.size() < 2) {
            continue;
        }
        auto nearest = [&](double z) {
            std::size_t k = 0;
            for (std::size_t j = 1; j < cross.size(); ++j) {
                k = std::abs(cross[j].second - z) < std::abs(cross[k].second - z) ? j : k;
            }
            return k;
        };
        const std::size_t kf = nearest(wf[2]), kb = nearest(wb[2]);
        const double off =
            std::max(std::abs(cross[kf].second - wf[2]), std::abs(cross[kb].second - wb[2]));
        if (kf == kb || off >= best) {
            continue;
        }
        // Two arcs between the crossings; the one below the waist holds the lowest point.
        auto arc_from = [&](std::size_t from, double zfrom, std::size_t to, double zto) {
            std::vector<P2> arc{{zfrom, yw}};
            for (std::size_t i = (from + 1) % n;; i = (i + 1) % n) {
                arc.push_back(q[i]);
                if (i == to) {
                    break;
                }
            }
            arc.push_back({zto, yw});
            return arc;
        };
        std::vector<P2> a1 =
            arc_from(cross[kf].first, cross[kf].second, cross[kb].first, cross[kb].second);
        std::vector<P2> a2 =
            arc_from(cross[kb].first, cross[kb].second, cross[kf].first, cross[kf].second);
        std::reverse(a2.begin(), a2.end());  // both from the front crossing to the back one
        auto lowest = [](const std::vector<P2>& a) {
            double y = std::numeric_limits<double>::infinity();
            for (const auto& p : a) {
                y = std::min(y, p[1]);
            }
            return y;
        };
        best = off;
        best_arc = lowest(a1) < lowest(a2) ? a1 : a2;
    }
    if (best_arc.empty() || best > 0.03 * frame.height) {
        fail(
            "the mid-sagittal section (x = the crotch point's) has no outline through the "
            "waist front and back points");
        return;
    }
    for (const auto& p : best_arc) {
        if (p[1] > yw + 1e-9) {
            fail("the mid-sagittal outline rises above the waist between the waist points");
            return;
        }
    }
    std::vector<P2> extra;
    if (const auto hip = lm.point("hip_back")) {
        extra.push_back({(*hip)[2], (*hip)[1]});
    }
    const std::vector<P2> tape = internal::tape_under(best_arc, extra);
    if (tape.size() < 2) {
        fail("the waist points are not on the taut tape of the mid-sagittal outline");
        return;
    }
    // Split under the crotch point: the lowest crossing of z = crotch z.
    std::size_t split = 0;
    P2 at{0, std::numeric_limits<double>::infinity()};
    for (std::size_t i = 0; i + 1 < tape.size(); ++i) {
        const P2 &a = tape[i], &b = tape[i + 1];
        if ((a[0] >= crotch[2]) != (b[0] >= crotch[2])) {
            const double t = (crotch[2] - a[0]) / (b[0] - a[0]);
            const double y = a[1] + t * (b[1] - a[1]);
            if (y < at[1]) {
                at = {crotch[2], y};
                split = i;
            }
        }
    }
    if (!std::isfinite(at[1])) {
        fail("the crotch point is not between the waist front and back");
        return;
    }
    auto to3 = [&](const P2& p) { return Vec3{xc, p[1], p[0]}; };
    std::vector<Vec3> front, back;
    for (std::size_t i = 0; i <= split; ++i) {
        front.push_back(to3(tape[i]));
    }
    front.push_back(to3(at));
    back.push_back(to3(at));
    for (std::size_t i = split + 1; i < tape.size(); ++i) {
        back.push_back(to3(tape[i]));
    }
    auto make = [&](const std::string& name, std::vector<Vec3> points) {
        Measurement m;
        m.name = name;
        m.kind = MeasurementKind::length;
        m.landmarks = {"crotch", "waist_front", "waist_back"};
        if (lm.point("hip_back")) {
            m.landmarks.push_back("hip_back");
        }
        m.value = internal::polyline_length(points);
        m.points = std::move(points);
        apply_catalogue(m);
        set.add(std::move(m));
    };
    std::vector<Vec3> all = front;
    all.insert(all.end(), back.begin() + 1, back.end());
    make("cross_seam", all);
    make("cross_seam_front", front);
    make("cross_seam_back", back);
}

/// One-shot: the lengths along the skin of a body mesh (the mesh measure_body measured, with its
/// frame and landmarks) added to `set`. Returns the wall-clock seconds it took.
///
/// \tparam TriangleMesh a model of `FaceListGraph`, `VertexListGraph` and `EdgeListGraph`
///         (CGAL::Surface_mesh, CGAL::Polyhedron_3, ...), every face a triangle.
/// \tparam NamedParameters a sequence of CGAL named parameters; accepted: `vertex_point_map`
///         (a `ReadablePropertyMap` vertex_descriptor -> `geom_traits::Point_3`),
///         `vertex_index_map` and `face_index_map` (`ReadablePropertyMap`s onto [0, n)),
///         `geom_traits` (a CGAL kernel).
/// \throws TopologyError when a face is not a triangle.
/// \throws InvalidInput on a non-finite coordinate, an index map that is not a bijection
///         onto [0, n), a mesh without faces or beyond 32-bit indices.
/// \throws SolverFailure when the linear solve of a flow step fails.
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
double measure_skin_lengths(const TriangleMesh& tm, const BodyFrame& frame,
                            const LandmarkSet& landmarks, MeasurementSet& set,
                            const NamedParameters& np = CGAL::parameters::default_values()) {
    const auto t0 = std::chrono::steady_clock::now();
    const SkinLocator<TriangleMesh, NamedParameters> at(tm, frame, np);
    const geodesic::GeodesicPathSolver<TriangleMesh, NamedParameters> solver(tm, np);
    take_skin_lengths(solver, at, frame, plan_skin_lengths(at, landmarks), set);
    measure_cross_seam(tm, frame, landmarks, set, np);
    measure_shoulder_slope(landmarks, set);
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// The body's mesh with its filled holes, back in the input's coordinates and unit (the vertices
/// and faces of the input first, in their order, then the patches').
inline CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>
filled_input_mesh(const Body& body) {
    using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
    using Mesh = CGAL::Surface_mesh<Point>;
    Mesh out;
    for (const auto& p : body.mesh.points) {
        const Vec3 q = body.frame.to_input(p);
        out.add_vertex(Point(q[0], q[1], q[2]));
    }
    for (const auto& t : body.mesh.triangles) {
        out.add_face(Mesh::Vertex_index(t[0]), Mesh::Vertex_index(t[1]), Mesh::Vertex_index(t[2]));
    }
    return out;
}

/// The lengths along the skin of a prepared body whose input mesh is `tm` (what make_body was
/// given): taken on `tm` when no hole was filled, else on the filled mesh (filled_input_mesh),
/// the lengths that cross a filled hole marked. Returns the wall-clock seconds.
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
double measure_skin_lengths(const Body& body, const TriangleMesh& tm, const LandmarkSet& landmarks,
                            MeasurementSet& set,
                            const NamedParameters& np = CGAL::parameters::default_values()) {
    if (body.holes.empty()) {
        return measure_skin_lengths(tm, body.frame, landmarks, set, np);
    }
    const auto t0 = std::chrono::steady_clock::now();
    const auto filled = filled_input_mesh(body);
    measure_skin_lengths(filled, body.frame, landmarks, set);
    mark_filled_crossings(body.mesh, set);
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace tapeline::measurement
