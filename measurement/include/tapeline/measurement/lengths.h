// Lengths along the skin between landmarks: shortest paths on the body mesh by the geodesic
// module's curvature flow (GeodesicPathSolver; see geodesic/README.md for the method), the way a
// tape laid on the skin measures a length.
//
// Every length is a chain of waypoints on the surface (landmarks snapped to their nearest surface
// point, or points found by casting a ray from inside the body, which hits the skin of the part
// the ray starts in first), joined by geodesic paths; leg lengths end at the ankle and add the
// ankle's height (the tape then hangs straight down to the floor). Definitions: measurement/README.
#pragma once

#include <tapeline/geodesic/curvature_flow.h>
#include <tapeline/geodesic/sources.h>
#include <tapeline/measurement/body_types.h>
#include <tapeline/measurement/measurement_types.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/locate.h>

#include <chrono>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace tapeline::measurement {

/// One length to take: its names and the surface points the path goes through, in order.
template <class TriangleMesh>
struct SkinLength {
    std::string name, iso_clause, freesewing;
    std::vector<std::string> landmarks;
    std::vector<geodesic::FaceLocation<TriangleMesh>> waypoints;
    double floor_drop = 0;  ///< mm added after the last waypoint: straight down to the floor
};

template <class TriangleMesh>
struct SkinLengthPlan {
    std::vector<SkinLength<TriangleMesh>> lengths;
    std::vector<MissingMeasurement> missing;
};

/// Finds surface points of a body mesh from canonical-frame queries (an AABB tree over its faces).
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
class SkinLocator {
public:
    using Location = geodesic::FaceLocation<TriangleMesh>;
    using GeomTraits = typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type;
    using VertexPointMap =
        typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::const_type;
    using Primitive = CGAL::AABB_face_graph_triangle_primitive<TriangleMesh, VertexPointMap>;
    using Tree = CGAL::AABB_tree<CGAL::AABB_traits<GeomTraits, Primitive>>;

    SkinLocator(const TriangleMesh& tm, const BodyFrame& frame,
                const NamedParameters& np = CGAL::parameters::default_values())
        : tm_(tm), frame_(frame), np_(np) {
        CGAL::Polygon_mesh_processing::build_AABB_tree(tm_, tree_, np_);
    }

    /// The surface point nearest to a canonical point.
    Location nearest(const Vec3& canonical) const {
        const Vec3 p = frame_.to_input(canonical);
        return CGAL::Polygon_mesh_processing::locate_with_AABB_tree(
            typename GeomTraits::Point_3(p[0], p[1], p[2]), tree_, tm_, np_);
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
    add({"shoulder_width_back", "back shoulder width", "shoulderToShoulder", {}, {}, 0},
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
        add({back ? "hps_to_waist_back" : "hps_to_waist_front",
             "",
             back ? "hpsToWaistBack" : "hpsToWaistFront",
             {},
             {},
             0},
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
        add({"shoulder_to_elbow", "upper arm length", "shoulderToElbow", {}, {}, 0}, {a, e},
            [&](auto& s) {
                s.waypoints = {at.nearest(P(a)), at.nearest(P(e))};
                return std::string();
            });
        add({"shoulder_to_wrist", "arm length", "shoulderToWrist", {}, {}, 0}, {a, e, w},
            [&](auto& s) {
                s.waypoints = {at.nearest(P(a)), at.nearest(P(e)), at.nearest(P(w))};
                return std::string();
            });
    }
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
        add({"inseam", "inside leg length", "inseam", {}, {}, 0}, {"crotch", ankle}, [&](auto& s) {
            s.waypoints.push_back(at.nearest(P("crotch")));
            return ankle_point(s, -out);
        });
        add({"outseam", "outside leg length", "waistToFloor", {}, {}, 0},
            {"waist_front", "waist_back", ankle}, [&](auto& s) {
                const std::string f =
                    hit(mid(P("waist_front"), P("waist_back")), {out, 0, 0}, s, "waist side");
                return f.empty() ? ankle_point(s, out) : f;
            });
    }
    // Along the side of the torso: waist to hip level, and armpit down to the waist (the side
    // points are where a ray from the torso's centre at that level leaves the skin sideways).
    {
        const std::string side = side_of({"armpit"});
        const double out = side == "right" ? -1.0 : 1.0;  // x is the body's left
        const std::string armpit = "armpit_" + side;
        auto waist_side = [&](SkinLength<TriangleMesh>& s) {
            return hit(mid(P("waist_front"), P("waist_back")), {out, 0, 0}, s, "waist side");
        };
        add({"waist_to_hips", "", "waistToHips", {}, {}, 0},
            {"waist_front", "waist_back", "hip_back"}, [&](auto& s) {
                const std::string f = waist_side(s);
                if (!f.empty())
                    return f;
                const Vec3 w = mid(P("waist_front"), P("waist_back"));
                return hit({w[0], P("hip_back")[1], w[2]}, {out, 0, 0}, s, "hip side");
            });
        add({"waist_to_armpit", "", "waistToArmpit", {}, {}, 0},
            {armpit, "waist_front", "waist_back"}, [&](auto& s) {
                s.waypoints.push_back(at.nearest(P(armpit)));
                return waist_side(s);
            });
    }
    return plan;
}

/// Takes every length of the plan with `solver` and adds it to `set` (value: the sum of the
/// on-mesh path lengths in mm plus the floor drop; points: the path, canonical mm). A segment
/// whose ends lie on different components of the mesh makes the length missing.
template <class TriangleMesh, class NamedParameters>
void take_skin_lengths(const geodesic::GeodesicPathSolver<TriangleMesh, NamedParameters>& solver,
                       const SkinLocator<TriangleMesh, NamedParameters>& at, const BodyFrame& frame,
                       const SkinLengthPlan<TriangleMesh>& plan, MeasurementSet& set) {
    for (const auto& s : plan.lengths) {
        Measurement m;
        m.name = s.name;
        m.kind = MeasurementKind::length;
        m.iso_clause = s.iso_clause;
        m.freesewing = s.freesewing;
        m.landmarks = s.landmarks;
        double length = 0;
        std::string fail;
        for (std::size_t i = 0; i + 1 < s.waypoints.size() && fail.empty(); ++i) {
            const Vec3 a = at.canonical(s.waypoints[i]), b = at.canonical(s.waypoints[i + 1]);
            if (std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]) < 1e-9) {
                continue;  // two landmarks on one surface point: nothing to walk
            }
            const auto r = solver.path(s.waypoints[i], s.waypoints[i + 1]);
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
        set.add(std::move(m));
    }
    for (const auto& miss : plan.missing) {
        set.add_missing(miss.name, miss.reason);
    }
}

/// One-shot: the lengths along the skin of a body mesh (the mesh measure_body measured, with its
/// frame and landmarks) added to `set`. Returns the wall-clock seconds it took.
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
double measure_skin_lengths(const TriangleMesh& tm, const BodyFrame& frame,
                            const LandmarkSet& landmarks, MeasurementSet& set,
                            const NamedParameters& np = CGAL::parameters::default_values()) {
    const auto t0 = std::chrono::steady_clock::now();
    const SkinLocator<TriangleMesh, NamedParameters> at(tm, frame, np);
    const geodesic::GeodesicPathSolver<TriangleMesh, NamedParameters> solver(tm, np);
    take_skin_lengths(solver, at, frame, plan_skin_lengths(at, landmarks), set);
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace tapeline::measurement
