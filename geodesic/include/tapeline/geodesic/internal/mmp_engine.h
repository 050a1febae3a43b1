// Exact polyhedral distances by window propagation on edges, written from the papers:
//   J. S. B. Mitchell, D. M. Mount, C. H. Papadimitriou, "The discrete geodesic problem",
//   SIAM J. Computing 16(4), 1987 (continuous Dijkstra with windows on edges);
//   V. Surazhsky, T. Surazhsky, D. Kirsanov, S. Gortler, H. Hoppe, "Fast exact and approximate
//   geodesics on meshes", ACM TOG 24(3), 2005 (the practical form: windows with a pseudo-source,
//   priority by the window's minimum distance, trimming of overlapping windows);
// with the vertex-distance pruning idea of Y. Qin, X. Han, H. Yu, Y. Yu, J. Zhang, "Fast and
// exact discrete geodesic computation based on triangle-oriented wavefront propagation",
// ACM TOG 35(4), 2016 (a window whose every point is reached more cheaply through one of its
// edge's end vertices or the opposite corner is dropped), and a bucketed queue after the FWP of
// C. Xu, T. Y. Wang, Y.-J. Liu, L. Liu, Y. He, IEEE TVCG 21(7), 2015 (kept in exact order here).
// Our own addition: a halfedge is closed once the wavefront radius has passed all its values and
// none of its windows waits in the queue; later windows are rejected there, and without
// keep_windows its windows are freed, so memory follows the wavefront, not the whole field.
//
// No CGAL here: the engine works on a CompactMesh (mmp_mesh.h).
//
// A window lives on halfedge h and propagates into face(h): on h's frame (source of h at the
// origin, target at (L, 0), face(h) in y > 0) it covers [b0, b1] and its pseudo-source is the
// unfolded point (sx, sy), sy <= 0, at distance sigma from the real source: the distance at t is
// sigma + |(t, 0) - (sx, sy)|. Windows of one halfedge never overlap (trimming keeps, at every
// point, the window that is shorter there); saddle, border, non-manifold and degenerate vertices
// become pseudo-sources that emit windows into their whole one-ring.
//
// Robustness: tolerances are relative to the edge length (kLenTol) and to the distance
// (kDistTol); a new window only survives where it is shorter than what is already known by more
// than kDistTol, so equal windows (symmetric meshes) are not propagated twice and the propagation
// terminates; a hard cap on propagated windows turns a runaway into an error instead of a hang.
#pragma once

#include <tapeline/core/progress.h>
#include <tapeline/geodesic/internal/mmp_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

namespace tapeline::geodesic::internal::mmp {

constexpr double kInf = std::numeric_limits<double>::infinity();
/// Windows shorter than this fraction of their edge are dropped (a sliver that thin cannot hold a
/// vertex that its neighbours do not also reach, see kVertexTol).
constexpr double kLenTol = 1e-12;
/// A vertex counts as inside a window's cone if its ray crosses the edge within this fraction of
/// the edge length outside the window: the value is then short by O(kVertexTol^2) edge lengths.
constexpr double kVertexTol = 1e-9;
/// Relative margin: a window must be shorter by more than this to replace another one.
constexpr double kDistTol = 1e-12;
/// Propagated windows per progress update (one atomic add per batch, not per window).
constexpr std::size_t kProgressBatch = 4096;

struct Window {
    double b0, b1, sx, sy, sigma;
    std::uint32_t he;
    std::uint32_t gen;   ///< bumped on every change; queue entries carry it
    std::uint8_t state;  ///< kFree, kQueued, kDone
};
enum : std::uint8_t { kFree = 0, kQueued = 1, kDone = 2 };

inline double window_distance(const Window& w, double t) {
    const double dx = t - w.sx;
    return w.sigma + std::sqrt(dx * dx + w.sy * w.sy);
}
inline double window_min(const Window& w) {
    if (w.sx <= w.b0)
        return window_distance(w, w.b0);
    if (w.sx >= w.b1)
        return window_distance(w, w.b1);
    return w.sigma - w.sy;
}

struct FaceSource {
    std::uint32_t face;
    Vec2 p;  ///< in layout(face, 0)
};

class SolverAbort : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct EngineStats {
    std::size_t created = 0, propagated = 0, pruned = 0, peak = 0, emitted = 0;
    std::size_t peak_bytes = 0;
    double stopped_at = kInf;
};

struct QItem {
    double key;
    std::uint32_t id, gen;
    bool operator>(const QItem& o) const { return key > o.key; }
};

/// Monotone priority queue (keys pushed are never below the last key popped, up to round-off):
/// buckets of width `width` by key, only the current bucket is kept as a binary heap. Same order
/// as one big heap, with small heaps that stay in cache (after the bucketed wavefront of Xu et
/// al., "Fast wavefront propagation (FWP) for computing exact geodesic distances on meshes",
/// IEEE TVCG 21(7), 2015, but exact order within the bucket).
class BucketQueue {
public:
    explicit BucketQueue(double width) : inv_width_(width > 0 ? 1.0 / width : 1.0) {}

    void push(const QItem& q) {
        const std::size_t b = bucket_of(q.key);
        if (b <= current_) {
            // Into the bucket being processed: a small side heap (round-off may bring keys a
            // hair below the current one: they are simply taken next).
            side_.push_back(q);
            std::push_heap(side_.begin(), side_.end(), std::greater<QItem>());
        } else {
            if (b >= buckets_.size())
                buckets_.resize(b + 1);
            buckets_[b].push_back(q);
        }
        ++size_;
    }
    bool empty() const { return size_ == 0; }
    std::size_t size() const { return size_; }
    /// Smallest item; call only when !empty().
    QItem pop() {
        while (sorted_.empty() && side_.empty()) {
            ++current_;
            sorted_.swap(buckets_[current_]);
            std::vector<QItem>().swap(buckets_[current_]);
            // Sorted once, taken from the back: cheaper than heap pops on the whole bucket.
            std::sort(sorted_.begin(), sorted_.end(), std::greater<QItem>());
        }
        --size_;
        if (!side_.empty() && (sorted_.empty() || side_.front().key < sorted_.back().key)) {
            std::pop_heap(side_.begin(), side_.end(), std::greater<QItem>());
            const QItem q = side_.back();
            side_.pop_back();
            return q;
        }
        const QItem q = sorted_.back();
        sorted_.pop_back();
        return q;
    }

private:
    std::size_t bucket_of(double key) const {
        const double b = key * inv_width_;
        if (!(b < kMaxBuckets))
            return b >= 0 ? static_cast<std::size_t>(kMaxBuckets) : 0;
        return b > 0 ? static_cast<std::size_t>(b) : 0;
    }
    static constexpr double kMaxBuckets = 1 << 20;  // beyond: one last bucket
    double inv_width_;
    std::vector<std::vector<QItem>> buckets_ = std::vector<std::vector<QItem>>(1);
    std::vector<QItem> sorted_, side_;
    std::size_t current_ = 0;
    std::size_t size_ = 0;
};

/// One step of a back-traced path: a point on the surface, given by its 3D position.
struct TracePoint {
    std::array<double, 3> xyz;
};

class Engine {
public:
    /// keep_windows = false frees the windows of an edge once no later window can matter there
    /// (distances only: face-location queries and paths need the windows).
    Engine(const CompactMesh& m, double max_distance, bool prune, std::size_t max_propagated,
           bool keep_windows = true)
        : m_(m),
          keep_windows_(keep_windows),
          max_distance_(max_distance),
          prune_(prune),
          max_propagated_(max_propagated ? max_propagated : 4096 * m.corner.size() + 1000000),
          dist_(m.vertex_count(), kInf),
          emitted_(m.vertex_count(), kInf),
          source_vertex_(m.vertex_count(), 0),
          list_(m.corner.size()),
          closed_(m.corner.size(), 0),
          edge_key_(m.corner.size(), kInf),
          heap_(bucket_width(m)) {}

    void add_vertex_source(std::uint32_t v) {
        dist_[v] = 0;
        source_vertex_[v] = 1;
        push_vertex(v);
    }

    /// Point with barycentric coordinates b (corner order) in face f; b must be clean (no
    /// negative, sum 1, not a corner).
    void add_face_source(std::uint32_t f, const std::array<double, 3>& b) {
        const auto P = m_.layout(f, 0);
        const Vec2 p = b[0] * P[0] + b[1] * P[1] + b[2] * P[2];
        face_sources_.push_back({f, p});
        // A point on an edge is also a point of the neighbouring face. "On the edge" must be
        // emit_across's test (within kLenTol of the edge's length from its line), not b[k] == 0:
        // emit_across sends no window over an edge whose line holds the source, so a point just
        // inside (b[k] = 1e-14, the 1e-14 snap of the location check does not catch it) left the
        // neighbour to be reached only around the edge's ends (measured on a MakeHuman body:
        // 278.83 mm from such a point against 276.29 mm in the other direction and with CGAL).
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t h = 3 * f + (k + 1) % 3;  // opposite corner k
            const Vec2 ea = P[(k + 1) % 3], eb = P[(k + 2) % 3];
            const Vec2 d = eb - ea, r = p - ea;
            const double el = norm(d);
            if (b[k] != 0.0 && !(std::abs(d.x * r.y - d.y * r.x) <= 4 * kLenTol * el * el))
                continue;
            const std::uint32_t t = m_.twin[h];
            if (t == kNone)
                continue;
            const double s = b[(k + 2) % 3] / (b[(k + 1) % 3] + b[(k + 2) % 3]);  // along h
            const std::uint32_t g = t / 3;
            const int j = static_cast<int>(t % 3);
            const auto Q = m_.layout(g, 0);
            // t runs from corner j to j+1 of g, opposite to h: parameter 1 - s from its source.
            const Vec2 q = (s)*Q[j] + (1 - s) * Q[(j + 1) % 3];
            face_sources_.push_back({g, q});
        }
    }

    /// Propagates every window; `progress` (optional) is advanced per batch of propagated windows.
    void run(Progress* progress = nullptr) {
        // Seed the face sources.
        for (const auto& s : face_sources_) {
            const auto P = m_.layout(s.face, 0);
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t v = m_.corner[3 * s.face + k];
                relax(v, norm(s.p - P[k]));
                emit_across(s.face, k, s.p, 0.0, P);
            }
        }
        while (!heap_.empty()) {
            if (heap_.size() > heap_peak_)
                heap_peak_ = heap_.size();
            const QItem top = heap_.pop();
            if (top.key > stop_radius_) {
                stats_.stopped_at = stop_radius_;
                stopped_ = true;
                break;
            }
            if (!targets_.empty() && targets_final(top.key)) {
                stats_.stopped_at = top.key;
                stop_radius_ = top.key;
                stopped_ = true;
                break;
            }
            if (top.gen == kVertexEvent) {
                const std::uint32_t v = top.id;
                if (dist_[v] < emitted_[v] - kDistTol * dist_[v] || emitted_[v] == kInf)
                    emit_vertex(v);
                continue;
            }
            if (top.gen == kEdgeEvent) {
                double& pending = edge_key_[top.id];
                if (pending > top.key) {
                    heap_.push({pending, top.id, kEdgeEvent});
                    continue;
                }
                pending = kInf;
                try_close(top.id, top.key);
                continue;
            }
            Window& w = pool_[top.id];
            if (w.state != kQueued || w.gen != top.gen)
                continue;
            if (prune_ && dominated(w)) {
                ++stats_.pruned;
                unlink_and_free(top.id);
                continue;
            }
            w.state = kDone;
            if (++stats_.propagated > max_propagated_)
                throw SolverAbort("more than " + std::to_string(max_propagated_) +
                                  " windows propagated (runaway propagation)");
            if (progress && stats_.propagated % kProgressBatch == 0)
                progress->advance(kProgressBatch);
            propagate(top.id);
            // The edge may be settled once the wave has passed this window's farthest point;
            // one pending edge event per halfedge at a time.
            const Window& d = pool_[top.id];
            const double far = std::max(window_distance(d, d.b0), window_distance(d, d.b1));
            double& pending = edge_key_[d.he];
            if (pending == kInf) {
                pending = far;
                heap_.push({far, d.he, kEdgeEvent});
            } else {
                pending = std::max(pending, far);
            }
        }
        if (max_distance_ < kInf && !stopped_)
            stats_.stopped_at = std::min(stats_.stopped_at, max_distance_);
        update_peak();
    }

    void set_targets(std::vector<std::uint32_t> targets) { targets_ = std::move(targets); }
    void set_stop_radius(double r) { stop_radius_ = r; }

    /// Vertex distance, +infinity beyond the stop radius.
    double vertex_distance(std::uint32_t v) const {
        const double d = dist_[v];
        return d > output_radius() ? kInf : d;
    }
    const EngineStats& stats() const { return stats_; }
    std::size_t windows_alive() const { return alive_; }

    /// Exact distance at barycentric b of face f.
    double face_distance(std::uint32_t f, const std::array<double, 3>& b) const {
        const auto P = m_.layout(f, 0);
        const Vec2 q = b[0] * P[0] + b[1] * P[1] + b[2] * P[2];
        const Best best = best_in_face(f, P, q);
        return best.value > output_radius() ? kInf : best.value;
    }

    /// Path from the point at barycentric b of face f (or vertex v when f == kNone) back to the
    /// nearest source, as 3D points from the target to the source. Empty when unreachable.
    std::vector<TracePoint> trace(std::uint32_t f, const std::array<double, 3>& b,
                                  std::uint32_t v) const;

private:
    static constexpr std::uint32_t kVertexEvent = 0xffffffffu;
    static constexpr std::uint32_t kEdgeEvent = 0xfffffffeu;

    /// Bucket width of the queue: 1/16 of the mean edge length (measured on a 41k-vertex sphere:
    /// 2.6 s with one edge length, 2.1 s with 1/16; the current bucket's heap stays small).
    static double bucket_width(const CompactMesh& m) {
        double sum = 0;
        for (double l : m.len)
            sum += l;
        return m.len.empty() || !(sum > 0) ? 1.0 : sum / (16.0 * static_cast<double>(m.len.size()));
    }

    double output_radius() const { return std::min(stop_radius_, max_distance_); }

    /// All targets are final once the wave radius passes their distance (keys only grow and
    /// distances only shrink, so a target once final stays final: one cursor, amortised O(1)).
    bool targets_final(double key) {
        while (target_cursor_ < targets_.size() && dist_[targets_[target_cursor_]] <= key)
            ++target_cursor_;
        return target_cursor_ == targets_.size();
    }

    void push_vertex(std::uint32_t v) { heap_.push({dist_[v], v, kVertexEvent}); }

    /// Closes halfedge h when, at wave radius `radius`, every point of it is already reached at
    /// distance <= radius (by a window, or through an end vertex) and no window of it waits in
    /// the queue: every later window has all its values >= radius, so it cannot shorten anything
    /// there and is rejected on arrival. Without keep_windows the edge's windows are freed.
    void try_close(std::uint32_t h, double radius) {
        if (closed_[h])
            return;
        const double L = m_.len[h];
        const double dA = dist_[m_.corner[h]], dB = dist_[m_.corner[next_he(h)]];
        // Largest value of the vertex bound min(dA + t, dB + L - t) on [a, b] (concave).
        auto vertex_max = [&](double a, double b) {
            const double ts = std::clamp(0.5 * (dB + L - dA), a, b);
            return std::min(dA + ts, dB + L - ts);
        };
        const auto& list = list_[h];
        for (std::uint32_t id : list)
            if (pool_[id].state != kDone)
                return;
        double worst = 0, at = 0;
        for (std::uint32_t id : list) {
            const Window& w = pool_[id];
            if (w.b0 > at)
                worst = std::max(worst, vertex_max(at, w.b0));
            const double wmax = std::max(window_distance(w, w.b0), window_distance(w, w.b1));
            worst = std::max(worst, std::min(wmax, vertex_max(w.b0, w.b1)));
            at = std::max(at, w.b1);
        }
        if (at < L)
            worst = std::max(worst, vertex_max(at, L));
        if (!(worst <= radius)) {
            if (worst < kInf && edge_key_[h] == kInf) {
                edge_key_[h] = worst;
                heap_.push({worst, h, kEdgeEvent});
            }
            return;
        }
        closed_[h] = 1;
        if (keep_windows_)
            return;
        for (std::uint32_t id : list_[h])
            release(id);
        std::vector<std::uint32_t>().swap(list_[h]);
    }

    void relax(std::uint32_t v, double d) {
        if (d < dist_[v]) {
            dist_[v] = d;
            if ((m_.vflags[v] & kPseudoSource) &&
                (emitted_[v] == kInf || d < emitted_[v] - kDistTol * d))
                push_vertex(v);
        }
    }

    /// Window on the twin of halfedge 3f+k (i.e. into the neighbour across that edge) from the
    /// point p of face f's layout P, at distance sigma.
    void emit_across(std::uint32_t f, int k, Vec2 p, double sigma, const std::array<Vec2, 3>& P) {
        const std::uint32_t h = 3 * f + k;
        const std::uint32_t t = m_.twin[h];
        if (t == kNone || !(m_.len[h] > 0))
            return;
        // Twin frame: origin at corner k+1, x towards corner k, y away from f.
        const Vec2 o = P[(k + 1) % 3];
        Vec2 e = P[k] - o;
        const double l = norm(e);
        e = (1.0 / l) * e;
        const Vec2 n{-e.y, e.x};
        const Vec2 s = p - o;
        Window w{0.0, m_.len[t], dot(s, e), dot(s, n), sigma, t, 0, kQueued};
        if (!(w.sy < -kLenTol * m_.len[t]))
            return;  // p on the edge line: its rays never enter the neighbour
        insert(w);
    }

    void emit_vertex(std::uint32_t v) {
        emitted_[v] = dist_[v];
        ++stats_.emitted;
        const double d = dist_[v];
        for (std::uint32_t i = m_.vstart[v]; i < m_.vstart[v + 1]; ++i) {
            const std::uint32_t c = m_.vcorners[i];
            const std::uint32_t f = c / 3;
            const int k = static_cast<int>(c % 3);
            relax(m_.corner[3 * f + (k + 1) % 3], d + m_.len[c]);
            relax(m_.corner[3 * f + (k + 2) % 3], d + m_.len[3 * f + (k + 2) % 3]);
            const auto P = m_.layout(f, 0);
            emit_across(f, (k + 1) % 3, P[k], d, P);
        }
    }

    // --- windows -----------------------------------------------------------------------------

    std::uint32_t allocate(const Window& w) {
        std::uint32_t id;
        if (!free_.empty()) {
            id = free_.back();
            free_.pop_back();
            const std::uint32_t gen = (pool_[id].gen + 1) & 0x7fffffffu;
            pool_[id] = w;
            pool_[id].gen = gen;
        } else {
            id = static_cast<std::uint32_t>(pool_.size());
            if (id >= 0x7fffffffu)
                throw SolverAbort("window pool exhausted (2^31 windows)");
            pool_.push_back(w);
            pool_[id].gen = 0;
        }
        ++alive_;
        if (alive_ > stats_.peak)
            stats_.peak = alive_;
        return id;
    }

    void release(std::uint32_t id) {
        pool_[id].state = kFree;
        pool_[id].gen = (pool_[id].gen + 1) & 0x7fffffffu;
        free_.push_back(id);
        --alive_;
    }

    void unlink_and_free(std::uint32_t id) {
        const std::uint32_t h = pool_[id].he;
        auto& list = list_[h];
        list.erase(std::find(list.begin(), list.end(), id));
        release(id);
    }

    void enqueue(std::uint32_t id) {
        Window& w = pool_[id];
        heap_.push({window_min(w), id, w.gen});
    }

    /// True when every point of w is reached more cheaply (by a margin) through A or B, the end
    /// vertices of its edge (exact test: dW(t) - t and dW(t) + t are monotone), or through C, the
    /// opposite corner of the face it enters (conservative: min of dW against the largest |C - P|
    /// over the window, |C - P| being convex). Every path continuing w crosses the window, so it
    /// is dominated too, and w can be dropped. (Splitting the window into 2 or 4 pieces for mixed
    /// A/B/C domination pruned nothing more on the test meshes and cost 10 % of the time.)
    bool dominated(const Window& w) const {
        const double L = m_.len[w.he];
        const double dA = dist_[m_.corner[w.he]], dB = dist_[m_.corner[next_he(w.he)]];
        const double dC = dist_[m_.corner[prev_he(w.he)]];
        if (dA < kInf || dB < kInf) {
            double t;
            if (dA == kInf)
                t = w.b0;
            else if (dB == kInf)
                t = w.b1;
            else
                t = std::clamp(0.5 * (dB + L - dA), w.b0, w.b1);
            const double dw = window_distance(w, t);
            const double bound = std::min(dA + t, dB + (L - t));
            if (dw - bound > kDistTol * (dw + L))
                return true;
        }
        if (dC < kInf) {
            const double lo = window_min(w);
            const Vec2 C = m_.apex[w.he];
            const double ca = norm(C - Vec2{w.b0, 0}), cb = norm(C - Vec2{w.b1, 0});
            if (lo - (dC + std::max(ca, cb)) > kDistTol * (lo + L))
                return true;
        }
        return false;
    }

    /// Points of (p, q) where the two windows' distances may be equal (sorted, with duplicates).
    static int crossings(const Window& a, const Window& b, double p, double q, double out[2]) {
        // Shift to the middle of the overlap for conditioning.
        const double m = 0.5 * (p + q);
        const double x1 = a.sx - m, y1 = a.sy, x2 = b.sx - m, y2 = b.sy;
        const double ds = b.sigma - a.sigma;
        const double alpha = 2 * (x2 - x1);
        const double beta = (x1 * x1 + y1 * y1) - (x2 * x2 + y2 * y2) - ds * ds;
        const double r2 = 4 * ds * ds;
        const double A = alpha * alpha - r2;
        const double B = 2 * alpha * beta + 2 * r2 * x2;
        const double C = beta * beta - r2 * (x2 * x2 + y2 * y2);
        double roots[2];
        int n = 0;
        const double scale = std::abs(A) + std::abs(B) / (q - p + 1e-300) +
                             std::abs(C) / ((q - p) * (q - p) + 1e-300);
        if (ds == 0) {
            // Equal sigmas: the squared equation is (alpha s + beta)^2 = 0.
            if (alpha != 0)
                roots[n++] = -beta / alpha;
        } else if (std::abs(A) <= 1e-14 * scale) {
            if (B != 0)
                roots[n++] = -C / B;
        } else {
            const double disc = B * B - 4 * A * C;
            if (disc < 0) {
                // A (near-)double root lost to round-off: the vertex of the parabola is a
                // harmless extra split point (pieces are decided by evaluation).
                roots[n++] = -B / (2 * A);
            } else {
                const double sq = std::sqrt(disc);
                const double qq = -0.5 * (B + (B >= 0 ? sq : -sq));
                if (qq != 0) {
                    roots[n++] = qq / A;
                    roots[n++] = C / qq;
                } else {
                    roots[n++] = 0;
                }
            }
        }
        int count = 0;
        for (int i = 0; i < n; ++i) {
            double s = roots[i];
            if (!std::isfinite(s))
                continue;
            // Newton polish on f(s) = d_a - d_b (the quadratic squares twice).
            for (int it = 0; it < 3; ++it) {
                const double ra = std::sqrt((s - x1) * (s - x1) + y1 * y1);
                const double rb = std::sqrt((s - x2) * (s - x2) + y2 * y2);
                const double f = (a.sigma + ra) - (b.sigma + rb);
                const double df = (ra > 0 ? (s - x1) / ra : 0) - (rb > 0 ? (s - x2) / rb : 0);
                if (!(std::abs(df) > 1e-12))
                    break;
                const double step = f / df;
                if (!std::isfinite(step) || std::abs(step) > (q - p))
                    break;
                s -= step;
            }
            const double t = s + m;
            if (t > p && t < q)
                out[count++] = t;
        }
        if (count == 2 && out[0] > out[1])
            std::swap(out[0], out[1]);
        return count;
    }

    struct Interval {
        double a, b;
    };

    /// Inserts w on its halfedge: w keeps the parts where it is shorter than the windows already
    /// there; they lose those parts. Updates the end vertices.
    void insert(Window w) {
        const std::uint32_t h = w.he;
        const double L = m_.len[h];
        if (!(w.b1 - w.b0 > kLenTol * L))
            return;
        if (w.b0 <= kLenTol * L)
            relax(m_.corner[h], window_distance(w, 0.0));
        if (w.b1 >= L * (1 - kLenTol))
            relax(m_.corner[next_he(h)], window_distance(w, L));
        if (closed_[h] || window_min(w) > max_distance_)
            return;
        if (prune_ && dominated(w)) {
            ++stats_.pruned;
            return;
        }
        // Parts of w where an existing window is at least as short.
        lose_.clear();
        auto& list = list_[h];
        // Windows of the halfedge are disjoint and sorted: [first, last) overlap w.
        const std::size_t first = static_cast<std::size_t>(
            std::partition_point(list.begin(), list.end(),
                                 [&](std::uint32_t id) { return pool_[id].b1 <= w.b0; }) -
            list.begin());
        std::size_t last = first;
        while (last < list.size() && pool_[list[last]].b0 < w.b1)
            ++last;
        for (std::size_t i = first; i < last; ++i) {
            const Window& e = pool_[list[i]];
            const double p = std::max(w.b0, e.b0), q = std::min(w.b1, e.b1);
            if (!(q > p))
                continue;
            double cut[2];
            const int nc = crossings(w, e, p, q, cut);
            double pts[4];
            int np = 0;
            pts[np++] = p;
            for (int c = 0; c < nc; ++c)
                pts[np++] = cut[c];
            pts[np++] = q;
            for (int k = 0; k + 1 < np; ++k) {
                const double u = pts[k], v = pts[k + 1];
                if (!(v > u))
                    continue;
                const double mid = 0.5 * (u + v);
                const double dw = window_distance(w, mid), de = window_distance(e, mid);
                if (!(dw < de - kDistTol * (de + L))) {
                    if (!lose_.empty() && lose_.back().a <= u && lose_.back().b >= u)
                        lose_.back().b = std::max(lose_.back().b, v);
                    else
                        lose_.push_back({u, v});
                }
            }
        }
        // w's surviving parts: [b0, b1] minus the losses.
        std::sort(lose_.begin(), lose_.end(),
                  [](const Interval& x, const Interval& y) { return x.a < y.a; });
        keep_.clear();
        double from = w.b0;
        for (const auto& l : lose_) {
            if (l.a > from)
                keep_.push_back({from, l.a});
            from = std::max(from, l.b);
        }
        if (w.b1 > from)
            keep_.push_back({from, w.b1});
        keep_.erase(std::remove_if(keep_.begin(), keep_.end(),
                                   [&](const Interval& k) { return !(k.b - k.a > kLenTol * L); }),
                    keep_.end());
        if (keep_.empty())
            return;
        // Existing windows lose the kept parts of w; the overlapped range of the list is rebuilt.
        ids_.clear();
        for (std::size_t i = first; i < last; ++i) {
            const std::uint32_t id = list[i];
            const Window e = pool_[id];
            parts_.clear();
            double f = e.b0;
            for (const auto& k : keep_) {
                if (k.b <= e.b0 || k.a >= e.b1)
                    continue;
                if (k.a > f)
                    parts_.push_back({f, k.a});
                f = std::max(f, k.b);
            }
            if (e.b1 > f)
                parts_.push_back({f, e.b1});
            parts_.erase(
                std::remove_if(parts_.begin(), parts_.end(),
                               [&](const Interval& k) { return !(k.b - k.a > kLenTol * L); }),
                parts_.end());
            if (parts_.empty()) {
                release(id);
                continue;
            }
            if (parts_.size() == 1 && parts_[0].a == e.b0 && parts_[0].b == e.b1) {
                ids_.push_back(id);  // untouched
                continue;
            }
            pool_[id].b0 = parts_[0].a;
            pool_[id].b1 = parts_[0].b;
            pool_[id].gen = (pool_[id].gen + 1) & 0x7fffffffu;
            if (e.state == kQueued)
                enqueue(id);
            ids_.push_back(id);
            for (std::size_t j = 1; j < parts_.size(); ++j) {
                Window c = e;
                c.b0 = parts_[j].a;
                c.b1 = parts_[j].b;
                const std::uint32_t cid = allocate(c);
                if (c.state == kQueued)
                    enqueue(cid);
                ids_.push_back(cid);
            }
        }
        for (const auto& k : keep_) {
            Window c = w;
            c.b0 = k.a;
            c.b1 = k.b;
            c.state = kQueued;
            const std::uint32_t id = allocate(c);
            enqueue(id);
            ids_.push_back(id);
            ++stats_.created;
        }
        std::sort(ids_.begin(), ids_.end(),
                  [&](std::uint32_t a, std::uint32_t b) { return pool_[a].b0 < pool_[b].b0; });
        auto& l = list_[h];  // allocate() does not touch list_, but stay explicit
        l.erase(l.begin() + static_cast<std::ptrdiff_t>(first),
                l.begin() + static_cast<std::ptrdiff_t>(last));
        l.insert(l.begin() + static_cast<std::ptrdiff_t>(first), ids_.begin(), ids_.end());
    }

    /// Window w on halfedge 3f+k crosses face f: children on the twins of the two other edges,
    /// and the opposite corner when it lies in the window's cone.
    void propagate(std::uint32_t id) {
        const Window w = pool_[id];
        const std::uint32_t h = w.he;
        const double L = m_.len[h];
        if (!(w.sy < -kLenTol * L))
            return;  // pseudo-source on the edge line: no ray enters the face
        const std::uint32_t f = h / 3;
        const int k = static_cast<int>(h % 3);
        const auto P = m_.layout(f, k);  // P[k] = (0, 0), P[k+1] = (L, 0)
        const Vec2 A = P[k], B = P[(k + 1) % 3], C = P[(k + 2) % 3];
        const Vec2 S{w.sx, w.sy};
        // Where the ray from S to a point Q of the face crosses the edge line (monotone along
        // each of the other two edges since Q.y - S.y > 0).
        auto cross_x = [&](Vec2 Q) { return w.sx + (Q.x - w.sx) * (-w.sy) / (Q.y - w.sy); };
        const double xc = cross_x(C);
        const std::uint32_t vc = m_.corner[3 * f + (k + 2) % 3];
        if (xc >= w.b0 - kVertexTol * L && xc <= w.b1 + kVertexTol * L)
            relax(vc, w.sigma + norm(C - S));
        // Child on the twin of the edge C -> A (twin runs A -> C) and of B -> C (twin C -> B).
        child(w, 3 * f + (k + 2) % 3, A, C, 0.0, xc);
        child(w, 3 * f + (k + 1) % 3, C, B, xc, L);
    }

    /// Child of w on the twin of halfedge he, the twin running from P0 to P1 (face layout in w's
    /// frame), whose points' rays cross w's edge at x0 (at P0) .. x1 (at P1).
    void child(const Window& w, std::uint32_t he, Vec2 P0, Vec2 P1, double x0, double x1) {
        const std::uint32_t t = m_.twin[he];
        if (t == kNone)
            return;
        const double Lc = m_.len[t];
        if (!(Lc > 0))
            return;
        const double lo = std::max(w.b0, std::min(x0, x1));
        const double hi = std::min(w.b1, std::max(x0, x1));
        if (!(hi - lo > kLenTol * m_.len[w.he]))
            return;
        const Vec2 d = P1 - P0;
        auto u_of = [&](double b) {
            if (b == x0)
                return 0.0;
            if (b == x1)
                return 1.0;
            const double num = (b - w.sx) * (P0.y - w.sy) - (P0.x - w.sx) * (-w.sy);
            const double den = d.x * (-w.sy) - (b - w.sx) * d.y;
            return std::clamp(num / den, 0.0, 1.0);
        };
        double ua = u_of(lo), ub = u_of(hi);
        if (!std::isfinite(ua) || !std::isfinite(ub))
            return;
        if (ua > ub)
            std::swap(ua, ub);
        const double l = norm(d);
        const Vec2 e = (1.0 / l) * d;
        const Vec2 n{-e.y, e.x};
        const Vec2 s = Vec2{w.sx, w.sy} - P0;
        Window c{ua * Lc, ub * Lc, dot(s, e), dot(s, n), w.sigma, t, 0, kQueued};
        if (c.sy > 0)
            c.sy = 0;  // round-off: the pseudo-source is never on the far side
        insert(c);
    }

    void update_peak() {
        const std::size_t bytes =
            pool_.capacity() * sizeof(Window) + free_.capacity() * sizeof(std::uint32_t) +
            heap_peak_ * sizeof(QItem) + list_.size() * sizeof(std::vector<std::uint32_t>) +
            stats_.peak * sizeof(std::uint32_t) + dist_.size() * (2 * sizeof(double) + 1);
        stats_.peak_bytes = std::max(stats_.peak_bytes, bytes);
    }

    // --- queries -----------------------------------------------------------------------------

    struct Best {
        double value = kInf;
        int kind = -1;  ///< 0 source, 1 vertex, 2 window
        std::uint32_t vertex = kNone;
        std::uint32_t he = kNone;  ///< window's halfedge
        double x = 0;              ///< crossing parameter on he
        Vec2 source;               ///< face source position (layout 0)
    };

    /// Best way to reach point q (layout P = layout(f, 0)) through face f: a source in f, a corner
    /// of f, or a window entering f (except through halfedge `skip`).
    Best best_in_face(std::uint32_t f, const std::array<Vec2, 3>& P, Vec2 q, unsigned he_mask = 7,
                      std::uint32_t skip_vertex = kNone) const {
        Best best;
        for (const auto& s : face_sources_)
            if (s.face == f) {
                const double d = norm(q - s.p);
                if (d < best.value) {
                    best.value = d;
                    best.kind = 0;
                    best.source = s.p;
                }
            }
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = m_.corner[3 * f + k];
            if (v == skip_vertex)
                continue;
            const double d = dist_[v] + norm(q - P[k]);
            if (d < best.value) {
                best.value = d;
                best.kind = 1;
                best.vertex = v;
            }
        }
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t h = 3 * f + k;
            if (!(he_mask & (1u << k)))
                continue;
            const double L = m_.len[h];
            if (!(L > 0))
                continue;
            const Vec2 o = P[k];
            const Vec2 e = (1.0 / norm(P[(k + 1) % 3] - o)) * (P[(k + 1) % 3] - o);
            const Vec2 n{-e.y, e.x};
            const Vec2 qq{dot(q - o, e), std::max(0.0, dot(q - o, n))};
            for (std::uint32_t id : list_[h]) {
                const Window& w = pool_[id];
                const double den = qq.y - w.sy;
                if (!(den > 0))
                    continue;
                const double x = w.sx + (qq.x - w.sx) * (-w.sy) / den;
                if (x < w.b0 - kVertexTol * L || x > w.b1 + kVertexTol * L)
                    continue;
                const double d = w.sigma + norm(qq - Vec2{w.sx, w.sy});
                if (d < best.value) {
                    best.value = d;
                    best.kind = 2;
                    best.he = h;
                    best.x = std::clamp(x, w.b0, w.b1);
                }
            }
        }
        return best;
    }

    std::array<double, 3> on_edge(std::uint32_t h, double x) const {
        const auto p = m_.point(m_.corner[h]);
        const auto q = m_.point(m_.corner[next_he(h)]);
        const double s = m_.len[h] > 0 ? std::clamp(x / m_.len[h], 0.0, 1.0) : 0.0;
        return {p[0] + s * (q[0] - p[0]), p[1] + s * (q[1] - p[1]), p[2] + s * (q[2] - p[2])};
    }

    std::array<double, 3> in_face(std::uint32_t f, Vec2 q) const {
        // Barycentric coordinates of q in layout(f, 0), then the 3D point.
        const auto P = m_.layout(f, 0);
        const Vec2 e1 = P[1] - P[0], e2 = P[2] - P[0], r = q - P[0];
        const double det = e1.x * e2.y - e1.y * e2.x;
        double b1 = 0, b2 = 0;
        if (det != 0) {
            b1 = (r.x * e2.y - r.y * e2.x) / det;
            b2 = (e1.x * r.y - e1.y * r.x) / det;
        }
        const double b0 = 1 - b1 - b2;
        std::array<double, 3> out{0, 0, 0};
        const double bb[3] = {b0, b1, b2};
        for (int k = 0; k < 3; ++k) {
            const auto p = m_.point(m_.corner[3 * f + k]);
            for (int i = 0; i < 3; ++i)
                out[i] += bb[k] * p[i];
        }
        return out;
    }

    const CompactMesh& m_;
    bool keep_windows_;
    double max_distance_;
    bool prune_;
    std::size_t max_propagated_;
    double stop_radius_ = kInf;
    bool stopped_ = false;
    std::vector<std::uint32_t> targets_;
    std::size_t target_cursor_ = 0;
    std::vector<double> dist_, emitted_;
    std::vector<char> source_vertex_;
    std::vector<FaceSource> face_sources_;
    std::vector<Window> pool_;
    std::vector<std::uint32_t> free_;
    std::vector<std::vector<std::uint32_t>> list_;  ///< per halfedge, disjoint, sorted by b0
    std::vector<char> closed_;
    std::vector<double> edge_key_;  ///< pending edge event key, +inf when none
    std::vector<std::uint32_t> ids_;
    BucketQueue heap_;
    std::size_t heap_peak_ = 0;
    std::size_t alive_ = 0;
    std::vector<Interval> lose_, keep_, parts_;
    EngineStats stats_;
};

inline std::vector<TracePoint> Engine::trace(std::uint32_t f0, const std::array<double, 3>& b,
                                             std::uint32_t v0) const {
    std::vector<TracePoint> out;
    // State: either at a vertex, or at a point of face f (layout 0), entered through `skip`.
    bool at_vertex = f0 == kNone;
    std::uint32_t v = v0, f = f0, skip = kNone;
    Vec2 q{};
    if (at_vertex) {
        if (!(dist_[v] <= output_radius()))
            return out;
        out.push_back({m_.point(v)});
    } else {
        const auto P = m_.layout(f, 0);
        q = b[0] * P[0] + b[1] * P[1] + b[2] * P[2];
        if (!(face_distance(f, b) < kInf))
            return out;
        out.push_back({in_face(f, q)});
    }
    const std::size_t max_steps = 4 * (m_.corner.size() + m_.vertex_count()) + 16;
    for (std::size_t step = 0; step < max_steps; ++step) {
        Best best;
        std::uint32_t best_face = kNone;
        if (at_vertex) {
            if (source_vertex_[v])
                return out;
            // Through a face of the one-ring: a window on the edge opposite v, a face source,
            // or a neighbour (the geodesic runs along an edge).
            for (std::uint32_t i = m_.vstart[v]; i < m_.vstart[v + 1]; ++i) {
                const std::uint32_t c = m_.vcorners[i];
                const std::uint32_t g = c / 3;
                const int k = static_cast<int>(c % 3);
                const auto P = m_.layout(g, 0);
                const Best bg = best_in_face(g, P, P[k], 1u << ((k + 1) % 3), v);
                if (bg.value < best.value) {
                    best = bg;
                    best_face = g;
                }
            }
        } else {
            const auto P = m_.layout(f, 0);
            best = best_in_face(f, P, q, 7u & ~(skip == kNone ? 0u : 1u << (skip % 3)));
            best_face = f;
        }
        if (best.kind < 0 || best_face == kNone)
            return {};
        if (best.kind == 0) {
            out.push_back({in_face(best_face, best.source)});
            return out;
        }
        if (best.kind == 1) {
            if (at_vertex && best.vertex == v)
                return {};
            v = best.vertex;
            at_vertex = true;
            out.push_back({m_.point(v)});
            continue;
        }
        // Window: move to the crossing point on the edge, into the face on the other side.
        const std::uint32_t h = best.he;
        out.push_back({on_edge(h, best.x)});
        const std::uint32_t t = m_.twin[h];
        if (t == kNone)
            return {};
        f = t / 3;
        skip = t;
        at_vertex = false;
        const auto Q = m_.layout(f, 0);
        const int j = static_cast<int>(t % 3);
        const double s = std::clamp(best.x / m_.len[h], 0.0, 1.0);  // from source(h) = target(t)
        q = (1 - s) * Q[(j + 1) % 3] + s * Q[j];
    }
    return {};
}

}  // namespace tapeline::geodesic::internal::mmp
