// Machinery of the geodesic curvature flow (curvature_flow.h) on plain arrays; Eigen, no CGAL.
//
// A path is a polyline of samples with fixed endpoints. At each sample the tangent plane is the one
// of its nearest mesh vertex: the eigenvectors of the two smaller eigenvalues of B = sum n_f n_fᵀ
// over the unit normals of the faces around the vertex (the largest one is the normal). Samples
// move only in their tangent planes, parametrised by two coordinates each (see flow_step for why),
// and are projected back onto the faces around their nearest vertex after each step.
#pragma once

#include <tapeline/core/compact_mesh_types.h>
#include <tapeline/geodesic/curvature_flow_types.h>
#include <tapeline/geodesic/internal/gcf_wavefront.h>

#include <Eigen/Dense>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <Eigen/SparseQR>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <queue>
#include <string>
#include <utility>
#include <vector>

namespace tapeline::geodesic::internal::gcf {

using Vec3 = Eigen::Vector3d;
constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

/// Lazily filled per-element values (vertex frames of the mesh, local charts of point sets) that
/// several threads may fill at once. Filling all of them up front was the alternative: 0.3 us per
/// 3x3 eigen-decomposition (measured, -O3, one thread), i.e. 12 ms at 41k vertices against a
/// 15 ms two-point path that needs only a few hundred of them. Here each slot has a state (0
/// empty, 1 being written, 2 ready): a reader that finds 2 (acquire) reads the value; else it
/// computes the value itself and publishes it only if it wins the 0 -> 1 exchange, so one thread
/// writes a slot and nobody waits. The value must be a deterministic function of the input, so
/// every thread gets bitwise the same one. A copy starts empty (the atomics cannot be copied, and
/// recomputing is cheap).
template <class T>
class LazySlots {
public:
    LazySlots() = default;
    LazySlots(const LazySlots& o) { reset(o.size_); }
    LazySlots& operator=(const LazySlots& o) {
        if (this != &o)
            reset(o.size_);
        return *this;
    }
    LazySlots(LazySlots&&) noexcept = default;
    LazySlots& operator=(LazySlots&&) noexcept = default;

    void reset(std::size_t n) {
        size_ = n;
        state_ = n ? std::make_unique<std::atomic<unsigned char>[]>(n) : nullptr;
        for (std::size_t i = 0; i < n; ++i)
            state_[i].store(0, std::memory_order_relaxed);
        values_.clear();
        values_.resize(n);  // Eigen types stay uninitialised: nothing touched up front
    }
    bool get(std::size_t v, T& f) const {
        if (state_[v].load(std::memory_order_acquire) != 2)
            return false;
        f = values_[v];
        return true;
    }
    /// The stored value, or nullptr while slot v is not ready (no copy).
    const T* find(std::size_t v) const {
        return state_[v].load(std::memory_order_acquire) == 2 ? &values_[v] : nullptr;
    }
    void put(std::size_t v, const T& f) const {
        unsigned char empty = 0;
        if (state_[v].compare_exchange_strong(empty, 1, std::memory_order_acquire)) {
            values_[v] = f;
            state_[v].store(2, std::memory_order_release);
        }
    }
    std::size_t size() const { return size_; }

private:
    std::size_t size_ = 0;
    std::unique_ptr<std::atomic<unsigned char>[]> state_;
    mutable std::vector<T> values_;
};

/// The flow's view of the compact mesh (core/compact_mesh_types.h, whose corner order it keeps):
/// Eigen positions, the face across each edge, vertex-to-face and vertex-to-vertex tables, unit
/// face normals and the lazily computed vertex frames.
struct Mesh {
    std::vector<Vec3> xyz;
    std::vector<std::uint32_t> corner;    ///< 3 per face
    std::vector<std::uint32_t> across;    ///< 3 per face: face across edge (corner k, corner k+1)
    std::vector<std::uint32_t> vf_start;  ///< CSR vertex -> incident faces
    std::vector<std::uint32_t> vf;
    std::vector<std::uint32_t> vv_start;  ///< CSR vertex -> neighbour vertices
    std::vector<std::uint32_t> vv;
    std::vector<Vec3> face_normal;  ///< unit (zero for a zero-area face)
    double mean_edge = 0;

    std::size_t vertex_count() const { return xyz.size(); }
    std::size_t face_count() const { return corner.size() / 3; }

    Mesh() = default;
    explicit Mesh(const tapeline::CompactMesh& c) {
        const std::size_t nv = c.vertex_count();
        xyz.resize(nv);
        for (std::size_t i = 0; i < nv; ++i)
            xyz[i] = Vec3(c.xyz[3 * i], c.xyz[3 * i + 1], c.xyz[3 * i + 2]);
        corner = c.corner;
        across.resize(c.twin.size());
        for (std::size_t h = 0; h < c.twin.size(); ++h)
            across[h] = c.twin[h] == tapeline::CompactMesh::kNone ? kNone : c.twin[h] / 3;
        vf_start = c.vstart;
        vf.resize(c.vcorners.size());
        for (std::size_t k = 0; k < vf.size(); ++k)
            vf[k] = c.vcorners[k] / 3;
        vv_start = c.nstart;
        vv = c.neighbours;
        double edge_sum = 0;
        for (std::size_t i = 0; i < nv; ++i)
            for (std::uint32_t k = vv_start[i]; k < vv_start[i + 1]; ++k)
                edge_sum += (xyz[vv[k]] - xyz[i]).norm();
        mean_edge = vv.empty() ? 0.0 : edge_sum / static_cast<double>(vv.size());
        finish();
    }

    void finish() {
        const std::size_t nf = face_count();
        face_normal.resize(nf);
        for (std::size_t f = 0; f < nf; ++f) {
            const Vec3 n = (xyz[corner[3 * f + 1]] - xyz[corner[3 * f]])
                               .cross(xyz[corner[3 * f + 2]] - xyz[corner[3 * f]]);
            const double len = n.norm();
            face_normal[f] = len > 0 ? Vec3(n / len) : Vec3::Zero();
        }
        frames_.reset(vertex_count());
    }

    /// Tangent basis (columns 0, 1) and normal (column 2) at a vertex, computed on first use and
    /// kept. Safe to call from several threads at once (see LazySlots).
    Eigen::Matrix3d frame(std::uint32_t v) const {
        Eigen::Matrix3d f;
        if (frames_.get(v, f))
            return f;
        Eigen::Matrix3d b = Eigen::Matrix3d::Zero();
        for (std::uint32_t k = vf_start[v]; k < vf_start[v + 1]; ++k)
            b += face_normal[vf[k]] * face_normal[vf[k]].transpose();
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(b);
        // Eigenvalues ascending: the last eigenvector is the normal.
        f = es.eigenvectors();
        frames_.put(v, f);
        return f;
    }

private:
    LazySlots<Eigen::Matrix3d> frames_;
};

/// Closest point of triangle abc to p (Ericson, Real-Time Collision Detection, 5.1.5), with its
/// barycentric coordinates.
inline Vec3 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c,
                                Vec3& bary) {
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0 && d2 <= 0) {
        bary = {1, 0, 0};
        return a;
    }
    const Vec3 bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0 && d4 <= d3) {
        bary = {0, 1, 0};
        return b;
    }
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) {
        const double v = d1 / (d1 - d3);
        bary = {1 - v, v, 0};
        return a + v * ab;
    }
    const Vec3 cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0 && d5 <= d6) {
        bary = {0, 0, 1};
        return c;
    }
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) {
        const double w = d2 / (d2 - d6);
        bary = {1 - w, 0, w};
        return a + w * ac;
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
        const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        bary = {0, 1 - w, w};
        return b + w * (c - b);
    }
    const double denom = 1.0 / (va + vb + vc);
    const double v = vb * denom, w = vc * denom;
    bary = {1 - v - w, v, w};
    return a + ab * v + ac * w;
}

/// A sample of the path: position, nearest vertex, face it was projected onto.
struct Sample {
    Vec3 p;
    std::uint32_t vertex = kNone;
    std::uint32_t face = kNone;
};

/// Greedy descent over the 1-ring from `start` to a vertex nearer to p than all its neighbours.
inline std::uint32_t nearest_vertex_walk(const Mesh& m, const Vec3& p, std::uint32_t start) {
    std::uint32_t v = start;
    double best = (m.xyz[v] - p).squaredNorm();
    for (std::size_t guard = 0; guard < m.vertex_count(); ++guard) {
        std::uint32_t next = v;
        for (std::uint32_t k = m.vv_start[v]; k < m.vv_start[v + 1]; ++k) {
            const double d = (m.xyz[m.vv[k]] - p).squaredNorm();
            if (d < best) {
                best = d;
                next = m.vv[k];
            }
        }
        if (next == v)
            break;
        v = next;
    }
    return v;
}

/// Projects p onto the faces around its nearest vertex (closest point on those triangles). On
/// irregular meshes the closest face can lie just outside that 1-ring, so the 1-rings of the
/// corners of the face found are searched too.
inline void project_around(const Mesh& m, Sample& s) {
    double best = std::numeric_limits<double>::infinity();
    Vec3 best_p = s.p;
    auto ring = [&](std::uint32_t v) {
        for (std::uint32_t k = m.vf_start[v]; k < m.vf_start[v + 1]; ++k) {
            const std::uint32_t f = m.vf[k];
            Vec3 bary;
            const Vec3 q =
                closest_on_triangle(s.p, m.xyz[m.corner[3 * f]], m.xyz[m.corner[3 * f + 1]],
                                    m.xyz[m.corner[3 * f + 2]], bary);
            const double d = (q - s.p).squaredNorm();
            if (d < best) {
                best = d;
                best_p = q;
                s.face = f;
            }
        }
    };
    ring(s.vertex);
    if (s.face != kNone && m.face_count() > 0) {
        const std::uint32_t f = s.face;
        for (int k = 0; k < 3; ++k)
            if (m.corner[3 * f + k] != s.vertex)
                ring(m.corner[3 * f + k]);
    }
    s.p = best_p;
}

/// Dijkstra on the edge graph; the vertex sequence from a to b, empty if unreachable.
inline std::vector<std::uint32_t> edge_path(const Mesh& m, std::uint32_t a, std::uint32_t b) {
    std::vector<double> dist;
    std::vector<std::uint32_t> pred;
    dijkstra_to(
        m.vv_start, m.vv, a, b,
        [&m](std::uint32_t v, std::uint32_t w) { return (m.xyz[w] - m.xyz[v]).norm(); }, dist,
        pred);
    std::vector<std::uint32_t> path;
    if (!(dist[b] < std::numeric_limits<double>::infinity()))
        return path;
    for (std::uint32_t v = b; v != kNone; v = pred[v])
        path.push_back(v);
    std::reverse(path.begin(), path.end());
    return path;
}

/// A polyline on the faces from vertex a to vertex b: points and, per point, a mesh vertex near it.
struct FacePath {
    std::vector<Vec3> points;
    std::vector<std::uint32_t> hints;
};

/// Dijkstra on the edge graph plus, for every edge, the step between the two vertices opposite it
/// when the straight line between them crosses the edge in the pair of faces unfolded into one
/// plane (a convex pair): a metric much closer to the surface's than the edges' alone, whose paths
/// on structured (grid, fan) meshes are up to sqrt(2) long and can take the other way around a
/// limb. The crossing point on the edge is part of the path, so it stays on the faces. A* with the
/// straight-line distance to b as the (consistent) estimate: only the region around the segment
/// is searched. Empty if b is not reachable.
inline FacePath face_path(const Mesh& m, std::uint32_t a, std::uint32_t b) {
    const std::size_t n = m.vertex_count();
    std::vector<double> dist(n, std::numeric_limits<double>::infinity());
    std::vector<std::uint32_t> pred(n, kNone);
    std::vector<Vec3> via(n);  // the edge crossing of a step across an edge
    std::vector<char> crossed(n, 0);
    using Item = std::pair<double, std::uint32_t>;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> q;
    dist[a] = 0;
    const Vec3 goal = m.xyz[b];
    q.push({(m.xyz[a] - goal).norm(), a});
    auto relax = [&](std::uint32_t v, std::uint32_t w, double nd, const Vec3* x) {
        if (nd < dist[w]) {
            dist[w] = nd;
            pred[w] = v;
            crossed[w] = x != nullptr;
            if (x)
                via[w] = *x;
            q.push({nd + (m.xyz[w] - goal).norm(), w});
        }
    };
    while (!q.empty()) {
        const auto [key, v] = q.top();
        q.pop();
        const double d = dist[v];
        if (key > d + (m.xyz[v] - goal).norm() * (1 + 1e-12))
            continue;  // a stale entry
        if (v == b)
            break;
        for (std::uint32_t k = m.vv_start[v]; k < m.vv_start[v + 1]; ++k)
            relax(v, m.vv[k], d + (m.xyz[m.vv[k]] - m.xyz[v]).norm(), nullptr);
        for (std::uint32_t k = m.vf_start[v]; k < m.vf_start[v + 1]; ++k) {
            const std::uint32_t f = m.vf[k];
            int c = 0;
            while (c < 3 && m.corner[3 * f + c] != v)
                ++c;
            if (c == 3)
                continue;
            // The edge opposite v (corners c+1, c+2) and the face across it.
            const int e = (c + 1) % 3;
            const std::uint32_t g = m.across[3 * f + e];
            if (g == kNone)
                continue;
            const std::uint32_t u = m.corner[3 * f + e], w = m.corner[3 * f + (c + 2) % 3];
            std::uint32_t x = kNone;
            for (int j = 0; j < 3; ++j) {
                const std::uint32_t cj = m.corner[3 * g + j];
                if (cj != u && cj != w)
                    x = cj;
            }
            if (x == kNone || x == v)
                continue;
            // Unfold: edge u-w along an axis, v on one side, x on the other.
            const Vec3 ew = m.xyz[w] - m.xyz[u];
            const double len = ew.norm();
            if (!(len > 0))
                continue;
            const Vec3 t = ew / len;
            const Vec3 pv = m.xyz[v] - m.xyz[u], px = m.xyz[x] - m.xyz[u];
            const double sv = pv.dot(t), sx = px.dot(t);
            const double hv = (pv - sv * t).norm(), hx = (px - sx * t).norm();
            if (!(hv > 0 && hx > 0))
                continue;
            const double along = sv + (sx - sv) * hv / (hv + hx);  // crossing, from u
            if (!(along > 1e-9 * len && along < len * (1 - 1e-9)))
                continue;
            const Vec3 cross = m.xyz[u] + along * t;
            relax(v, x, d + std::hypot(sx - sv, hv + hx), &cross);
        }
    }
    FacePath out;
    if (!(dist[b] < std::numeric_limits<double>::infinity()))
        return out;
    for (std::uint32_t v = b; v != kNone; v = pred[v]) {
        out.points.push_back(m.xyz[v]);
        out.hints.push_back(v);
        if (crossed[v]) {
            out.points.push_back(via[v]);
            out.hints.push_back(v);
        }
    }
    std::reverse(out.points.begin(), out.points.end());
    std::reverse(out.hints.begin(), out.hints.end());
    return out;
}

inline double polyline_length(const std::vector<Vec3>& p) {
    double len = 0;
    for (std::size_t i = 1; i < p.size(); ++i)
        len += (p[i] - p[i - 1]).norm();
    return len;
}

/// Uniform resampling by arc length to `count` samples; hint[i] is a mesh vertex near point i of
/// the input, used to start the nearest-vertex walk of the samples.
inline std::vector<Sample> resample(const std::vector<Vec3>& pts,
                                    const std::vector<std::uint32_t>& hint, std::size_t count) {
    std::vector<double> s(pts.size(), 0.0);
    for (std::size_t i = 1; i < pts.size(); ++i)
        s[i] = s[i - 1] + (pts[i] - pts[i - 1]).norm();
    const double total = s.back();
    std::vector<Sample> out(count);
    std::size_t seg = 0;
    for (std::size_t k = 0; k < count; ++k) {
        const double t = total * static_cast<double>(k) / static_cast<double>(count - 1);
        while (seg + 2 < pts.size() && s[seg + 1] < t)
            ++seg;
        const double len = s[seg + 1] - s[seg];
        const double u = len > 0 ? std::clamp((t - s[seg]) / len, 0.0, 1.0) : 0.0;
        out[k].p = (1 - u) * pts[seg] + u * pts[seg + 1];
        out[k].vertex = u < 0.5 ? hint[seg] : hint[seg + 1];
    }
    out.front().p = pts.front();
    out.back().p = pts.back();
    return out;
}

/// Tangent frame of a sample: the one of its nearest vertex (the thesis' choice), or with
/// `interpolate` the vertex normals of its face blended by its barycentric coordinates, which is
/// continuous where the nearest vertex jumps.
inline Eigen::Matrix3d sample_frame(const Mesh& m, const Sample& s, bool interpolate) {
    const Eigen::Matrix3d& fv = m.frame(s.vertex);
    if (!interpolate || s.face == kNone)
        return fv;
    const std::uint32_t f = s.face;
    Vec3 bary;
    closest_on_triangle(s.p, m.xyz[m.corner[3 * f]], m.xyz[m.corner[3 * f + 1]],
                        m.xyz[m.corner[3 * f + 2]], bary);
    Vec3 n = Vec3::Zero();
    for (int k = 0; k < 3; ++k) {
        const Vec3 nk = m.frame(m.corner[3 * f + k]).col(2);
        n += bary[k] * (nk.dot(m.face_normal[f]) < 0 ? Vec3(-nk) : nk);
    }
    if (!(n.norm() > 0))
        return fv;
    n.normalize();
    Vec3 t1 = fv.col(0) - fv.col(0).dot(n) * n;
    if (t1.norm() < 1e-6)
        t1 = fv.col(1) - fv.col(1).dot(n) * n;
    t1.normalize();
    Eigen::Matrix3d out;
    out.col(0) = t1;
    out.col(1) = n.cross(t1);
    out.col(2) = n;
    return out;
}

/// Geodesic curvature rows at the current samples: T_iᵀ (p_{i-1} - 2 p_i + p_{i+1}).
inline void curvature(const Mesh& m, const std::vector<Sample>& s, bool interpolate,
                      double& max_norm, double& residual) {
    max_norm = 0;
    double sum = 0;
    for (std::size_t i = 1; i + 1 < s.size(); ++i) {
        const Vec3 l = s[i - 1].p - 2 * s[i].p + s[i + 1].p;
        const Eigen::Matrix<double, 3, 2> t = sample_frame(m, s[i], interpolate).leftCols<2>();
        const double r = (t.transpose() * l).norm();
        max_norm = std::max(max_norm, r);
        sum += r * r;
    }
    residual = std::sqrt(sum);
}

/// Moves the samples by their solved tangent coordinates x and re-projects them; max_update is
/// the largest displacement after re-projection. False if x is not finite.
inline bool apply_step(const Mesh& m, std::vector<Sample>& s,
                       const std::vector<Eigen::Matrix<double, 3, 2>>& t, const Eigen::VectorXd& x,
                       double& max_update) {
    const std::size_t n = s.size();
    if (!x.allFinite())
        return false;
    max_update = 0;
    for (std::size_t i = 1; i + 1 < n; ++i) {
        // The move that counts is the one left after re-projection: at sharp features the
        // projection can undo the tangent move, a fixed point that must end as "stalled".
        const Vec3 before = s[i].p;
        s[i].p += t[i] * x.segment<2>(static_cast<Eigen::Index>(2 * i));
        s[i].vertex = nearest_vertex_walk(m, s[i].p, s[i].vertex);
        project_around(m, s[i]);
        max_update = std::max(max_update, (s[i].p - before).norm());
    }
    return true;
}

/// Up to this many unknowns (k per sample) the normal equations are assembled and factorised
/// densely.
constexpr std::size_t kDenseColumns = 64;

/// Solver of one flow step's least-squares system from outside this header: given the samples,
/// their tangent bases t and the step, writes the 2 tangent coordinates per sample into x (size
/// 2 m; the endpoints' are ignored). False if it failed.
using TangentStepSolver = bool (*)(const std::vector<Sample>& s,
                                   const std::vector<Eigen::Matrix<double, 3, 2>>& t,
                                   const CurvatureFlowOptions& o, double step, Eigen::VectorXd& x);

/// The solver of CurvatureFlowSolver::ceres, registered by curvature_flow_ceres.h (null until a
/// translation unit that includes it runs its initialisers). A registry rather than a member of
/// the options keeps Ceres, and even Eigen types, out of curvature_flow_types.h, so a program that
/// needs only geodesics never compiles Ceres.
inline std::atomic<TangentStepSolver>& ceres_step_solver() {
    static std::atomic<TangentStepSolver> solver{nullptr};
    return solver;
}

/// The least-squares system of one flow step, for samples in R^D with k-dimensional tangent
/// bases (the mesh: D = 3, k = 2; point sets: any D and k). Unknowns: k tangent coordinates a_i per
/// sample (delta_i = T_i a_i). Chosen over D coordinates with penalty rows N_iᵀ delta_i = 0
/// because the constraint then holds exactly rather than up to a penalty weight, and the system
/// has k m instead of D m unknowns. Rows (overdetermined, 2 k (m - 1) rows for k m unknowns):
///   T_iᵀ (L (p + delta))_i = 0        interior i: geodesic curvature after the step (linearised)
///   mu^{-1/2} a_i = 0                 interior i: step size (damping)
///   w a_0 = 0, w a_{m-1} = 0          endpoints
/// `pos(i)` gives sample i's position (an Eigen vector of size D), t[i] its D x k orthonormal
/// tangent basis; k is the runtime tangent dimension (must equal K unless K is Eigen::Dynamic).
/// Writes the k m coordinates into x (the endpoints' are ignored by the caller); false if the
/// factorisation failed. D and K are compile-time sizes when known (the mesh's 3 x 2: fixed-size
/// Eigen blocks, no allocation per block) or Eigen::Dynamic.
template <int D, int K, class Position>
bool solve_tangent_step(std::size_t n, const Position& pos,
                        const std::vector<Eigen::Matrix<double, D, K>>& t, Eigen::Index k,
                        const CurvatureFlowOptions& o, double step, Eigen::VectorXd& x) {
    using Block = Eigen::Matrix<double, K, K>;
    using Coords = Eigen::Matrix<double, K, 1>;
    const auto kk = static_cast<std::size_t>(k);
    const std::size_t cols = kk * n;
    const Block identity = Block::Identity(k, k);
    if (o.solver == CurvatureFlowSolver::eigen_normal_ldlt && cols <= kDenseColumns) {
        // Short polylines (the windows of Algorithm 2): the normal equations of the rows below,
        // assembled block by block into a small dense matrix (no sparse symbolic analysis).
        Eigen::MatrixXd normal =
            Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(cols), static_cast<Eigen::Index>(cols));
        Eigen::VectorXd atb = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(cols));
        Block b[3];
        for (std::size_t i = 1; i + 1 < n; ++i) {
            const auto ti = t[i].transpose();
            b[0] = ti * t[i - 1];
            b[1] = -2 * identity;
            b[2] = ti * t[i + 1];
            const Coords r = -(ti * (pos(i - 1) - 2 * pos(i) + pos(i + 1)));
            for (int j = 0; j < 3; ++j) {
                const auto rj = static_cast<Eigen::Index>(kk * (i - 1 + j));
                atb.template segment<K>(rj, k) += b[j].transpose() * r;
                for (int c = 0; c < 3; ++c)
                    normal.template block<K, K>(rj, static_cast<Eigen::Index>(kk * (i - 1 + c)), k,
                                                k) += b[j].transpose() * b[c];
            }
            normal
                .template block<K, K>(static_cast<Eigen::Index>(kk * i),
                                      static_cast<Eigen::Index>(kk * i), k, k)
                .diagonal()
                .array() += 1.0 / step;
        }
        const double w2 = o.endpoint_weight * o.endpoint_weight;
        const auto last = static_cast<Eigen::Index>(cols - kk);
        normal.template block<K, K>(0, 0, k, k).diagonal().array() += w2;
        normal.template block<K, K>(last, last, k, k).diagonal().array() += w2;
        const Eigen::LDLT<Eigen::MatrixXd> ldlt(normal);
        if (ldlt.info() != Eigen::Success)
            return false;
        x = ldlt.solve(atb);
        return true;
    }
    std::vector<Eigen::Triplet<double>> trip;
    trip.reserve(4 * kk * kk * n);
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(2 * kk * (n - 1)));
    std::size_t row = 0;
    auto block = [&](std::size_t r, std::size_t c, const Block& b) {
        for (Eigen::Index x = 0; x < k; ++x)
            for (Eigen::Index y = 0; y < k; ++y)
                if (b(x, y) != 0)
                    trip.emplace_back(static_cast<int>(r + static_cast<std::size_t>(x)),
                                      static_cast<int>(kk * c + static_cast<std::size_t>(y)),
                                      b(x, y));
    };
    for (std::size_t i = 1; i + 1 < n; ++i, row += kk) {
        const auto ti = t[i].transpose();
        block(row, i - 1, ti * t[i - 1]);
        block(row, i, -2 * identity);
        block(row, i + 1, ti * t[i + 1]);
        rhs.template segment<K>(static_cast<Eigen::Index>(row), k) =
            -(ti * (pos(i - 1) - 2 * pos(i) + pos(i + 1)));
    }
    const double damp = 1.0 / std::sqrt(step);
    for (std::size_t i = 1; i + 1 < n; ++i, row += kk)
        block(row, i, damp * identity);
    block(row, 0, o.endpoint_weight * identity);
    row += kk;
    block(row, n - 1, o.endpoint_weight * identity);
    row += kk;
    Eigen::SparseMatrix<double> a(static_cast<int>(row), static_cast<int>(cols));
    a.setFromTriplets(trip.begin(), trip.end());
    a.makeCompressed();
    if (o.solver == CurvatureFlowSolver::eigen_sparse_qr) {
        Eigen::SparseQR<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> qr(a);
        if (qr.info() != Eigen::Success)
            return false;
        x = qr.solve(rhs);
    } else if (o.solver == CurvatureFlowSolver::eigen_lscg) {
        Eigen::LeastSquaresConjugateGradient<Eigen::SparseMatrix<double>> cg(a);
        cg.setTolerance(1e-12);
        x = cg.solve(rhs);
        if (cg.info() != Eigen::Success && cg.info() != Eigen::NoConvergence)
            return false;
    } else {
        const Eigen::SparseMatrix<double> at = a.transpose();
        const Eigen::SparseMatrix<double> normal = at * a;
        Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(normal);
        if (ldlt.info() != Eigen::Success)
            return false;
        x = ldlt.solve(at * rhs);
    }
    return true;
}

/// One flow step on the mesh: the tangent planes of the samples (sample_frame), the system of
/// solve_tangent_step with D = 3, k = 2 (or the registered Ceres solver), then apply_step.
/// max_update: the largest displacement of a sample (after re-projection); false if the solver
/// failed.
inline bool flow_step(const Mesh& m, std::vector<Sample>& s, const CurvatureFlowOptions& o,
                      double step, double& max_update) {
    const std::size_t n = s.size();
    std::vector<Eigen::Matrix<double, 3, 2>> t(n);
    for (std::size_t i = 0; i < n; ++i)
        t[i] = sample_frame(m, s[i], o.interpolate_normals).leftCols<2>();
    Eigen::VectorXd x;
    if (o.solver == CurvatureFlowSolver::ceres) {
        const TangentStepSolver solve = ceres_step_solver().load(std::memory_order_acquire);
        if (!solve || !solve(s, t, o, step, x) || x.size() != static_cast<Eigen::Index>(2 * n))
            return false;
        return apply_step(m, s, t, x, max_update);
    }
    const auto pos = [&s](std::size_t i) -> const Vec3& { return s[i].p; };
    if (!solve_tangent_step<3, 2>(n, pos, t, 2, o, step, x))
        return false;
    return apply_step(m, s, t, x, max_update);
}

/// Phong tessellation (Boubekeur, Alexa 2008, alpha = 3/4) of the point x of face f with
/// barycentric coordinates b: lifts a point of the faces towards the smooth surface that the
/// vertex normals describe.
inline Vec3 phong_lift(const Mesh& m, std::uint32_t f, const Vec3& x) {
    const Vec3 a = m.xyz[m.corner[3 * f]], b = m.xyz[m.corner[3 * f + 1]],
               c = m.xyz[m.corner[3 * f + 2]];
    Vec3 bary;
    closest_on_triangle(x, a, b, c, bary);
    Vec3 sum = Vec3::Zero();
    for (int k = 0; k < 3; ++k) {
        const std::uint32_t v = m.corner[3 * f + k];
        const Vec3 nrm = m.frame(v).col(2);
        sum += bary[k] * (x - (x - m.xyz[v]).dot(nrm) * nrm);
    }
    return 0.25 * x + 0.75 * sum;
}

/// Whether x lies on face f (within 1e-9 mean edge lengths).
inline bool on_face(const Mesh& m, std::uint32_t f, const Vec3& x) {
    Vec3 bary;
    const Vec3 c = closest_on_triangle(x, m.xyz[m.corner[3 * f]], m.xyz[m.corner[3 * f + 1]],
                                       m.xyz[m.corner[3 * f + 2]], bary);
    return (c - x).norm() <= 1e-9 * m.mean_edge;
}

/// Traces the straight segment p (on face fp) -> q (on face fq) over the faces by cutting them
/// with the plane through p and q that contains the normal `nrm` (the plane-cut of the thesis).
/// Appends the edge crossings and q to out; false (q appended, a chord) if the walk got lost.
inline bool trace_segment(const Mesh& m, const Vec3& p, std::uint32_t fp, const Vec3& q,
                          std::uint32_t fq, const Vec3& nrm, std::vector<Vec3>& out) {
    if (fp == fq || on_face(m, fp, q)) {
        out.push_back(q);
        return true;
    }
    Vec3 c = (q - p).cross(nrm);
    if (!(c.norm() > 0)) {
        out.push_back(q);
        return false;
    }
    c.normalize();
    const std::size_t n0 = out.size();
    const Vec3 dir = q - p;
    std::uint32_t f = fp, from = kNone;
    Vec3 cur = p;
    for (int guard = 0; guard < 64; ++guard) {
        double best = -std::numeric_limits<double>::infinity();
        Vec3 best_x;
        int best_k = -1;
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t g = m.across[3 * f + k];
            if (g == from && from != kNone)
                continue;
            const Vec3& a = m.xyz[m.corner[3 * f + k]];
            const Vec3& b = m.xyz[m.corner[3 * f + (k + 1) % 3]];
            const double sa = c.dot(a - p), sb = c.dot(b - p);
            if ((sa > 0 && sb > 0) || (sa < 0 && sb < 0))
                continue;
            const double u = (sa == sb) ? 0.5 : sa / (sa - sb);
            const Vec3 x = a + std::clamp(u, 0.0, 1.0) * (b - a);
            const double ahead = (x - cur).dot(dir);
            if (ahead > best) {
                best = ahead;
                best_x = x;
                best_k = k;
            }
        }
        if (best_k < 0 || (best_x - p).dot(dir) > dir.squaredNorm())
            break;
        out.push_back(best_x);
        const std::uint32_t g = m.across[3 * f + best_k];
        if (g == kNone)
            break;
        from = f;
        f = g;
        cur = best_x;
        if (f == fq || on_face(m, f, q)) {
            out.push_back(q);
            return true;
        }
    }
    out.resize(n0);
    out.push_back(q);
    return false;
}

}  // namespace tapeline::geodesic::internal::gcf
