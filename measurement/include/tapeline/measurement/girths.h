// Girths as a tailor's tape takes them: the plane section at the level, the section around the
// right body part (the one containing a seed point on the part's axis, so the torso and not the
// arms), its convex hull in the plane (the tape bridges hollows), and the hull's perimeter. Where
// the definition asks for the smallest or largest girth, the level is searched within a band
// (dense scan, then golden-section search). Limb girths are taken in planes perpendicular to the
// limb's axis, found from the centres of the limb landmarks' sections. Names and ISO 8559-1,
// FreeSewing and Seamly2D columns: the catalogue (tapeline/sizes/catalogue.h). Definitions:
// measurement/README.md.
#pragma once

#include <tapeline/measurement/body.h>
#include <tapeline/measurement/internal/search.h>
#include <tapeline/measurement/internal/sections.h>
#include <tapeline/measurement/measurement_types.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace tapeline::measurement {

namespace internal {

class GirthMeasurer {
public:
    GirthMeasurer(const Body& body, const LandmarkSet& landmarks, const MeasureOptions& options,
                  CutWorkspace& ws)
        : m_(body.mesh), L_(landmarks), options_(options), ws_(ws) {
        height_ = m_.max_y - m_.min_y;
        if (options_.smooth_surface) {
            normals_ = vertex_normals(m_.points, m_.triangles);
        }
    }

    MeasurementSet run() {
        stature();
        head();
        neck();
        neck_base();
        torso();
        for (int s = 0; s < 2; ++s) {
            legs(s);
            arms(s);
        }
        unsuffixed();
        return out_;
    }

private:
    struct Tape {
        double perimeter = std::numeric_limits<double>::infinity();
        double area = 0;
        std::vector<Vec3> loop;
        Plane plane;
        bool crosses_filled = false;
        Vec3 seed{0, 0, 0};   // the point tape() located the section by
        bool cut = false;     // made by tape(): record() takes it again on the smooth surface
        bool smooth = false;  // taken on the smooth surface
    };

    const BodyMesh& m_;
    const LandmarkSet& L_;
    MeasureOptions options_;
    CutWorkspace& ws_;
    std::vector<Vec3> normals_;  // vertex normals, for the smooth surface (phong.h)
    /// Points per crossed face on the smooth surface: 4 leave a 20 mm chord's sagitta 1/16.
    static constexpr int kSmoothSamples = 4;
    double height_ = 0;
    MeasurementSet out_;
    static constexpr double kInf = std::numeric_limits<double>::infinity();

    /// The first missing landmark among `names`, as a reason line for `what`.
    std::optional<std::string> missing(const std::string& what,
                                       const std::vector<std::string>& names) const {
        for (const auto& n : names) {
            const Landmark* l = L_.find(n);
            if (!l || !l->available()) {
                return what + ": needs landmark " + n + " (" + (l ? l->reason : "unknown") + ")";
            }
        }
        return std::nullopt;
    }
    Vec3 pt(const std::string& n) const { return L_.find(n)->point; }
    Vec3 axis_pt(const std::string& n) const { return L_.find(n)->axis_point; }

    /// Tape of the section containing (or nearest to) the seed; +inf perimeter when there is no
    /// section within 5% of the height of the seed. The section is found on the flat facets;
    /// with `smooth` (and MeasureOptions::smooth_surface) its tape goes round the smooth surface
    /// (smooth_points()). Searches compare flat tapes; record() takes the one it keeps again.
    Tape tape(const Plane& plane, const Vec3& seed, bool smooth = false) {
        Tape t;
        t.plane = plane;
        t.seed = seed;
        t.cut = true;
        PlaneSection ps = section(m_, plane, ws_);
        double d = 0;
        const int s = ps.locate(plane.to2(seed), &d);
        if (s < 0 || d > 0.05 * height_) {
            return t;
        }
        auto& sec = ps.sections[static_cast<std::size_t>(s)];
        if (smooth && options_.smooth_surface) {
            compute_tape(smooth_points(m_, normals_, ps, sec, kSmoothSamples), sec);
            t.smooth = true;
        }
        t.perimeter = sec.perimeter;
        t.area = sec.area;
        t.loop = ps.tape(static_cast<std::size_t>(s));
        t.crosses_filled = sec.crosses_filled;
        return t;
    }

    void record(const std::string& name, Tape t, const std::vector<std::string>& deps) {
        if (std::isfinite(t.perimeter) && t.cut && !t.smooth && options_.smooth_surface) {
            t = tape(t.plane, t.seed, true);
        }
        if (!std::isfinite(t.perimeter)) {
            out_.add_missing(name, name + ": no body section around the expected point");
            return;
        }
        Measurement m;
        m.name = name;
        m.kind = MeasurementKind::girth;
        m.value = t.perimeter;
        apply_catalogue(m);
        m.points = t.loop;
        m.closed = true;
        m.plane_point = t.plane.origin;
        m.plane_normal = t.plane.normal;
        m.landmarks = deps;
        m.crosses_filled_hole = t.crosses_filled;
        out_.add(std::move(m));
    }

    /// Along `dir` from `origin`: the tape at distance t, planes perpendicular to dir.
    std::function<Tape(double)> along(const Vec3& origin, const Vec3& dir,
                                      std::function<Vec3(double)> seed, const Vec3& u_hint) {
        return [this, origin, dir, seed, u_hint](double t) {
            const Vec3 o = add(origin, mul(dir, t));
            return tape(Plane::make(o, dir, u_hint), seed ? seed(t) : o);
        };
    }

    /// Smallest (largest) tape over t in [a, b]; tapes failing `accept` count as absent.
    Tape extreme(const std::function<Tape(double)>& f, double a, double b, bool largest,
                 const std::function<bool(const Tape&)>& accept = {}) {
        auto value = [&](double t) {
            const Tape tp = f(t);
            if (!std::isfinite(tp.perimeter) || (accept && !accept(tp))) {
                return kInf;
            }
            return largest ? -tp.perimeter : tp.perimeter;
        };
        const int samples = std::max(6, static_cast<int>((b - a) / (0.004 * height_)));
        const auto best = scan_minimum(value, a, b, samples, options_.level_tolerance);
        if (!std::isfinite(best.second)) {
            return Tape{};
        }
        return f(best.first);
    }

    /// Torso axis point at height y: through the crotch, the waist's middle and the neck's.
    Vec3 torso_seed(double y) const {
        std::vector<Vec3> axis;
        if (auto c = L_.point("crotch")) {
            axis.push_back(*c);
        }
        if (auto f = L_.point("waist_front"), b = L_.point("waist_back"); f && b) {
            axis.push_back(mul(add(*f, *b), 0.5));
        }
        if (auto f = L_.point("front_neck"), b = L_.point("cervicale"); f && b) {
            axis.push_back(mul(add(*f, *b), 0.5));
        }
        if (axis.empty()) {
            const Vec3 top = L_.find("top_of_head")->point;
            return {top[0], y, top[2]};
        }
        std::sort(axis.begin(), axis.end(),
                  [](const Vec3& a, const Vec3& b) { return a[1] < b[1]; });
        if (y <= axis.front()[1]) {
            return {axis.front()[0], y, axis.front()[2]};
        }
        for (std::size_t i = 0; i + 1 < axis.size(); ++i) {
            if (y <= axis[i + 1][1]) {
                const double s = (y - axis[i][1]) / std::max(1e-9, axis[i + 1][1] - axis[i][1]);
                const Vec3 p = add(axis[i], mul(sub(axis[i + 1], axis[i]), s));
                return {p[0], y, p[2]};
            }
        }
        return {axis.back()[0], y, axis.back()[2]};
    }

    Tape horizontal_torso(double y) { return tape(Plane::horizontal(y), torso_seed(y)); }

    void stature() {
        const Vec3 top = pt("top_of_head");
        Measurement m;
        m.name = "stature";
        m.kind = MeasurementKind::height;
        m.value = top[1] - m_.min_y;
        apply_catalogue(m);
        m.points = {{top[0], m_.min_y, top[2]}, top};
        m.landmarks = {"top_of_head"};
        out_.add(std::move(m));
    }

    void head() {
        const Vec3 top = pt("top_of_head");
        auto f = [&](double y) { return tape(Plane::horizontal(y), {top[0], y, top[2]}); };
        record("head_girth", extreme(f, top[1] - 0.075 * height_, top[1] - 0.02 * height_, true),
               {"top_of_head"});
    }

    void neck() {
        const std::vector<std::string> deps = {"side_neck_left", "side_neck_right", "top_of_head"};
        if (auto why = missing("neck_girth", deps)) {
            out_.add_missing("neck_girth", *why);
            return;
        }
        const Vec3 base = mul(add(pt("side_neck_left"), pt("side_neck_right")), 0.5);
        const Vec3 top = pt("top_of_head");
        const Vec3 dir = normalized(sub(top, base));
        const double len = dist(top, base);
        // Smallest girth over the level along the neck axis and the plane's forward tilt.
        auto at = [&](double t, double tilt) {
            const double c = std::cos(tilt), s = std::sin(tilt);
            // Rotate the axis direction about x (the lateral axis).
            const Vec3 n{dir[0], c * dir[1] - s * dir[2], s * dir[1] + c * dir[2]};
            const Vec3 o = add(base, mul(dir, t));
            return tape(Plane::make(o, n, {1, 0, 0}), o);
        };
        const double lo = 0.01 * height_, hi = 0.5 * len;
        const double max_tilt = options_.max_neck_tilt_degrees * M_PI / 180;
        auto best_level = [&](double tilt) {
            return extreme([&](double t) { return at(t, tilt); }, lo, hi, false);
        };
        auto tilt_value = [&](double tilt) { return best_level(tilt).perimeter; };
        const auto tb = max_tilt > 0 ? golden_minimum(tilt_value, -max_tilt, max_tilt, 0.01)
                                     : std::make_pair(0.0, 0.0);
        record("neck_girth", best_level(tb.first), deps);
    }

    /// The part of plane section tape `t` on `apex`'s side of the line through `l` and `r` (both
    /// in the tape's plane), cut where the tape crosses that line: appended to `arc` in order,
    /// its length returned (+inf when the tape does not cross the line).
    static double half_tape(const Tape& t, const Vec3& l, const Vec3& r, const Vec3& apex,
                            std::vector<Vec3>& arc) {
        const Vec3 d = sub(r, l);
        auto side = [&](const Vec3& x) { return dot(cross(d, sub(x, l)), t.plane.normal); };
        const double sa = side(apex) > 0 ? 1.0 : -1.0;
        const std::size_t k = t.loop.size();
        std::size_t start = k;  // a point on the far side, so the kept part is one run
        for (std::size_t i = 0; i < k && start == k; ++i) {
            if (sa * side(t.loop[i]) < 0) {
                start = i;
            }
        }
        if (start == k) {
            return kInf;
        }
        double len = 0;
        for (std::size_t m = 0; m < k; ++m) {
            const Vec3& a = t.loop[(start + m) % k];
            const Vec3& b = t.loop[(start + m + 1) % k];
            const double fa = sa * side(a), fb = sa * side(b);
            if (fa < 0 && fb < 0) {
                continue;
            }
            const Vec3 cut = fa < 0 || fb < 0 ? add(a, mul(sub(b, a), fa / (fa - fb))) : a;
            const Vec3 from = fa < 0 ? cut : a, to = fb < 0 ? cut : b;
            if (fa < 0) {
                arc.push_back(from);
            }
            arc.push_back(to);
            len += dist(from, to);
        }
        return len;
    }

    /// Neck base girth (ISO 8559-1 5.3.3, over the cervicale, the side neck points and the front
    /// neck point): behind the side neck points' line, the section by the plane through the
    /// cervicale and both side neck points; in front of it, the section by the plane through the
    /// front neck point and both side neck points; the two halves joined on that line. A single
    /// plane through the cervicale and the front neck point passes 20-40 mm under the side neck
    /// points and, on short, thick necks, over the slope of the shoulders: 1.12-1.63 times the
    /// neck girth over 132 MakeHuman bodies whose neck is not at the jaw, this tape 1.10-1.33.
    void neck_base() {
        const std::vector<std::string> deps = {"cervicale", "front_neck", "side_neck_left",
                                               "side_neck_right"};
        if (auto why = missing("neck_base_girth", deps)) {
            out_.add_missing("neck_base_girth", *why);
            return;
        }
        const Vec3 cv = pt("cervicale"), fn = pt("front_neck");
        const Vec3 l = pt("side_neck_left"), r = pt("side_neck_right");
        Tape t;
        Vec3 n = cross(sub(fn, cv), {1, 0, 0});
        if (n[1] < 0) {
            n = mul(n, -1);
        }
        const Vec3 o = mul(add(cv, fn), 0.5);
        t.plane = Plane::make(o, n, {1, 0, 0});  // the girth's reference plane, for the checks
        std::vector<Vec3> back, front;
        double len = 0;
        for (int h = 0; h < 2; ++h) {
            const Vec3& apex = h == 0 ? cv : fn;
            const Vec3 nn = normalized(cross(sub(r, l), sub(apex, l)));
            const Vec3 seed = mul(add(add(l, r), apex), 1.0 / 3.0);
            const Tape half = tape(Plane::make(seed, nn, {1, 0, 0}), seed, true);
            std::vector<Vec3>& arc = h == 0 ? back : front;
            len += std::isfinite(half.perimeter) ? half_tape(half, l, r, apex, arc) : kInf;
            t.crosses_filled = t.crosses_filled || half.crosses_filled;
        }
        if (!std::isfinite(len) || back.empty() || front.empty()) {
            out_.add_missing("neck_base_girth",
                             "neck_base_girth: no neck section through the side neck points");
            return;
        }
        if (dist(back.back(), front.front()) > dist(back.back(), front.back())) {
            std::reverse(front.begin(), front.end());
        }
        t.perimeter = len + dist(back.back(), front.front()) + dist(front.back(), back.front());
        t.loop = std::move(back);
        t.loop.insert(t.loop.end(), front.begin(), front.end());
        record("neck_base_girth", t, deps);
    }

    void torso() {
        auto fy = [&](double y) { return horizontal_torso(y); };
        // Bust: largest horizontal girth within 1% of the height of the bust points' level.
        if (auto why = missing("bust_girth", {"bust_left", "bust_right"})) {
            out_.add_missing("bust_girth", *why);
        } else {
            const double y = 0.5 * (pt("bust_left")[1] + pt("bust_right")[1]);
            record("bust_girth", extreme(fy, y - 0.01 * height_, y + 0.01 * height_, true),
                   {"bust_left", "bust_right"});
        }
        // High bust: horizontal, just under the lower armpit.
        if (auto why = missing("high_bust_girth", {"armpit_left", "armpit_right"})) {
            out_.add_missing("high_bust_girth", *why);
        } else {
            const double y =
                std::min(pt("armpit_left")[1], pt("armpit_right")[1]) - 0.005 * height_;
            record("high_bust_girth", fy(y), {"armpit_left", "armpit_right"});
        }
        underbust();
        if (auto why = missing("waist_girth", {"waist_front"})) {
            out_.add_missing("waist_girth", *why);
        } else {
            record("waist_girth", fy(pt("waist_front")[1]), {"waist_front"});
        }
        if (auto why = missing("high_hip_girth", {"waist_front", "hip_back"})) {
            out_.add_missing("high_hip_girth", *why);
        } else {
            record("high_hip_girth", fy(0.5 * (pt("waist_front")[1] + pt("hip_back")[1])),
                   {"waist_front", "hip_back"});
        }
        if (auto why = missing("hip_girth", {"hip_back", "crotch"})) {
            out_.add_missing("hip_girth", *why);
        } else {
            const double y = pt("hip_back")[1];
            const double lo = std::max(y - 0.02 * height_, pt("crotch")[1] + 0.005 * height_);
            record("hip_girth", extreme(fy, lo, y + 0.02 * height_, true), {"hip_back", "crotch"});
        }
    }

    /// Underbust level: on the vertical line through the bust point, the front point deepest
    /// behind the chord from the bust point to the waist's front (the fold under the breast).
    void underbust() {
        const std::vector<std::string> deps = {"bust_left", "bust_right", "waist_front"};
        if (auto why = missing("underbust_girth", deps)) {
            out_.add_missing("underbust_girth", *why);
            return;
        }
        const Vec3 bl = pt("bust_left"), br = pt("bust_right"), wf = pt("waist_front");
        const double x = bl[0];
        const double y1 = 0.5 * (bl[1] + br[1]), y0 = wf[1];
        const double z1 = bl[2];
        std::vector<std::pair<double, double>> contour;
        const double h = std::max(1.0, 0.002 * height_);
        for (double y = y1; y >= y0; y -= h) {
            const PlaneSection ps = section(m_, Plane::horizontal(y), ws_);
            const int s = ps.locate(Plane::horizontal(y).to2(torso_seed(y)));
            if (s < 0) {
                continue;
            }
            const auto fb = internal_front_back(ps, ps.sections[static_cast<std::size_t>(s)], x);
            if (fb) {
                contour.emplace_back(y, *fb);
            }
        }
        if (contour.size() < 3) {
            out_.add_missing("underbust_girth",
                             "underbust_girth: the front below the bust point "
                             "was not found");
            return;
        }
        const double z0 = contour.back().second;
        const double dy = y0 - y1, dz = z0 - z1, len = std::hypot(dy, dz);
        double best = -kInf, at = y1;
        for (const auto& [y, z] : contour) {
            const double d = ((y - y1) * dz - (z - z1) * dy) / len;
            const double behind = dy < 0 ? -d : d;
            if (behind > best) {
                best = behind;
                at = y;
            }
        }
        // A flat chest has no fold under it: ISO's "just below the breasts" is then just below
        // the chest's prominence, 2.5% of the height under the bust points.
        if (best < 0.002 * height_) {
            at = y1 - 0.025 * height_;
        }
        record("underbust_girth", horizontal_torso(at), deps);
    }

    static std::optional<double> internal_front_back(const PlaneSection& ps, const Section& s,
                                                     double x0) {
        double front = -kInf;
        for (std::size_t l : s.loops) {
            const auto& uv = ps.loops[l].uv;
            for (std::size_t i = 0, j = uv.size() - 1; i < uv.size(); j = i++) {
                if ((uv[j][0] >= x0) != (uv[i][0] >= x0)) {
                    const double t = (x0 - uv[j][0]) / (uv[i][0] - uv[j][0]);
                    front = std::max(front, -(uv[j][1] + t * (uv[i][1] - uv[j][1])));
                }
            }
        }
        return std::isfinite(front) ? std::optional<double>(front) : std::nullopt;
    }

    /// Accepts tapes whose area is at most `factor` times the reference tape's (a section that
    /// swallowed the torso or the other leg is several times larger than the limb's own).
    static std::function<bool(const Tape&)> area_limit(const Tape& reference, double factor) {
        const double limit = std::isfinite(reference.perimeter) ? factor * reference.area : kInf;
        return [limit](const Tape& t) { return t.area <= limit; };
    }

    void legs(int s) {
        const std::string side = s == 0 ? "_left" : "_right";
        const double sg = s == 0 ? 1 : -1;
        const std::string knee = "knee" + side, ankle = "ankle" + side;
        // Thigh top: centre of this leg's horizontal section 2% of the height below the crotch.
        std::optional<Vec3> thigh_top;
        if (!missing("", {"crotch", knee})) {
            const Vec3 crotch = pt("crotch");
            const double y = crotch[1] - 0.02 * height_;
            const Plane plane = Plane::horizontal(y);
            const PlaneSection ps = section(m_, plane, ws_);
            const Vec3 k = axis_pt(knee);
            const int sec = ps.locate(plane.to2({0.5 * (crotch[0] + k[0]), y, k[2]}));
            if (sec >= 0 &&
                sg * (ps.sections[static_cast<std::size_t>(sec)].centroid[0] - crotch[0]) > 0) {
                thigh_top = plane.to3(ps.sections[static_cast<std::size_t>(sec)].centroid);
            }
        }
        const Vec3 lateral{sg, 0, 0};
        if (auto why = missing("thigh_girth" + side, {"crotch", knee})) {
            out_.add_missing("thigh_girth" + side, *why);
            out_.add_missing("mid_thigh_girth" + side,
                             "mid_thigh_girth" + side + ": needs crotch and " + knee);
        } else if (!thigh_top) {
            out_.add_missing("thigh_girth" + side,
                             "thigh_girth" + side + ": the leg below the crotch was not found");
        } else {
            const Vec3 k = axis_pt(knee);
            const Vec3 dir = normalized(sub(k, *thigh_top));
            const double len = dist(k, *thigh_top);
            auto f = along(*thigh_top, dir, {}, lateral);
            const Tape ref = f(0.3 * len);
            record("thigh_girth" + side, extreme(f, 0, 0.3 * len, true, area_limit(ref, 1.8)),
                   {"crotch", knee});
            // Mid-thigh: the axis point halfway in height between crotch and knee.
            const double ymid = 0.5 * (pt("crotch")[1] + pt(knee)[1]);
            const double t = ((*thigh_top)[1] - ymid) / std::max(1e-9, -dir[1]);
            record("mid_thigh_girth" + side, f(t), {"crotch", knee});
        }
        if (auto why = missing("knee_girth" + side, {knee, ankle})) {
            out_.add_missing("knee_girth" + side, *why);
            out_.add_missing("calf_girth" + side,
                             "calf_girth" + side + ": needs " + knee + " and " + ankle);
            out_.add_missing("ankle_girth" + side,
                             "ankle_girth" + side + ": needs " + knee + " and " + ankle);
            return;
        }
        const Vec3 k = axis_pt(knee), a = axis_pt(ankle);
        const Vec3 shank = normalized(sub(a, k));
        const double len = dist(a, k);
        Vec3 knee_dir = shank;
        if (thigh_top) {
            knee_dir = normalized(add(shank, normalized(sub(k, *thigh_top))));
        }
        record("knee_girth" + side, tape(Plane::make(k, knee_dir, lateral), k), {knee, ankle});
        auto f = along(k, shank, {}, lateral);
        record("calf_girth" + side, extreme(f, 0.15 * len, 0.7 * len, true), {knee, ankle});
        record("ankle_girth" + side,
               extreme(f, len - 0.015 * height_, len + 0.015 * height_, false), {knee, ankle});
    }

    void arms(int s) {
        const std::string side = s == 0 ? "_left" : "_right";
        const std::string acromion = "acromion" + side, armpit = "armpit" + side;
        const std::string elbow = "elbow" + side, wrist = "wrist" + side;
        const std::vector<std::string> deps = {acromion, armpit, elbow, wrist};
        if (auto why = missing("upper_arm_girth" + side, deps)) {
            out_.add_missing("upper_arm_girth" + side, *why);
            out_.add_missing("elbow_girth" + side, "elbow_girth" + side + ": needs " + acromion +
                                                       ", " + armpit + ", " + elbow + ", " + wrist);
            out_.add_missing("wrist_girth" + side, "wrist_girth" + side + ": needs " + acromion +
                                                       ", " + armpit + ", " + elbow + ", " + wrist);
            return;
        }
        const Vec3 joint = mul(add(pt(acromion), pt(armpit)), 0.5);
        const Vec3 e = axis_pt(elbow), w = axis_pt(wrist);
        const Vec3 upper = normalized(sub(e, joint)), fore = normalized(sub(w, e));
        const double ulen = dist(e, joint), flen = dist(w, e);
        const Vec3 up{0, 1, 0};
        // Upper arm: midway between the armpit and the elbow, along the upper arm's axis.
        const double tm = 0.5 * (std::max(0.0, dot(sub(pt(armpit), joint), upper)) + ulen);
        record("upper_arm_girth" + side,
               tape(Plane::make(add(joint, mul(upper, tm)), upper, up), add(joint, mul(upper, tm))),
               deps);
        record("elbow_girth" + side, tape(Plane::make(e, normalized(add(upper, fore)), up), e),
               deps);
        auto ff = along(e, fore, {}, up);
        record(
            "wrist_girth" + side,
            extreme(ff, flen - 0.015 * height_, std::min(flen + 0.01 * height_, 1.2 * flen), false),
            deps);
    }

    /// The unsuffixed limb girths: the right side's, else the left's.
    void unsuffixed() {
        for (const char* base : {"thigh_girth", "mid_thigh_girth", "knee_girth", "calf_girth",
                                 "ankle_girth", "upper_arm_girth", "elbow_girth", "wrist_girth"}) {
            const std::string b = base;
            const Measurement* m = out_.find(b + "_right");
            if (!m) {
                m = out_.find(b + "_left");
            }
            if (!m) {
                out_.add_missing(b, b + ": not measured on either side");
                continue;
            }
            Measurement copy = *m;
            copy.name = b;
            apply_catalogue(copy);
            out_.add(std::move(copy));
        }
    }
};

}  // namespace internal

/// Girths of a body from its landmarks (see the top of this file). Girths whose landmarks are
/// missing are listed in MeasurementSet::missing with a reason; all others are produced.
/// Nothing is thrown for a missing girth: the mesh was checked when the Body was made
/// (make_body).
///
/// \param body the body, canonical mm.
/// \param landmarks its landmarks; girths use the available ones (found or overridden).
/// \param options MeasureOptions::level_tolerance and MeasureOptions::max_neck_tilt_degrees
///        are used.
/// \param sections_cut when not null, receives the number of plane sections cut.
inline MeasurementSet measure_girths(const Body& body, const LandmarkSet& landmarks,
                                     const MeasureOptions& options = {},
                                     std::size_t* sections_cut = nullptr) {
    internal::CutWorkspace ws;
    internal::GirthMeasurer g(body, landmarks, options, ws);
    MeasurementSet set = g.run();
    if (sections_cut) {
        *sections_cut = ws.cuts;
    }
    return set;
}

}  // namespace tapeline::measurement
