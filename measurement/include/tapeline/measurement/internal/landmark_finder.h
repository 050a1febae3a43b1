// Landmarks from the geometry of a closed body mesh in the canonical frame (no vertex ids).
//
// A stack of horizontal sections (every `scan_step` mm) is the backbone: the two leg sections are
// followed upwards until they merge (crotch), the merged torso section is followed to the top of
// the head, and every other section that merges into it on the way is an arm (armpit; in T-pose
// the arms are followed by sagittal planes instead, see find_t_pose_armpits). Levels
// found on the scan are refined by bisection or golden-section search on fresh sections. Arms
// are sampled by planes perpendicular to their axis (both poses). Definitions, with their ISO
// 8559-1 / ASTM D5219 terms, are in measurement/README.md.
#pragma once

#include <tapeline/measurement/internal/search.h>
#include <tapeline/measurement/internal/sections.h>
#include <tapeline/measurement/measurement_types.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

namespace tapeline::measurement::internal {

inline std::string mm(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.1f mm", v);
    return b;
}

/// Front (max z) and back (min z) of a horizontal section's loops on the line x = x0; nullopt
/// when the line misses them.
inline std::optional<std::pair<double, double>> front_back(const PlaneSection& ps, const Section& s,
                                                           double x0) {
    double front = -std::numeric_limits<double>::infinity(), back = -front;
    for (std::size_t l : s.loops) {
        const auto& uv = ps.loops[l].uv;
        for (std::size_t i = 0, j = uv.size() - 1; i < uv.size(); j = i++) {
            const Vec2& a = uv[j];
            const Vec2& b = uv[i];
            if ((a[0] >= x0) != (b[0] >= x0)) {
                const double t = (x0 - a[0]) / (b[0] - a[0]);
                const double z = -(a[1] + t * (b[1] - a[1]));  // w = -z on horizontal planes
                front = std::max(front, z);
                back = std::min(back, z);
            }
        }
    }
    if (!std::isfinite(front)) {
        return std::nullopt;
    }
    return std::make_pair(front, back);
}

/// Closest pair of loop vertices between two sections of one plane; returns their midpoint.
inline Vec3 gap_midpoint(const PlaneSection& ps, const Section& a, const Section& b) {
    double best = std::numeric_limits<double>::infinity();
    Vec3 mid{0, 0, 0};
    for (std::size_t la : a.loops) {
        for (std::size_t lb : b.loops) {
            for (const auto& p : ps.loops[la].points) {
                for (const auto& q : ps.loops[lb].points) {
                    const double d = dist(p, q);
                    if (d < best) {
                        best = d;
                        mid = mul(add(p, q), 0.5);
                    }
                }
            }
        }
    }
    return mid;
}

/// Breakpoint of the best two-segment fit to `pts` (t ascending): for each sample t_k with three
/// samples or more either side, the least-squares fit y = b0 + b1 t + b2 max(0, t - t_k) (a
/// continuous hinge at t_k); the t_k of the smallest residual, moved to the vertex of the parabola
/// through the residuals at it and its neighbours. Empty with fewer than 7 samples.
inline std::optional<double> hinge_breakpoint(const std::vector<std::pair<double, double>>& pts) {
    const std::size_t n = pts.size();
    if (n < 7) {
        return std::nullopt;
    }
    Eigen::MatrixXd A(n, 3);
    Eigen::VectorXd y(n);
    for (std::size_t i = 0; i < n; ++i) {
        A(static_cast<Eigen::Index>(i), 0) = 1;
        A(static_cast<Eigen::Index>(i), 1) = pts[i].first - pts.front().first;
        y(static_cast<Eigen::Index>(i)) = pts[i].second;
    }
    std::vector<double> sse(n, std::numeric_limits<double>::infinity());
    std::size_t best = 3;
    for (std::size_t k = 3; k + 3 < n; ++k) {
        for (std::size_t i = 0; i < n; ++i) {
            A(static_cast<Eigen::Index>(i), 2) = std::max(0.0, pts[i].first - pts[k].first);
        }
        const Eigen::Vector3d c = A.colPivHouseholderQr().solve(y);
        sse[k] = (A * c - y).squaredNorm();
        if (sse[k] < sse[best]) {
            best = k;
        }
    }
    double t = pts[best].first;
    const double y0 = sse[best - 1], y1 = sse[best], y2 = sse[best + 1];
    const double curvature = y0 - 2 * y1 + y2;
    if (std::isfinite(y0) && std::isfinite(y2) && curvature > 0) {
        const double u = std::clamp(0.5 * (y0 - y2) / curvature, -1.0, 1.0);
        t += u * (u < 0 ? pts[best].first - pts[best - 1].first
                        : pts[best + 1].first - pts[best].first);
    }
    return t;
}

/// A point of a limb profile: a section perpendicular to the limb's axis.
struct LimbSample {
    double t = 0;          // distance along the axis from its start
    double perimeter = 0;  // tape length; +inf where no section was found
    double area = 0;
    Vec3 centre{0, 0, 0};    // 3D centroid of the section's hull
    Vec3 outer{0, 0, 0};     // hull point farthest along the reference direction
    Vec3 front{0, 0, 0};     // hull point with the largest z
    Vec3 back{0, 0, 0};      // hull point with the smallest z
    std::vector<Vec3> hull;  // the tape, 3D
};

class LandmarkFinder {
public:
    /// `overrides`: canonical points that replace whatever the geometry gives (later steps use
    /// them too).
    LandmarkFinder(const BodyMesh& mesh, const MeasureOptions& options, Pose pose,
                   std::map<std::string, Vec3> overrides = {})
        : m_(mesh), options_(options), pose_(pose), overrides_(std::move(overrides)) {
        height_ = m_.max_y - m_.min_y;
        step_ = options_.scan_step > 0 ? options_.scan_step : height_ / 400.0;
    }

    LandmarkSet run() {
        scan();
        find_top();
        find_crotch();
        find_torso_and_armpits();
        find_waist_and_hips();
        find_neck();
        find_bust();
        find_acromions();
        find_arms();
        find_legs();
        for (const auto& [name, p] : overrides_) {
            if (Landmark* l = set_.find(name); l && l->status != LandmarkStatus::overridden) {
                set_found(name, p);
            }
        }
        return set_;
    }

    std::size_t cuts() const { return ws_.cuts; }
    /// The chin's underside (mm above the floor), when the front profile shows it.
    std::optional<double> chin_underside() const { return chin_y_; }
    const std::vector<std::string>& warnings() const { return warnings_; }

    // Profiles kept for diagnostics and tests.
    std::vector<LimbSample> arm_profile[2], leg_profile[2];

private:
    struct Level {
        double y = 0;
        PlaneSection ps;
        int torso = -1;
        int leg[2] = {-1, -1};
    };

    const BodyMesh& m_;
    MeasureOptions options_;
    Pose pose_;
    std::map<std::string, Vec3> overrides_;
    double height_ = 0, step_ = 0;
    CutWorkspace ws_;
    std::vector<Level> levels_;
    LandmarkSet set_;
    std::vector<std::string> warnings_;
    std::size_t crotch_level_ = 0;
    std::optional<double> crotch_y_, armpit_y_[2], waist_y_, hip_y_, neck_y_, snp_y_[2], chin_y_;
    std::optional<std::size_t> arm_merge_level_[2];
    int arm_section_[2] = {-1, -1};     // the arm's section at its merge level
    std::optional<Vec3> fingertip_[2];  // T-pose: the farthest point out on each side
    double x_mid_ = 0;

    /// Nipple level below the armpit on a chest without a prominence, as a fraction of the
    /// height: where the apexes lie on MakeHuman bodies (medians 0.037 H on women, 0.031 H on
    /// men over the 406 of 419 bodies, the bundled ones and nine random draws, that have one;
    /// 0.02-0.06 H between their 10th and 90th percentiles).
    static constexpr double kNippleDrop = 0.035;
    /// The nipple's usual distance off the midline, as a fraction of the torso's half-width
    /// there (the same bodies' bust points: median 0.45, 10th percentile 0.35): the inner edge of
    /// the band searched for a bust point on a level whose front is furthest forward on the
    /// midline.
    static constexpr double kNippleOffset = 0.35;
    /// How far from the nipple level (fraction of the height) a bust point without an apex may
    /// stay on a level of the profile: about the apexes' spread around their median (above).
    static constexpr double kNippleReach = 0.02;
    /// Waist level on a torso without a waist indentation, as a fraction of the way from the
    /// crotch to the armpit.
    static constexpr double kWaistFraction = 0.57;
    /// Highest waist, as a fraction of the way from the crotch to the armpit: about the lowest
    /// ribs. A narrowest girth above it is the fold under the chest over a belly, not a waist
    /// (the development population's narrowest girths: 0.50-0.65 on bodies without a belly,
    /// 0.72-0.78 with one, where MakeHuman's waist loop stays at 0.47-0.51).
    static constexpr double kWaistTop = 0.68;
    /// How far below the knee hollow's rearmost point (mm, in z) the leg's back outline still
    /// counts as the hollow (popliteal_hollow).
    static constexpr double kHollowDepth = 2.0;
    /// How far ahead of the midline's front (mm, in z) a level's most forward point off the
    /// midline must be to be a breast's or pectoral's apex (find_bust): a belly's front just off
    /// the midline is within scan noise of the midline's.
    static constexpr double kApexAhead = 2.0;

    static double side_sign(int s) { return s == 0 ? 1.0 : -1.0; }
    static const char* side_name(int s) { return s == 0 ? "left" : "right"; }
    double y_of(double fraction) const { return m_.min_y + fraction * height_; }

    PlaneSection horizontal(double y) { return section(m_, Plane::horizontal(y), ws_); }

    /// Records a found landmark, or its override; returns the point recorded.
    Vec3 set_found(const std::string& name, const Vec3& p, const Vec3* axis = nullptr) {
        Landmark* l = set_.find(name);
        const auto o = overrides_.find(name);
        l->status = o != overrides_.end() ? LandmarkStatus::overridden : LandmarkStatus::found;
        l->point = o != overrides_.end() ? o->second : p;
        l->axis_point = o != overrides_.end() || !axis ? l->point : *axis;
        l->reason.clear();
        return l->point;
    }
    void set_missing(const std::string& name, const std::string& why) {
        if (overrides_.count(name)) {
            set_found(name, overrides_.at(name));
            return;
        }
        Landmark* l = set_.find(name);
        l->status = LandmarkStatus::not_found;
        l->reason = name + ": " + why;
        warnings_.push_back(l->reason);
    }

    void scan() {
        const int n = static_cast<int>(std::floor(height_ / step_));
        levels_.reserve(static_cast<std::size_t>(n));
        for (int k = 0; k < n; ++k) {
            Level level;
            level.y = m_.min_y + (k + 0.5) * step_;
            level.ps = horizontal(level.y);
            levels_.push_back(std::move(level));
        }
        double lo = std::numeric_limits<double>::infinity(), hi = -lo;
        for (const auto& p : m_.points) {
            lo = std::min(lo, p[0]);
            hi = std::max(hi, p[0]);
        }
        x_mid_ = 0.5 * (lo + hi);
    }

    /// The section of level k+1 that continues section s of level k (contains its centroid, or is
    /// the nearest within a tenth of the height); -1 when none.
    int successor(std::size_t k, int s) const {
        if (k + 1 >= levels_.size() || s < 0) {
            return -1;
        }
        double d = 0;
        const int next = levels_[k + 1].ps.locate(
            levels_[k].ps.sections[static_cast<std::size_t>(s)].centroid, &d);
        return d <= 0.1 * height_ ? next : -1;
    }

    void find_top() {
        std::size_t best = 0;
        for (std::size_t v = 1; v < m_.points.size(); ++v) {
            if (m_.points[v][1] > m_.points[best][1]) {
                best = v;
            }
        }
        set_found("top_of_head", m_.points[best]);
    }

    void find_crotch() {
        std::size_t k0 = 0;
        while (k0 < levels_.size() && levels_[k0].y < y_of(0.02)) {
            ++k0;
        }
        if (k0 >= levels_.size() || levels_[k0].ps.sections.size() < 2) {
            set_missing("crotch", "the legs are not two separate sections at 2% of the height");
            return;
        }
        // The two largest sections near the floor are the feet.
        std::vector<int> order(levels_[k0].ps.sections.size());
        for (std::size_t i = 0; i < order.size(); ++i) {
            order[i] = static_cast<int>(i);
        }
        const auto& secs = levels_[k0].ps.sections;
        std::sort(order.begin(), order.end(),
                  [&secs](int a, int b) { return secs[a].perimeter > secs[b].perimeter; });
        int a = order[0], b = order[1];
        if (secs[a].centroid[0] < secs[b].centroid[0]) {
            std::swap(a, b);
        }
        levels_[k0].leg[0] = a;
        levels_[k0].leg[1] = b;
        for (std::size_t k = k0; k + 1 < levels_.size(); ++k) {
            const int l = successor(k, levels_[k].leg[0]);
            const int r = successor(k, levels_[k].leg[1]);
            if (l < 0 || r < 0) {
                set_missing("crotch", "a leg section was lost at " + mm(levels_[k].y));
                return;
            }
            if (l != r) {
                levels_[k + 1].leg[0] = l;
                levels_[k + 1].leg[1] = r;
                continue;
            }
            // Merged between levels k and k+1: bisect, following both legs from level k.
            Vec2 cl = levels_[k].ps.sections[static_cast<std::size_t>(levels_[k].leg[0])].centroid;
            Vec2 cr = levels_[k].ps.sections[static_cast<std::size_t>(levels_[k].leg[1])].centroid;
            auto merged = [&](double y) {
                const PlaneSection ps = horizontal(y);
                return ps.locate(cl) == ps.locate(cr);
            };
            const auto [lo, hi] =
                bisect(merged, levels_[k].y, levels_[k + 1].y, options_.level_tolerance);
            (void)hi;
            const PlaneSection ps = horizontal(lo);
            const int sl = ps.locate(cl), sr = ps.locate(cr);
            Vec3 p = sl >= 0 && sr >= 0 && sl != sr
                         ? gap_midpoint(ps, ps.sections[static_cast<std::size_t>(sl)],
                                        ps.sections[static_cast<std::size_t>(sr)])
                         : Vec3{0.5 * (cl[0] + cr[0]), lo, -0.5 * (cl[1] + cr[1])};
            p[1] = lo;
            // Front to back, the point is the middle of the two thighs' sections below the
            // merge (where the inside leg seams meet), not where the thighs first touch: the
            // contact is a ridge along which the first touching point slides with the triangles
            // (10-45 mm between a body and its re-meshed copy), and the cross seam is split
            // at this z.
            p[2] = -0.5 * (cl[1] + cr[1]);
            // Side to side likewise: the middle of the two thighs' centroids. The gap's midpoint
            // slides along the contact with the triangles (up to 8 mm between a body and its
            // re-meshed copy), and every midline landmark takes this x.
            p[0] = 0.5 * (cl[0] + cr[0]);
            crotch_y_ = set_found("crotch", p)[1];
            crotch_level_ = k + 1;
            levels_[k + 1].torso = l;
            x_mid_ = p[0];
            return;
        }
        set_missing("crotch", "the two leg sections never merge");
    }

    /// Follows section `sec` of level `k` down the scan while the section below holds its
    /// centroid (within 2 % of the height) and is neither the torso nor a leg, calling
    /// visit(section, index) on each; returns the lowest level reached.
    template <typename Visit>
    std::size_t follow_down(std::size_t k, int sec, Visit&& visit) const {
        while (sec >= 0) {
            const PlaneSection& ps = levels_[k].ps;
            visit(ps, static_cast<std::size_t>(sec));
            if (k == 0) {
                break;
            }
            double d = 0;
            const Vec2 c = ps.sections[static_cast<std::size_t>(sec)].centroid;
            const int below = levels_[k - 1].ps.locate(c, &d);
            if (below < 0 || below == levels_[k - 1].torso || d > 0.02 * height_ ||
                below == levels_[k - 1].leg[0] || below == levels_[k - 1].leg[1]) {
                break;
            }
            --k;
            sec = below;
        }
        return k;
    }

    void find_torso_and_armpits() {
        if (!crotch_y_) {
            for (int s = 0; s < 2; ++s) {
                set_missing(std::string("armpit_") + side_name(s), "needs the crotch");
            }
            return;
        }
        for (std::size_t k = crotch_level_; k + 1 < levels_.size(); ++k) {
            const int t = levels_[k].torso;
            int next = successor(k, t);
            if (next < 0) {
                // T-pose: once the arms join, the tape around torso and arms reaches the
                // forearms in front, and its centroid leaves the body; the section whose tape
                // still holds it is the torso.
                const Vec2 c = levels_[k].ps.sections[static_cast<std::size_t>(t)].centroid;
                const auto& secs = levels_[k + 1].ps.sections;
                for (std::size_t i = 0; i < secs.size() && next < 0; ++i) {
                    if (inside(secs[i].hull, c)) {
                        next = static_cast<int>(i);
                    }
                }
            }
            if (next < 0) {
                break;
            }
            levels_[k + 1].torso = next;
            const Vec2 tc = levels_[k].ps.sections[static_cast<std::size_t>(t)].centroid;
            for (std::size_t s = 0; s < levels_[k].ps.sections.size(); ++s) {
                if (static_cast<int>(s) == t || successor(k, static_cast<int>(s)) != next) {
                    continue;
                }
                const Vec2 sc = levels_[k].ps.sections[s].centroid;
                const int side = sc[0] > tc[0] ? 0 : 1;
                if (arm_merge_level_[side] || pose_ == Pose::t_pose) {
                    continue;
                }
                if (levels_[k].y < *crotch_y_ + 0.1 * height_) {
                    warnings_.push_back(std::string("a ") + side_name(side) +
                                        " section joins the torso at " + mm(levels_[k].y) +
                                        ", below the armpit band (hand touching the hip?)");
                    continue;
                }
                // An arm hangs at least a tenth of the height below where it joins the torso;
                // a shorter part joining it is the lower half of a hanging breast or a fold
                // (the breast's underside is cut apart from the chest below the crease).
                const std::size_t bottom =
                    follow_down(k, static_cast<int>(s), [](const PlaneSection&, std::size_t) {});
                if (levels_[k].y - levels_[bottom].y < 0.1 * height_) {
                    continue;
                }
                arm_merge_level_[side] = k;
                arm_section_[side] = static_cast<int>(s);
                refine_armpit(side, k, tc, sc);
            }
        }
        if (pose_ == Pose::t_pose) {
            find_t_pose_armpits();
            return;
        }
        for (int s = 0; s < 2; ++s) {
            if (!armpit_y_[s]) {
                set_missing(std::string("armpit_") + side_name(s),
                            "no arm section joins the torso above the crotch (arm fused to the "
                            "torso, or a T-pose arm level with the armpit)");
            }
        }
    }

    /// T-pose: a horizontal arm meets the horizontal scan all at once, so the arm is followed
    /// by sagittal planes (x = const, every scan step) from the forearm inwards instead. The
    /// lowest point of the arm's section runs along the arm's underside, then down the torso's
    /// side once the plane passes the junction; the armpit is the corner of that lower outline
    /// (the point farthest from the chord joining its ends), the highest point of the junction.
    /// The outline ends before it drops 10% of the height below the arm (where the torso's side
    /// joins the hips' section), before a drop of 3% of the height within one step, or where the
    /// section is lost.
    void find_t_pose_armpits() {
        for (int s = 0; s < 2; ++s) {
            const double sg = side_sign(s);
            const std::string name = std::string("armpit_") + side_name(s);
            std::size_t tip = 0;
            for (std::size_t v = 1; v < m_.points.size(); ++v) {
                if (sg * m_.points[v][0] > sg * m_.points[tip][0]) {
                    tip = v;
                }
            }
            fingertip_[s] = m_.points[tip];
            const double reach = sg * (m_.points[tip][0] - x_mid_);
            auto at = [&](double r) {
                return section(m_, Plane::make({x_mid_ + sg * r, 0, 0}, {1, 0, 0}, {0, 1, 0}), ws_);
            };
            // On these planes u = y and w = z. Start on the forearm, 60% of the way out, at the
            // section nearest the fingertip.
            PlaneSection ps = at(0.6 * reach);
            int arm = ps.locate({m_.points[tip][1], m_.points[tip][2]});
            std::vector<std::pair<double, Vec3>> lower;  // (r, lowest point of the arm)
            double start_y = 0;
            Vec2 arm_centroid{0, 0};  // of the arm's section on the previous plane
            for (double r = 0.6 * reach; arm >= 0 && r > step_; r -= step_) {
                if (!lower.empty()) {
                    arm_centroid = ps.sections[static_cast<std::size_t>(arm)].centroid;
                    double d = 0;
                    const PlaneSection next = at(r);
                    const int na =
                        next.locate(ps.sections[static_cast<std::size_t>(arm)].centroid, &d);
                    if (na < 0 || d > 0.02 * height_) {
                        break;
                    }
                    ps = next;
                    arm = na;
                }
                const Section& sec = ps.sections[static_cast<std::size_t>(arm)];
                Vec2 low = sec.hull.front();
                for (const auto& q : sec.hull) {
                    if (q[0] < low[0]) {
                        low = q;
                    }
                }
                if (lower.empty()) {
                    start_y = low[0];
                }
                const bool jump =
                    !lower.empty() && low[0] < lower.back().second[1] - 0.03 * height_;
                if (low[0] < start_y - 0.1 * height_ || jump) {
                    if (!lower.empty() && lower.back().second[1] > start_y - 0.03 * height_) {
                        // Dropped at once (the torso's side is steep, or the arm is a separate
                        // part overlapping the torso): the armpit is the arm's lowest point just
                        // before the plane reaches the torso's side.
                        const Vec2 ac = arm_centroid;
                        const double floor = lower.back().second[1] - 0.03 * height_;
                        auto lowest = [&](double rr) -> std::optional<Vec3> {
                            const PlaneSection q = at(rr);
                            const int a = q.locate(ac);
                            if (a < 0) {
                                return std::nullopt;
                            }
                            const Section& sa = q.sections[static_cast<std::size_t>(a)];
                            Vec2 l = sa.hull.front();
                            for (const auto& h : sa.hull) {
                                if (h[0] < l[0]) {
                                    l = h;
                                }
                            }
                            return q.plane.to3(l);
                        };
                        auto dropped = [&](double rr) {
                            const auto l = lowest(rr);
                            return !l || (*l)[1] < floor;
                        };
                        const double r_apart =
                            bisect(dropped, lower.back().first, r, options_.level_tolerance).first;
                        if (const auto l = lowest(r_apart)) {
                            lower.assign(1, {r_apart, *l});
                        }
                    }
                    break;
                }
                lower.emplace_back(r, ps.plane.to3(low));
            }
            if (lower.size() == 1) {  // dropped at once, see above
                armpit_y_[s] = set_found(name, lower.front().second)[1];
                continue;
            }
            if (lower.size() < 5 || lower.back().second[1] > start_y - 0.03 * height_) {
                set_missing(name,
                            "the T-pose arm's underside never turns down the torso's side "
                            "(sagittal sections from the forearm inwards)");
                continue;
            }
            const double r0 = lower.front().first, y0 = lower.front().second[1];
            const double dr = lower.back().first - r0, dy = lower.back().second[1] - y0;
            const double len = std::hypot(dr, dy);
            double best = -1;
            Vec3 p = lower.front().second;
            for (const auto& [r, q] : lower) {
                const double d = std::abs((r - r0) * dy - (q[1] - y0) * dr) / len;
                if (d > best) {
                    best = d;
                    p = q;
                }
            }
            armpit_y_[s] = set_found(name, p)[1];
        }
    }

    void refine_armpit(int side, std::size_t k, Vec2 tc, Vec2 sc) {
        auto merged = [&](double y) {
            const PlaneSection ps = horizontal(y);
            return ps.locate(tc) == ps.locate(sc);
        };
        const auto [lo, hi] =
            bisect(merged, levels_[k].y, levels_[k + 1].y, options_.level_tolerance);
        (void)hi;
        const PlaneSection ps = horizontal(lo);
        const int a = ps.locate(tc), b = ps.locate(sc);
        Vec3 p{sc[0], lo, -sc[1]};
        if (a >= 0 && b >= 0 && a != b) {
            p = gap_midpoint(ps, ps.sections[static_cast<std::size_t>(a)],
                             ps.sections[static_cast<std::size_t>(b)]);
        }
        p[1] = lo;
        armpit_y_[side] = set_found(std::string("armpit_") + side_name(side), p)[1];
    }

    /// Torso section at a height (fresh cut) located from the nearest scan level's torso.
    std::optional<std::pair<PlaneSection, int>> torso_at(double y) {
        const auto k = nearest_level(y);
        if (!k || levels_[*k].torso < 0) {
            return std::nullopt;
        }
        const Vec2 c =
            levels_[*k].ps.sections[static_cast<std::size_t>(levels_[*k].torso)].centroid;
        PlaneSection ps = horizontal(y);
        const int s = ps.locate(c);
        if (s < 0) {
            return std::nullopt;
        }
        return std::make_pair(std::move(ps), s);
    }

    /// Front and back z of the torso's fresh section at height y on the midline x = x_mid_.
    std::optional<std::pair<double, double>> midline_front_back(double y) {
        const auto t = torso_at(y);
        return t ? front_back(t->first, t->first.sections[static_cast<std::size_t>(t->second)],
                              x_mid_)
                 : std::nullopt;
    }

    std::optional<std::size_t> nearest_level(double y) const {
        if (levels_.empty()) {
            return std::nullopt;
        }
        const double k = std::round((y - m_.min_y) / step_ - 0.5);
        return static_cast<std::size_t>(
            std::clamp(k, 0.0, static_cast<double>(levels_.size() - 1)));
    }

    double armpit_level() const {
        if (armpit_y_[0] && armpit_y_[1]) {
            return std::min(*armpit_y_[0], *armpit_y_[1]);
        }
        if (armpit_y_[0] || armpit_y_[1]) {
            return armpit_y_[0] ? *armpit_y_[0] : *armpit_y_[1];
        }
        return *crotch_y_ + 0.27 * height_;  // typical proportions when no armpit was found
    }

    void find_waist_and_hips() {
        if (!crotch_y_) {
            set_missing("waist_front", "needs the crotch");
            set_missing("waist_back", "needs the crotch");
            set_missing("hip_back", "needs the crotch");
            return;
        }
        const double c = *crotch_y_, a = armpit_level();
        auto girth = [&](double y) {
            const auto t = torso_at(y);
            return t ? t->first.sections[static_cast<std::size_t>(t->second)].perimeter
                     : std::numeric_limits<double>::infinity();
        };
        const double lo = c + 0.3 * (a - c), hi = c + 0.85 * (a - c);
        const int samples = std::max(8, static_cast<int>((hi - lo) / step_));
        auto [wy, wg] = scan_minimum(girth, lo, hi, samples, options_.level_tolerance);
        // The narrowest girth above the lowest ribs (kWaistTop) is the fold under the chest:
        // the waist is then a narrowing below them, if there is one.
        double band_top = hi;
        if (std::isfinite(wg) && wy > c + kWaistTop * (a - c)) {
            band_top = c + kWaistTop * (a - c);
            const int n = std::max(8, static_cast<int>((band_top - lo) / step_));
            std::tie(wy, wg) = scan_minimum(girth, lo, band_top, n, options_.level_tolerance);
        }
        // No waist indentation (a belly or a straight torso): the smallest girth sits at an end
        // of the band searched. The waist is then at its usual place between crotch and armpit
        // (kWaistFraction of the way, the population's median where a waist is found).
        if (std::isfinite(wg) && (wy < lo + 2 * step_ || wy > band_top - 2 * step_)) {
            wy = c + kWaistFraction * (a - c);
            wg = girth(wy);
        }
        if (!std::isfinite(wg)) {
            set_missing("waist_front", "no torso section between crotch and armpits");
            set_missing("waist_back", "no torso section between crotch and armpits");
        } else {
            waist_y_ = wy;
            if (overrides_.count("waist_front")) {
                waist_y_ = overrides_.at("waist_front")[1];
            }
            const auto fb = midline_front_back(*waist_y_);
            if (fb) {
                set_found("waist_front", {x_mid_, *waist_y_, fb->first});
                set_found("waist_back", {x_mid_, *waist_y_, fb->second});
            } else {
                set_missing("waist_front", "the midline misses the waist section");
                set_missing("waist_back", "the midline misses the waist section");
            }
        }
        // Greatest buttock protrusion: the most posterior point of the torso's tape between the
        // crotch and the waist.
        const double top = waist_y_ ? *waist_y_ : c + 0.5 * (a - c);
        auto back = [&](double y) {
            const auto t = torso_at(y);
            if (!t) {
                return std::numeric_limits<double>::infinity();
            }
            const Section& s = t->first.sections[static_cast<std::size_t>(t->second)];
            return -s.hi[1];  // w = -z: the largest w is the most posterior point; minimise -w
        };
        const double b0 = c + 0.01 * height_;
        const int n = std::max(8, static_cast<int>((top - b0) / step_));
        const auto [hy, hv] = scan_minimum(back, b0, top, n, options_.level_tolerance);
        if (!std::isfinite(hv)) {
            set_missing("hip_back", "no torso section between crotch and waist");
            return;
        }
        hip_y_ = set_found("hip_back", {x_mid_, hy, hv})[1];
    }

    void find_neck() {
        // The neck: the smallest torso-chain section between the armpits and the head.
        const double a = crotch_y_ ? armpit_level() : y_of(0.73);
        const Vec3 top = set_.find("top_of_head")->point;
        const double lo = a + 0.04 * height_, hi = top[1] - 0.08 * height_;
        // The chin's underside, for the self-checks: going up, the first level where the front
        // midline comes forward by more than twice the levels' spacing (a nearly horizontal
        // surface). A short, thick neck can be as narrow as the jaw, and then the smallest
        // section below is the jaw's (neck_below_chin in self_checks.h).
        {
            const auto profile = front_profile(lo, hi);
            for (std::size_t i = 1; i < profile.size(); ++i) {
                const auto &prev = profile[i - 1], &q = profile[i];
                if (q.second - prev.second > 2 * (q.first - prev.first) &&
                    prev.first >= lo + 0.02 * height_) {
                    chin_y_ = prev.first;
                    break;
                }
            }
        }
        double best = std::numeric_limits<double>::infinity();
        std::size_t best_k = 0;
        for (std::size_t k = 0; k < levels_.size(); ++k) {
            if (levels_[k].y < lo || levels_[k].y > hi || levels_[k].torso < 0) {
                continue;
            }
            const double p =
                levels_[k].ps.sections[static_cast<std::size_t>(levels_[k].torso)].perimeter;
            if (p < best) {
                best = p;
                best_k = k;
            }
        }
        const char* names[] = {"side_neck_left", "side_neck_right", "cervicale", "front_neck"};
        if (!std::isfinite(best)) {
            for (const char* n : names) {
                set_missing(n, "no neck section found between the armpits and the head");
            }
            return;
        }
        neck_y_ = levels_[best_k].y;
        // Side neck point: going down from the neck, the first height y where the frontal
        // outline's chord over the `lag` below y slopes by more than 45 degrees (the lateral
        // extent grows by more than `lag`): the neck's side turns into the shoulder. The outline
        // bends smoothly there, so the test is only as steady as the chord is long: with a lag
        // of one scan step (0.25% of the height) the height moved by 3-4 mm between a body and
        // its retriangulated proxy, and the neck base girth, whose plane hangs on this height,
        // by 12-22 mm; over 2% of the height the chord averages out the triangles (0.3-0.8 mm,
        // girths within 1 mm; 1.25% left 1.2 mm and 4.5 mm). The scan brackets the switch,
        // bisection on fresh sections places it.
        const int lag_levels = std::max(1, static_cast<int>(std::lround(0.02 * height_ / step_)));
        const double lag = lag_levels * step_;
        for (int s = 0; s < 2; ++s) {
            const double sg = side_sign(s);
            auto lateral = [&](std::size_t k) {
                const Section& sec =
                    levels_[k].ps.sections[static_cast<std::size_t>(levels_[k].torso)];
                return sg > 0 ? sec.hi[0] : -sec.lo[0];
            };
            std::optional<std::size_t> found;
            const auto lagk = static_cast<std::size_t>(lag_levels);
            for (std::size_t k = best_k; k >= lagk && levels_[k - lagk].torso >= 0; --k) {
                if (levels_[k - lagk].y < a) {
                    break;
                }
                if (lateral(k - lagk) - lateral(k) > lag) {
                    found = k;  // the last level of the neck
                    break;
                }
            }
            const std::string name = std::string("side_neck_") + side_name(s);
            if (!found) {
                set_missing(name, "the neck outline never turns into a shoulder above the armpit");
                continue;
            }
            const Vec2 c = levels_[*found]
                               .ps.sections[static_cast<std::size_t>(levels_[*found].torso)]
                               .centroid;
            auto lateral_at = [&](double y) -> std::optional<std::pair<double, Vec3>> {
                const PlaneSection ps = horizontal(y);
                const int t = ps.locate(c);
                if (t < 0) {
                    return std::nullopt;
                }
                const Section& sec = ps.sections[static_cast<std::size_t>(t)];
                Vec2 best_q = sec.hull.front();
                for (const auto& q : sec.hull) {
                    if (sg * q[0] > sg * best_q[0]) {
                        best_q = q;
                    }
                }
                return std::make_pair(sg * best_q[0], ps.plane.to3(best_q));
            };
            auto turned = [&](double y) {
                const auto here = lateral_at(y), below = lateral_at(y - lag);
                return here && below && below->first - here->first > lag;
            };
            const double y_true = levels_[*found].y;
            const double y_false = *found + 1 < levels_.size() ? levels_[*found + 1].y : y_true;
            double y_snp = y_true;
            if (y_false > y_true && !turned(y_false) && turned(y_true)) {
                y_snp = bisect(turned, y_false, y_true, options_.level_tolerance).second;
            }
            // On a sharp corner (a flat shoulder meeting the neck: more than half of the window's
            // growth within one scan step) the chord's top sits up to `lag` above it; there the
            // point is the corner itself, where the outline has made half of that growth. On a
            // smooth turn (the MakeHuman bodies: a third at most), a point inside the window is
            // a level crossing of the outline, which moved by 2 mm between body and proxy, and
            // the girth by 10 mm: the chord's top stays.
            const auto top = lateral_at(y_snp), bottom = lateral_at(y_snp - lag);
            if (top && bottom) {
                const double growth = bottom->first - top->first;
                double jump = 0;
                for (double y = y_snp; y > y_snp - lag + 0.5 * step_; y -= step_) {
                    const auto a = lateral_at(y), b = lateral_at(y - step_);
                    if (a && b) {
                        jump = std::max(jump, b->first - a->first);
                    }
                }
                if (jump > 0.5 * growth) {
                    const double target = top->first + 0.5 * growth;
                    auto out = [&](double y) {
                        const auto l = lateral_at(y);
                        return l && l->first > target;
                    };
                    y_snp = bisect(out, y_snp, y_snp - lag, options_.level_tolerance).first;
                }
            }
            // The point itself: where the section's outline (its hull, the tape) crosses the
            // line through the section's centre towards the side, i.e. the side of the neck
            // midway front-back. The lateral extreme of a round neck section is flat in z: its z
            // moved by 6 mm between a body and its retriangulated proxy (and the back/front HPS
            // lengths with it); the centre's z is an average over the whole section.
            auto side_point = [&](double y) -> std::optional<Vec3> {
                const PlaneSection ps = horizontal(y);
                const int t = ps.locate(c);
                if (t < 0) {
                    return std::nullopt;
                }
                const Section& sec = ps.sections[static_cast<std::size_t>(t)];
                const Vec2 o = sec.centroid;
                std::optional<Vec2> best_q;
                const std::size_t n = sec.hull.size();
                for (std::size_t i = 0; i < n; ++i) {
                    const Vec2& p = sec.hull[i];
                    const Vec2& q = sec.hull[(i + 1) % n];
                    const double dp = p[1] - o[1], dq = q[1] - o[1];
                    if ((dp > 0) == (dq > 0) || dp == dq) {
                        continue;
                    }
                    const double t01 = dp / (dp - dq);
                    const Vec2 x{p[0] + t01 * (q[0] - p[0]), o[1]};
                    if (sg * (x[0] - o[0]) > 0 && (!best_q || sg * x[0] > sg * (*best_q)[0])) {
                        best_q = x;
                    }
                }
                if (!best_q) {
                    return std::nullopt;
                }
                return ps.plane.to3(*best_q);
            };
            const auto at = side_point(y_snp);
            if (!at) {
                set_missing(name, "the neck section was lost at the side neck point");
                continue;
            }
            snp_y_[s] = set_found(name, *at)[1];
        }
        // Cervicale: the back midline at the height of the side neck points.
        if (snp_y_[0] || snp_y_[1]) {
            const double y = snp_y_[0] && snp_y_[1] ? 0.5 * (*snp_y_[0] + *snp_y_[1])
                                                    : (snp_y_[0] ? *snp_y_[0] : *snp_y_[1]);
            const auto fb = midline_front_back(y);
            if (fb) {
                set_found("cervicale", {x_mid_, y, fb->second});
            } else {
                set_missing("cervicale", "the midline misses the section at the side neck points");
            }
        } else {
            set_missing("cervicale", "needs a side neck point");
        }
        find_front_neck(best_k);
    }

    /// The front midline's z on the torso chain's scan sections with heights in [lo, hi],
    /// going up: (y, front z).
    std::vector<std::pair<double, double>> front_profile(double lo, double hi) const {
        std::vector<std::pair<double, double>> out;
        for (std::size_t k = 0; k < levels_.size(); ++k) {
            if (levels_[k].y < lo || levels_[k].y > hi || levels_[k].torso < 0) {
                continue;
            }
            const auto fb = front_back(
                levels_[k].ps, levels_[k].ps.sections[static_cast<std::size_t>(levels_[k].torso)],
                x_mid_);
            if (fb) {
                out.emplace_back(levels_[k].y, fb->first);
            }
        }
        return out;
    }

    /// Front neck point (the jugular notch): on the front midline between the chest (18 % of the
    /// height below the neck level) and the neck level, the point deepest behind the chord from
    /// the chest's front to the neck's. The chord's lower end hangs on the neck, not on the
    /// armpits, which move with the arms (A- against T-pose: 4-10 mm). The depth is smoothed
    /// (Gaussian, sigma 0.5 % of the height) and its maximum placed between scan levels by a
    /// parabola: the profile there is often nearly straight (the raw depth flat within 0.2 mm
    /// over 25 mm), its raw maximum jumps a scan level (3.8 mm) or more between a body and its
    /// re-meshed copy, and the neck base girth with it. The point of largest bend of the profile
    /// (the maximum of z'') is no steadier: its peaks are several and it jumps between them (tens
    /// of mm) on re-meshed copies.
    void find_front_neck(std::size_t neck_k) {
        const double y0 = levels_[neck_k].y - 0.18 * height_;
        const std::vector<std::pair<double, double>> contour = front_profile(y0, levels_[neck_k].y);
        if (contour.size() < 5) {
            set_missing("front_neck", "the front midline between bust and neck was not found");
            return;
        }
        // Chord from the lowest (chest) to the highest (neck) sample; "behind" is -z.
        const auto p0 = contour.front(), p1 = contour.back();
        const double dy = p1.first - p0.first, dz = p1.second - p0.second;
        const double len = std::hypot(dy, dz);
        const std::size_t n = contour.size();
        std::vector<double> depth(n), smooth(n, 0.0);
        for (std::size_t i = 0; i < n; ++i) {
            const auto& q = contour[i];
            depth[i] = ((q.first - p0.first) * dz - (q.second - p0.second) * dy) / len;
        }
        const double sigma = 0.005 * height_;
        for (std::size_t i = 0; i < n; ++i) {
            double w_sum = 0;
            for (std::size_t j = 0; j < n; ++j) {
                const double u = (contour[j].first - contour[i].first) / sigma;
                if (std::abs(u) < 3) {
                    const double w = std::exp(-0.5 * u * u);
                    smooth[i] += w * depth[j];
                    w_sum += w;
                }
            }
            smooth[i] /= w_sum;
        }
        const auto best = static_cast<std::size_t>(std::max_element(smooth.begin(), smooth.end()) -
                                                   smooth.begin());
        double y = contour[best].first;
        if (best > 0 && best + 1 < n) {
            const double dm = smooth[best - 1], d0 = smooth[best], dp = smooth[best + 1];
            const double curv = dm - 2 * d0 + dp;
            if (curv < 0) {
                const double h = 0.5 * (contour[best + 1].first - contour[best - 1].first);
                y += h * 0.5 * (dm - dp) / curv;
            }
        }
        // A shelf: where the profile recedes by more than 2 mm per mm of height just below the
        // deepest sample (a flat shoulder top meeting the neck), the notch is the shelf's edge
        // itself, placed by bisection on fresh sections; smoothing would carry it up the neck
        // by up to 3 sigma. Smooth bodies' chests recede by at most 0.9 mm per mm there.
        const auto raw =
            static_cast<std::size_t>(std::max_element(depth.begin(), depth.end()) - depth.begin());
        if (raw > 0) {
            const auto &lo = contour[raw - 1], &hi = contour[raw];
            if (lo.second - hi.second > 2 * (hi.first - lo.first)) {
                const double mid = 0.5 * (lo.second + hi.second);
                auto receded = [&](double yy) {
                    const auto f = midline_front_back(yy);
                    return f && f->first < mid;
                };
                y = bisect(receded, lo.first, hi.first, options_.level_tolerance).second;
            }
        }
        const auto fb = midline_front_back(y);
        set_found("front_neck", {x_mid_, y, fb ? fb->first : contour[best].second});
    }

    /// Bust point: the chest's most prominent point at nipple level, from the torso's front
    /// profile between the armpit and the waist (the most forward section point 10-80% of the
    /// half-width off the midline, per scan level). The level is the highest local maximum of
    /// that profile (over 1.5% of the height each way) below the armpit: a breast's apex, or a
    /// flat chest's pectoral prominence; a belly further forward lower down is not the chest.
    /// A side with no prominence of its own (the profile only grows towards the belly) takes
    /// the other side's level; a chest with none, the level `kNippleDrop` of the height below
    /// the armpit.
    void find_bust() {
        if (!crotch_y_) {
            set_missing("bust_left", "needs the crotch");
            set_missing("bust_right", "needs the crotch");
            return;
        }
        const double a = armpit_level();
        const double w = waist_y_ ? *waist_y_ : *crotch_y_ + 0.6 * (a - *crotch_y_);
        const double lo = std::max(w, a - 0.12 * height_), hi = a;
        std::vector<std::pair<double, Vec3>> profiles[2];  // (y, most forward point), top down
        // The levels left out of a profile, with their most forward point kNippleOffset or more
        // of the half-width off the midline: a flat chest's nipple level may be among them.
        std::vector<std::pair<double, Vec3>> lateral[2];
        std::optional<std::size_t> apexes[2];
        for (int s = 0; s < 2; ++s) {
            const double sg = side_sign(s);
            std::vector<std::pair<double, Vec3>>& profile = profiles[s];
            std::vector<std::pair<double, Vec3>> midline_ahead;  // the levels left out below
            for (std::size_t k = levels_.size(); k-- > 0;) {
                if (levels_[k].y < lo || levels_[k].y > hi || levels_[k].torso < 0) {
                    continue;
                }
                const PlaneSection& ps = levels_[k].ps;
                const Section& sec = ps.sections[static_cast<std::size_t>(levels_[k].torso)];
                const double half = sg > 0 ? sec.hi[0] - x_mid_ : x_mid_ - sec.lo[0];
                double best = -std::numeric_limits<double>::infinity(), best_lateral = best;
                Vec3 at{0, 0, 0}, at_lateral{0, 0, 0};
                for (std::size_t l : sec.loops) {
                    for (const auto& p : ps.loops[l].points) {
                        const double off = sg * (p[0] - x_mid_);
                        if (off > 0.1 * half && off < 0.8 * half && p[2] > best) {
                            best = p[2];
                            at = p;
                        }
                        if (off > kNippleOffset * half && off < 0.8 * half && p[2] > best_lateral) {
                            best_lateral = p[2];
                            at_lateral = p;
                        }
                    }
                }
                // A level whose front is furthest forward on the midline (the sternum or a belly
                // below a heavy, low chest) has no breast or pectoral apex of its own: left out.
                // Its most forward point off the midline is the band's inner edge, and the front
                // growing towards such a belly below the nipples put the bust point 50-105 mm
                // under them on 5 of 209 bodies (the bust girth 63-97 mm short, 3 of them silent).
                // A chest ahead of its midline nowhere keeps every level.
                const auto fb = front_back(ps, sec, x_mid_);
                if (std::isfinite(best)) {
                    const bool ahead = fb && best <= fb->first + kApexAhead;
                    (ahead ? midline_ahead : profile).emplace_back(levels_[k].y, at);
                    if (ahead && std::isfinite(best_lateral)) {
                        lateral[s].emplace_back(levels_[k].y, at_lateral);
                    }
                }
            }
            if (profile.empty()) {
                profile.swap(midline_ahead);
                lateral[s].clear();
            }
            const std::string name = std::string("bust_") + side_name(s);
            if (profile.empty()) {
                set_missing(name, "no torso front found below the armpits");
                continue;
            }
            const double window = 0.015 * height_;
            std::optional<std::size_t> apex;
            for (std::size_t i = 0; i < profile.size() && !apex; ++i) {
                const double y = profile[i].first;
                if (y < lo + window || y > hi - 0.01 * height_) {
                    continue;
                }
                // A maximum with no level kept just below it, where the levels ahead on the
                // midline begin, is an apex only if the front there stays within kApexAhead of
                // it: a sternum as far forward as a flat chest's nipples (the apex 0-3 mm ahead
                // of the midline). A front coming further forward is a belly's (SMPL's male
                // average body: 7.7 mm within the window), and the maximum is where it was cut.
                bool peak = true, below = false;
                for (std::size_t j = 0; j < profile.size() && peak; ++j) {
                    peak = std::abs(profile[j].first - y) > window ||
                           profile[j].second[2] <= profile[i].second[2];
                    below = below || (profile[j].first < y && profile[j].first >= y - window);
                }
                if (peak && !below) {
                    double ahead = -std::numeric_limits<double>::infinity();
                    for (const auto& m : midline_ahead) {
                        if (m.first < y && m.first >= y - window) {
                            ahead = std::max(ahead, m.second[2]);
                        }
                    }
                    below = std::isfinite(ahead) && ahead <= profile[i].second[2] + kApexAhead;
                }
                if (peak && below) {
                    apex = i;
                }
            }
            apexes[s] = apex;
        }
        // A side without an apex of its own (a flat chest whose front grows towards a belly
        // below the pectorals: SMPL's male average body) takes the other side's level, else the
        // usual nipple level below the armpit. A profile that keeps only levels far below it (a
        // thin chest whose sternum is its front down to the lower ribs) put the bust point
        // 0.11 H under the armpit, on the lower ribs, when the profile's nearest level was taken
        // however far.
        for (int s = 0; s < 2; ++s) {
            const auto& profile = profiles[s];
            if (profile.empty()) {
                continue;
            }
            Vec3 point = profile.front().second;
            if (apexes[s]) {
                point = profile[*apexes[s]].second;
            } else {
                const auto& other = profiles[1 - s];
                const double y = apexes[1 - s] ? other[*apexes[1 - s]].first
                                               : std::max(lo, a - kNippleDrop * height_);
                // The profile's nearest level (its front off the midline: a pectoral's), unless
                // it is more than kNippleReach from there; then the nearest of all levels.
                double nearest = std::numeric_limits<double>::infinity();
                const auto& left_out = lateral[s];
                for (const auto* levels : {&profile, &left_out}) {
                    if (levels == &left_out && nearest <= kNippleReach * height_) {
                        break;
                    }
                    for (const auto& [ly, p] : *levels) {
                        if (std::abs(ly - y) < nearest) {
                            nearest = std::abs(ly - y);
                            point = p;
                        }
                    }
                }
            }
            set_found(std::string("bust_") + side_name(s), point);
        }
    }

    /// Acromion: corner of the upper outline between the side neck point and the arm, the point
    /// farthest from the chord joining them. The outline is the highest section point (below
    /// the side neck point) of sagittal planes x = const, every 0.25% of the height outwards.
    void find_acromions() {
        for (int s = 0; s < 2; ++s) {
            const double sg = side_sign(s);
            const std::string name = std::string("acromion_") + side_name(s);
            const auto snp = set_.point(std::string("side_neck_") + side_name(s));
            if (!snp) {
                set_missing(name, "needs the side neck point");
                continue;
            }
            double tip = -std::numeric_limits<double>::infinity();
            for (const auto& p : m_.points) {
                tip = std::max(tip, sg * p[0]);
            }
            const double r0 = sg * (*snp)[0];
            double r1 = r0 + 0.6 * (tip - r0);
            // A horizontal arm continues the shoulder's top: its outline has no corner of its own
            // out there, so the search stops 5% of the height beyond the armpit.
            const auto ap = set_.point(std::string("armpit_") + side_name(s));
            if (pose_ == Pose::t_pose && ap) {
                r1 = std::min(r1, sg * (*ap)[0] + 0.05 * height_);
            }
            const double cap = (*snp)[1] + 0.005 * height_;
            std::vector<Vec3> outline;
            for (double r = r0; r <= r1; r += 0.0025 * height_) {
                const Plane plane = Plane::make({sg * r, 0, 0}, {1, 0, 0}, {0, 1, 0});
                const Loop* top = nullptr;
                std::size_t at = 0;
                Vec3 best{0, -std::numeric_limits<double>::infinity(), 0};
                const auto loops = cut(m_, plane, ws_);
                for (const Loop& loop : loops) {
                    for (std::size_t k = 0; k < loop.points.size(); ++k) {
                        const Vec3& p = loop.points[k];
                        if (p[1] <= cap && p[1] > best[1]) {
                            best = p;
                            top = &loop;
                            at = k;
                        }
                    }
                }
                if (top) {
                    // A flat top (a level plateau of the loop) has no single highest point: take
                    // the middle of the stretch of the loop within 1e-4 of the height around it,
                    // so that mirror-image shoulders give mirror-image points.
                    const auto& q = top->points;
                    const std::size_t n = q.size();
                    const double level = best[1] - 1e-4 * height_;
                    double z0 = best[2], z1 = best[2];
                    for (const std::size_t step : {std::size_t{1}, n - 1}) {
                        for (std::size_t k = (at + step) % n, c = 1;
                             c < n && q[k][1] >= level && q[k][1] <= cap; k = (k + step) % n, ++c) {
                            z0 = std::min(z0, q[k][2]);
                            z1 = std::max(z1, q[k][2]);
                        }
                    }
                    best[2] = (z0 + z1) / 2;
                    outline.push_back(best);
                }
            }
            if (outline.size() < 5) {
                set_missing(name, "no shoulder outline beyond the side neck point");
                continue;
            }
            const Vec2 p0{sg * (*snp)[0], (*snp)[1]};
            // The lateral tip of the shoulder: where the outline turns down the arm, the corner
            // farthest from the chord joining the side neck point and the arm. On a round
            // shoulder the distance to the chord is flat around its maximum: the best sample
            // moved by one sample (4 mm out, 3 mm down) between a body and its retriangulated
            // proxy, and the back shoulder width by 11 mm. So the maximum is that of a parabola
            // fitted (least squares) to the distances of the samples within 3 of the best one,
            // and the point is interpolated on the outline there.
            const std::size_t last = outline.size() - 1;
            const std::size_t best = farthest_from_chord(outline, sg, 0, last, p0);
            Vec3 point = refine_on_outline(outline, sg, best, p0);
            // A skinned T-pose (SMPL's) has no corner at the shoulder's end: the arm's top
            // continues the shoulder's, and the only corner is where the neck meets the
            // shoulder, 50-60 mm beside the neck (shoulder points 0.10-0.13 of the stature
            // apart). A corner medial of the torso's side is that one; the point is then the
            // outline above the torso's side 5% of the height below the armpit: 1-27 mm from
            // the shoulder vertices SMPL-Anthropometry takes the shoulder breadth between, on
            // SMPL's and SMPL-X's average bodies (the neck's corner: 66-84 mm). Arms raised
            // from an A-pose keep their corner outside the torso's side.
            if (pose_ == Pose::t_pose && ap) {
                if (const auto side = torso_side((*ap)[1] - 0.05 * height_, sg);
                    side && sg * point[0] < *side) {
                    point = on_outline(outline, sg, *side, 0, outline.size() - 1).value_or(point);
                }
            }
            set_found(name, point);
        }
    }

    /// The torso chain's lateral extent (sg * x) on the scan level nearest height y.
    std::optional<double> torso_side(double y, double sg) const {
        const auto k = nearest_level(y);
        if (!k || levels_[*k].torso < 0) {
            return std::nullopt;
        }
        const Section& sec = levels_[*k].ps.sections[static_cast<std::size_t>(levels_[*k].torso)];
        return sg > 0 ? sec.hi[0] : -sec.lo[0];
    }

    /// The outline (x mirrored by sg, samples going outwards) interpolated at lateral position
    /// r between samples i0 and i1; none when r is outside them.
    static std::optional<Vec3> on_outline(const std::vector<Vec3>& outline, double sg, double r,
                                          std::size_t i0, std::size_t i1) {
        for (std::size_t i = i0; i < i1; ++i) {
            const double ta = sg * outline[i][0], tb = sg * outline[i + 1][0];
            if (r >= ta && r <= tb && tb > ta) {
                return add(outline[i], mul(sub(outline[i + 1], outline[i]), (r - ta) / (tb - ta)));
            }
        }
        return std::nullopt;
    }

    /// The outline point near outline[best] farthest from the chord from p0 to outline.back():
    /// vertex of the least-squares parabola through the chord distances of the samples within 3
    /// of `best` (by lateral position), clamped to them, interpolated linearly between samples.
    static Vec3 refine_on_outline(const std::vector<Vec3>& outline, double sg, std::size_t best,
                                  const Vec2& p0) {
        const std::size_t i1 = outline.size() - 1;
        const double dx = sg * outline[i1][0] - p0[0], dy = outline[i1][1] - p0[1];
        const double len = std::max(1e-9, std::hypot(dx, dy));
        auto dist = [&](const Vec3& q) {
            return std::abs((sg * q[0] - p0[0]) * dy - (q[1] - p0[1]) * dx) / len;
        };
        const std::size_t a = best >= 3 ? best - 3 : 0, b = std::min(i1, best + 3);
        if (b - a < 2) {
            return outline[best];
        }
        // Fit d = c0 + c1 t + c2 t^2, t = lateral position relative to the best sample.
        const double r0 = sg * outline[best][0];
        double s[5] = {0, 0, 0, 0, 0}, sd[3] = {0, 0, 0};
        for (std::size_t i = a; i <= b; ++i) {
            const double t = sg * outline[i][0] - r0, d = dist(outline[i]);
            double tp = 1;
            for (int k = 0; k < 5; ++k) {
                s[k] += tp;
                if (k < 3) {
                    sd[k] += tp * d;
                }
                tp *= t;
            }
        }
        // Normal equations [s0 s1 s2; s1 s2 s3; s2 s3 s4] c = sd, by Cramer's rule.
        auto det3 = [](double a11, double a12, double a13, double a21, double a22, double a23,
                       double a31, double a32, double a33) {
            return a11 * (a22 * a33 - a23 * a32) - a12 * (a21 * a33 - a23 * a31) +
                   a13 * (a21 * a32 - a22 * a31);
        };
        const double D = det3(s[0], s[1], s[2], s[1], s[2], s[3], s[2], s[3], s[4]);
        if (std::abs(D) < 1e-300) {
            return outline[best];
        }
        const double c1 = det3(s[0], sd[0], s[2], s[1], sd[1], s[3], s[2], sd[2], s[4]) / D;
        const double c2 = det3(s[0], s[1], sd[0], s[1], s[2], sd[1], s[2], s[3], sd[2]) / D;
        if (c2 >= 0) {
            return outline[best];  // no maximum: keep the best sample
        }
        const double lo = sg * outline[a][0] - r0, hi = sg * outline[b][0] - r0;
        const double tv = std::clamp(-c1 / (2 * c2), lo, hi);
        return on_outline(outline, sg, r0 + tv, a, b).value_or(outline[best]);
    }

    /// Index in [i0, i1] of the outline point (x mirrored by sg) farthest from the chord from p0
    /// to outline[i1].
    static std::size_t farthest_from_chord(const std::vector<Vec3>& outline, double sg,
                                           std::size_t i0, std::size_t i1, const Vec2& p0) {
        const double dx = sg * outline[i1][0] - p0[0], dy = outline[i1][1] - p0[1];
        const double len = std::max(1e-9, std::hypot(dx, dy));
        double best = -1;
        std::size_t at = i0;
        for (std::size_t i = i0; i <= i1; ++i) {
            const Vec3& q = outline[i];
            const double d = std::abs((sg * q[0] - p0[0]) * dy - (q[1] - p0[1]) * dx) / len;
            if (d > best) {
                best = d;
                at = i;
            }
        }
        return at;
    }

    /// The limb's section by the plane through `o` perpendicular to `dir` (unit), as sample `t`
    /// of a profile; `reference` picks the "outer" hull point (largest component along it).
    LimbSample limb_sample(const Vec3& o, const Vec3& dir, double t, const Vec3& reference) {
        LimbSample sample;
        sample.t = t;
        const Plane plane = Plane::make(o, dir, reference);
        const PlaneSection ps = section(m_, plane, ws_);
        double d = 0;
        const int s = ps.locate({0, 0}, &d);
        if (s < 0 || d > 0.05 * height_) {
            sample.perimeter = std::numeric_limits<double>::infinity();
            sample.centre = o;
            return sample;
        }
        const Section& sec = ps.sections[static_cast<std::size_t>(s)];
        sample.perimeter = sec.perimeter;
        sample.area = sec.area;
        sample.centre = plane.to3(sec.centroid);
        Vec2 outer = sec.hull.front(), front = sec.hull.front(), back = front;
        for (const auto& q : sec.hull) {
            if (q[0] > outer[0]) {
                outer = q;
            }
            if (plane.to3(q)[2] > plane.to3(front)[2]) {
                front = q;
            }
            if (plane.to3(q)[2] < plane.to3(back)[2]) {
                back = q;
            }
        }
        sample.outer = plane.to3(outer);
        sample.front = plane.to3(front);
        sample.back = plane.to3(back);
        sample.hull = ps.tape(static_cast<std::size_t>(s));
        return sample;
    }

    /// Calls f(start, unit direction, length, t0) on each segment of positive length of the
    /// polyline `axis` in order (t0: the distance along the polyline to its start) while f
    /// returns true.
    template <class F>
    static void for_each_segment(const std::vector<Vec3>& axis, F&& f) {
        double t0 = 0;
        for (std::size_t i = 0; i + 1 < axis.size(); ++i) {
            const Vec3 d = sub(axis[i + 1], axis[i]);
            const double len = norm(d);
            if (len <= 0) {
                continue;
            }
            if (!f(axis[i], mul(d, 1 / len), len, t0)) {
                return;
            }
            t0 += len;
        }
    }

    /// Samples a limb with planes perpendicular to the polyline `axis` every `h` mm; `reference`
    /// picks the "outer" hull point (largest component along it).
    std::vector<LimbSample> limb_profile(const std::vector<Vec3>& axis, double h,
                                         const Vec3& reference) {
        std::vector<LimbSample> out;
        for_each_segment(axis, [&](const Vec3& a, const Vec3& dir, double len, double t0) {
            for (double t = std::fmod(h - std::fmod(t0, h), h); t < len; t += h) {
                out.push_back(limb_sample(add(a, mul(dir, t)), dir, t0 + t, reference));
            }
            return true;
        });
        return out;
    }

    /// The sample of limb_profile(axis, ..., reference) at distance `t` along the polyline `axis`
    /// (clamped to its ends).
    LimbSample limb_sample_at(const std::vector<Vec3>& axis, double t, const Vec3& reference) {
        Vec3 start = axis.front(), dir{0, -1, 0};
        double length = 0, from = 0;
        for_each_segment(axis, [&](const Vec3& a, const Vec3& d, double len, double t0) {
            start = a;
            dir = d;
            length = len;
            from = t0;
            return t > t0 + len;
        });
        const double u = std::clamp(t - from, 0.0, length);
        return limb_sample(add(start, mul(dir, u)), dir, from + u, reference);
    }

    /// Arms: axis from the shoulder joint (between armpit and acromion) to the fingertip, sampled
    /// twice by perpendicular planes (the second time along the section centres of the first).
    void find_arms() {
        for (int s = 0; s < 2; ++s) {
            const std::string elbow = std::string("elbow_") + side_name(s);
            const std::string wrist = std::string("wrist_") + side_name(s);
            const auto ac = set_.point(std::string("acromion_") + side_name(s));
            const auto ap = set_.point(std::string("armpit_") + side_name(s));
            if (!ac || !ap) {
                set_missing(elbow, "needs the acromion and the armpit");
                set_missing(wrist, "needs the acromion and the armpit");
                continue;
            }
            // Fingertip: the point farthest from the shoulder joint among the arm's sections,
            // followed down the scan from the level where the arm joins the torso.
            const Vec3 joint = mul(add(*ac, *ap), 0.5);
            Vec3 fingertip = joint;
            if (arm_merge_level_[s]) {
                follow_down(*arm_merge_level_[s], arm_section_[s],
                            [&](const PlaneSection& ps, std::size_t sec) {
                                for (std::size_t l : ps.sections[sec].loops) {
                                    for (const auto& p : ps.loops[l].points) {
                                        if (dist(p, joint) > dist(fingertip, joint)) {
                                            fingertip = p;
                                        }
                                    }
                                }
                            });
            }
            if (fingertip_[s]) {
                fingertip = *fingertip_[s];
            }
            if (dist(fingertip, joint) < 0.1 * height_) {
                set_missing(elbow, "the arm below the armpit was not found");
                set_missing(wrist, "the arm below the armpit was not found");
                continue;
            }
            // Reference "outer" direction: perpendicular to the arm in the vertical plane, up.
            const Vec3 along = normalized(sub(fingertip, joint));
            Vec3 up = sub(Vec3{0, 1, 0}, mul(along, along[1]));
            up = norm(up) > 1e-6 ? normalized(up) : Vec3{0, 0, 1};
            const double h = std::max(1.0, height_ / 340);
            auto first = limb_profile({joint, fingertip}, h, up);
            std::vector<Vec3> axis;
            axis.push_back(joint);
            for (std::size_t i = 0; i < first.size(); i += 6) {
                if (std::isfinite(first[i].perimeter) &&
                    first[i].t > 0.2 * dist(joint, fingertip)) {
                    axis.push_back(first[i].centre);
                }
            }
            axis.push_back(fingertip);
            auto prof = limb_profile(axis, h, up);
            arm_profile[s] = prof;
            const double total = prof.empty() ? 0 : prof.back().t;
            // Elbow narrowing: the first local minimum (over 1% of the height each way) past 30%
            // of the way to the fingertip.
            std::size_t from = 0;
            while (from < prof.size() && prof[from].t < 0.3 * total) {
                ++from;
            }
            const auto em = local_extremum(prof, from, false, 0.01);
            // Wrist: the narrowest section where a hand of 0.07-0.15 of the height ends (the
            // hand, wrist to fingertip, is 0.108 of the height: Drillis & Contini 1966, in Winter
            // 2009, Fig. 4.1), before the palm's widest section (the thumb's root: the widest
            // section 0.03-0.12 of the height from the fingertip). The first narrowing after the
            // forearm's widest section, used before, lay in the palm on arms without a narrowing
            // at the elbow (the first narrowing past 30% is then the wrist, the next one in the
            // hand), and whether it did changed with the triangles: 50-75 mm between a body and
            // its re-meshed copy. That rule remains the fallback when no section is in the band.
            // The narrowest section lies on a minimum flat to a few mm over 20-30 mm of the arm:
            // the wrist point moved by up to 21 mm between a body and its re-meshed copy
            // (shoulder to wrist 13 mm). The wrist is the centroid of the band's sections less
            // than 4 % longer than the narrowest, weighted by how much less, on a fresh section
            // there: within 8.3 mm over 60 bodies never used to set it (the wrist girth, the
            // smallest around it, does not move), 17.5 mm (sd 4.8) nearer the shoulder than
            // MakeHuman's own wrist joint over the population (14.6, sd 5.7, the narrowest).
            std::optional<std::size_t> palm;
            for (std::size_t i = 0; i < prof.size(); ++i) {
                const double hand = total - prof[i].t;
                if (hand >= 0.03 * height_ && hand <= 0.12 * height_ &&
                    std::isfinite(prof[i].perimeter) &&
                    (!palm || prof[i].perimeter > prof[*palm].perimeter)) {
                    palm = i;
                }
            }
            std::vector<std::size_t> band;
            std::optional<std::size_t> wm;
            for (std::size_t i = 0; i < prof.size() && (!palm || i < *palm); ++i) {
                const double hand = total - prof[i].t;
                if (hand >= 0.07 * height_ && hand <= 0.15 * height_ &&
                    std::isfinite(prof[i].perimeter)) {
                    band.push_back(i);
                    if (!wm || prof[i].perimeter < prof[*wm].perimeter) {
                        wm = i;
                    }
                }
            }
            std::optional<LimbSample> ws;
            if (wm) {
                const double limit = 1.04 * prof[*wm].perimeter;
                double sw = 0, st = 0;
                for (std::size_t i : band) {
                    const double w = std::max(0.0, limit - prof[i].perimeter);
                    sw += w;
                    st += w * prof[i].t;
                }
                ws = prof[*wm];
                if (sw > 0) {
                    LimbSample at = limb_sample_at(axis, st / sw, up);
                    if (std::isfinite(at.perimeter)) {
                        ws = std::move(at);
                    }
                }
            } else if (em) {
                const auto fm = local_extremum(prof, *em, true, 0.01);
                wm = fm ? local_extremum(prof, *fm, false, 0.01) : std::nullopt;
                if (wm) {
                    ws = prof[*wm];
                }
            }
            if (!ws || ws->t > 0.95 * total) {
                set_missing(wrist, "no narrowing of the arm after the forearm");
            } else {
                set_found(wrist, ws->outer, &ws->centre);
            }
            if (!em) {
                set_missing(elbow, "no narrowing of the arm past 30% of the way to the fingertip");
                continue;
            }
            // Elbow: where the arm's centre line bends, when it bends by more than 1% of the
            // height (the largest distance of a section centre from the chord between the upper
            // arm, at 20% of the way, and the wrist); on a straight arm, the narrowing. The bend
            // is the breakpoint of the best two-segment fit to the centres' distances from the
            // chord along the arm (hinge_breakpoint): where the upper arm's and the forearm's
            // axes meet, on a fresh section. The farthest centre itself sits on a maximum flat
            // to 1-2 mm over 20-30 mm of arm: the elbow point moved by up to 34 mm between a
            // body and its re-meshed copy (5 mm edges or 5k vertices), by 4.8 mm at most with
            // the breakpoint over 60 bodies never used to set it, and lies along the arm 2.2 mm
            // (sd 9.7) from MakeHuman's own elbow joint over the population (the farthest
            // centre: 6.4, sd 12.2). The point is the olecranon: the section's point farthest out
            // on the convex side of the bend, away from the chord (on a straight arm, the back).
            std::size_t e = *em;
            Vec3 convex{0, 0, -1};
            LimbSample es = prof[e];
            if (ws) {
                std::size_t a = 0;
                while (a + 1 < prof.size() && prof[a].t < ws->t &&
                       (prof[a].t < 0.2 * total || !std::isfinite(prof[a].perimeter))) {
                    ++a;
                }
                const Vec3 ca = prof[a].centre, cw = ws->centre;
                const Vec3 chord = normalized(sub(cw, ca));
                double best = 0;
                std::size_t bend = e;
                std::vector<std::pair<double, double>> offsets;
                for (std::size_t i = a; i < prof.size() && prof[i].t < ws->t; ++i) {
                    const Vec3 d = sub(prof[i].centre, ca);
                    const double off = norm(sub(d, mul(chord, dot(d, chord))));
                    if (!std::isfinite(prof[i].perimeter)) {
                        continue;
                    }
                    offsets.emplace_back(prof[i].t, off);
                    if (off > best) {
                        best = off;
                        bend = i;
                    }
                }
                if (best > 0.01 * height_) {
                    es = prof[bend];
                    if (const auto tb = hinge_breakpoint(offsets)) {
                        LimbSample at = limb_sample_at(axis, *tb, up);
                        if (std::isfinite(at.perimeter)) {
                            es = std::move(at);
                        }
                    }
                    const Vec3 d = sub(es.centre, ca);
                    const Vec3 out = sub(d, mul(chord, dot(d, chord)));
                    if (norm(out) > 1e-3 * height_) {
                        convex = out;
                    }
                } else if (ws->t - prof[e].t < 0.10 * height_) {
                    // A straight arm whose first narrowing leaves a forearm shorter than 0.10 of
                    // the height (0.146 in Drillis & Contini 1966) found a dip of the forearm:
                    // the elbow is the narrowest section 0.11-0.20 of the height before the
                    // wrist.
                    std::optional<std::size_t> narrow;
                    for (std::size_t i = 0; i < prof.size() && prof[i].t < ws->t; ++i) {
                        const double fore = ws->t - prof[i].t;
                        if (fore >= 0.11 * height_ && fore <= 0.20 * height_ &&
                            std::isfinite(prof[i].perimeter) &&
                            (!narrow || prof[i].perimeter < prof[*narrow].perimeter)) {
                            narrow = i;
                        }
                    }
                    if (narrow) {
                        es = prof[*narrow];
                    }
                }
            }
            Vec3 olecranon = es.back;
            double far = -std::numeric_limits<double>::infinity();
            for (const auto& q : es.hull) {
                if (dot(sub(q, es.centre), convex) > far) {
                    far = dot(sub(q, es.centre), convex);
                    olecranon = q;
                }
            }
            set_found(elbow, olecranon, &es.centre);
        }
    }

    /// When sample `i` of `prof` has the largest (smallest) `key` of the samples within
    /// `window` mm of it along the limb: how many those samples are; otherwise none.
    template <class Key>
    static std::optional<std::size_t> extreme_within(const std::vector<LimbSample>& prof,
                                                     std::size_t i, double window, bool largest,
                                                     Key key) {
        std::size_t neighbours = 0;
        const double v = key(prof[i]);
        for (std::size_t j = 0; j < prof.size(); ++j) {
            if (j == i || std::abs(prof[j].t - prof[i].t) > window) {
                continue;
            }
            ++neighbours;
            if (largest ? key(prof[j]) > v : key(prof[j]) < v) {
                return std::nullopt;
            }
        }
        return neighbours;
    }

    /// First sample from `from` on that is the largest (smallest) girth within `window` times
    /// the height on both sides.
    std::optional<std::size_t> local_extremum(const std::vector<LimbSample>& prof, std::size_t from,
                                              bool largest, double window = 0.02) const {
        const auto perimeter = [](const LimbSample& s) { return s.perimeter; };
        for (std::size_t i = from; i < prof.size(); ++i) {
            const auto n = extreme_within(prof, i, window * height_, largest, perimeter);
            if (n && *n > 2 && prof.back().t - prof[i].t > window * height_) {
                return i;
            }
        }
        return std::nullopt;
    }

    /// The level of the knee's back hollow on a leg profile: the first sample at or above
    /// `from` (less one scan step) whose back z is the largest within 2 % of the height either
    /// way, below the crotch less 5 % of the height. The hollow is shallow (its back z within
    /// 3 mm over 30-50 mm of height on long legs): the level is the centroid of the samples in
    /// that window weighted by how far their back z is above the peak's less kHollowDepth. The
    /// peak sample itself, or a parabola through it, moved the knee girth by more than ISO
    /// 20685-1's 4 mm between a body and its re-meshed copy on 6 of 49 bodies; the centroid on
    /// none.
    std::optional<double> popliteal_hollow(const std::vector<LimbSample>& prof, double from) const {
        const double window = 0.02 * height_, top = *crotch_y_ - 0.05 * height_;
        for (std::size_t i = 0; i < prof.size(); ++i) {
            if (prof[i].t < from - step_) {
                continue;
            }
            if (prof[i].t + window > top) {
                break;
            }
            if (!extreme_within(prof, i, window, true,
                                [](const LimbSample& s) { return s.back[2]; })) {
                continue;
            }
            const double limit = prof[i].back[2] - kHollowDepth;
            double sw = 0, swy = 0;
            for (const auto& sample : prof) {
                if (std::abs(sample.t - prof[i].t) <= window) {
                    const double w = std::max(0.0, sample.back[2] - limit);
                    sw += w;
                    swy += w * sample.t;
                }
            }
            return swy / sw;
        }
        return std::nullopt;
    }

    /// Legs, on the horizontal scan: ankle = the lowest level between 2.5% and 12% of the height
    /// (above the foot) whose leg girth is within kAnkleGirthTolerance of the smallest there;
    /// knee = the hollow of the knee's back (popliteal_hollow) above the smallest leg girth
    /// between the calf (largest girth from the ankle to 35% of the height) and the crotch level
    /// minus 5% of the height.
    void find_legs() {
        for (int s = 0; s < 2; ++s) {
            const std::string knee = std::string("knee_") + side_name(s);
            const std::string ankle = std::string("ankle_") + side_name(s);
            if (!crotch_y_) {
                set_missing(knee, "needs the crotch (legs not separated)");
                set_missing(ankle, "needs the crotch (legs not separated)");
                continue;
            }
            std::vector<LimbSample> prof;
            for (std::size_t k = 0; k < crotch_level_; ++k) {
                const int l = levels_[k].leg[s];
                if (l < 0) {
                    continue;
                }
                const PlaneSection& ps = levels_[k].ps;
                const Section& sec = ps.sections[static_cast<std::size_t>(l)];
                LimbSample sample;
                sample.t = levels_[k].y;
                sample.perimeter = sec.perimeter;
                sample.area = sec.area;
                sample.centre = ps.plane.to3(sec.centroid);
                const double sg = side_sign(s);
                Vec2 outer = sec.hull.front(), front = sec.hull.front(), back = sec.hull.front();
                for (const auto& q : sec.hull) {
                    if (sg * q[0] > sg * outer[0]) {
                        outer = q;
                    }
                    if (q[1] < front[1]) {  // w = -z
                        front = q;
                    }
                    if (q[1] > back[1]) {
                        back = q;
                    }
                }
                sample.outer = ps.plane.to3(outer);
                sample.front = ps.plane.to3(front);
                sample.back = ps.plane.to3(back);
                prof.push_back(sample);
            }
            leg_profile[s] = prof;
            auto pick = [&prof](double a, double b, bool largest) {
                int best = -1;
                for (std::size_t i = 0; i < prof.size(); ++i) {
                    if (prof[i].t < a || prof[i].t > b) {
                        continue;
                    }
                    const double v = largest ? -prof[i].perimeter : prof[i].perimeter;
                    const double bv = best < 0  ? 0
                                      : largest ? -prof[static_cast<std::size_t>(best)].perimeter
                                                : prof[static_cast<std::size_t>(best)].perimeter;
                    if (best < 0 || v < bv) {
                        best = static_cast<int>(i);
                    }
                }
                return best;
            };
            int a = pick(y_of(0.025), y_of(0.12), false);
            if (a < 0) {
                set_missing(ankle, "no leg section between 2.5% and 12% of the height");
                set_missing(knee, "needs the ankle");
                continue;
            }
            // ISO 8559-1 takes the ankle girth just above the malleoli. A straight, slender shin
            // narrows by a few millimetres all the way up, and its smallest girth sat at 10-12 %
            // of the height, halfway to the calf, where the lower leg's tape is the same to the
            // standard's tolerance: the level is the lowest one that close to the smallest girth
            // (the malleoli's bulge below rises well past it).
            const double ankle_limit =
                prof[static_cast<std::size_t>(a)].perimeter + kAnkleGirthTolerance;
            for (std::size_t i = 0; i < static_cast<std::size_t>(a); ++i) {
                if (prof[i].t >= y_of(0.025) && prof[i].perimeter <= ankle_limit) {
                    a = static_cast<int>(i);
                    break;
                }
            }
            const LimbSample& as = prof[static_cast<std::size_t>(a)];
            set_found(ankle, as.outer, &as.centre);
            // Calf: the first local maximum above the ankle; knee: the first local minimum above
            // the calf (extrema over a window of 2% of the height each way).
            auto c = local_extremum(prof, static_cast<std::size_t>(a), true);
            auto k = c ? local_extremum(prof, *c, false) : std::nullopt;
            // A narrowing below a fifth of the height is the shin above a bump of the lower leg,
            // not the knee (0.285 of the height in Drillis & Contini; adult knees sit above 0.23):
            // go on to the next maximum and minimum up the leg.
            while (k && prof[*k].t < y_of(0.20)) {
                c = local_extremum(prof, *k + 1, true);
                k = c ? local_extremum(prof, *c, false) : std::nullopt;
            }
            if (!k || prof[*k].t > *crotch_y_ - 0.05 * height_) {
                // No narrowing of its own (a full calf running into the thigh): the narrowest
                // section where knees are, 0.24-0.33 of the height (0.285 in Drillis & Contini
                // 1966, in Winter 2009, Fig. 4.1).
                k.reset();
                for (std::size_t i = static_cast<std::size_t>(a); i < prof.size(); ++i) {
                    if (prof[i].t >= y_of(0.24) && prof[i].t <= y_of(0.33) &&
                        (!k || prof[i].perimeter < prof[*k].perimeter)) {
                        k = i;
                    }
                }
                if (!k) {
                    set_missing(knee, "no narrowing of the leg between the calf and the thigh");
                    continue;
                }
                if (!c || *c > *k) {
                    c = static_cast<std::size_t>(a);
                }
            }
            // The smallest girth is a flat minimum: its level moved by 8-9 mm between a body and
            // its retriangulated proxy (and the mid-thigh level, halfway up to the crotch, with
            // it). The knee level is the centroid of the narrowing instead: levels weighted by
            // how far their girth is below 3% above the minimum, which moves with the surface.
            // Only levels within 4 % of the height of the minimum count: a shin narrower than
            // the knee (the calf search then starts at the ankle) must not pull the knee down.
            const double limit = 1.03 * prof[*k].perimeter;
            double sw = 0, swy = 0;
            for (std::size_t i = *c; i < prof.size(); ++i) {
                if (prof[i].t > *crotch_y_ - 0.05 * height_) {
                    break;
                }
                if (std::abs(prof[i].t - prof[*k].t) > 0.04 * height_) {
                    continue;
                }
                const double w = std::max(0.0, limit - prof[i].perimeter);
                sw += w;
                swy += w * prof[i].t;
            }
            double y = sw > 0 ? swy / sw : prof[*k].t;
            // That narrowing is the shin just below the kneecap (the tibia's top): 40-140 mm
            // below MakeHuman's own knee loop on its bodies, and below 0.23 of the stature on
            // short legs. The knee joint is higher, at the hollow of the knee's back (popliteal
            // fossa), between the calf's and the thigh's bulges: the first local maximum of the
            // leg's back outline (its rearmost point's z, ±2 % of the height) going up from
            // the narrowing, at the centre of the hollow. A leg with no such hollow below the
            // thigh keeps the narrowing.
            if (const auto hollow = popliteal_hollow(prof, y); hollow) {
                y = *hollow;
            }
            const Plane plane = Plane::horizontal(y);
            const PlaneSection ps = horizontal(y);
            const int ls = ps.locate(plane.to2(prof[*k].centre));
            if (ls < 0) {
                set_found(knee, prof[*k].front, &prof[*k].centre);
                continue;
            }
            const Section& sec = ps.sections[static_cast<std::size_t>(ls)];
            Vec2 front = sec.hull.front();
            for (const auto& q : sec.hull) {
                if (q[1] < front[1]) {  // w = -z
                    front = q;
                }
            }
            const Vec3 centre = plane.to3(sec.centroid);
            set_found(knee, plane.to3(front), &centre);
        }
    }
};

}  // namespace tapeline::measurement::internal
