// Machinery of geodesics on point sets by geodesic curvature flow (point_cloud.h): the thesis'
// Algorithm 3 on plain arrays. Eigen, TBB; CGAL only through the kNN search (gcf_knn.h).
//
// The flow is the mesh's (solve_tangent_step of gcf_engine.h, with D-dimensional samples and
// k-dimensional tangent bases); what changes is where a sample's tangent space and surface come
// from. The mesh takes the faces around the sample's nearest vertex; here the sample walks the
// kNN graph greedily to a nearest input point (as the mesh walks its 1-rings) and is projected
// onto that point's local chart: the PCA plane of its d nearest points, or the weighted quadratic
// (MLS) fitted over that plane. Charts are fitted on first use and kept (LazySlots), as the mesh
// keeps its vertex frames.
//
// Destinations are the non-empty cells of a regular grid (hash map on integer cell coordinates):
// the mean of a cell's points, projected onto its local surface. Neighbouring cells (Chebyshev
// distance 1) are joined; the propagation over that graph is the mesh's Algorithm 2 with
// field-anchored windows (gcf_distances.h) written for nodes instead of vertices: causal batches
// in tentative-distance order, the straightest continuation of a visited neighbour's geodesic
// (plus the cut-locus guard), the last W samples flowed, the anchor's distance interpolated from
// the visited nodes around it and the anchor slid to straighten the kink. Distances at the input
// points are interpolated from the nodes around them.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/geodesic/internal/gcf_batches.h>
#include <tapeline/geodesic/internal/gcf_engine.h>
#include <tapeline/geodesic/internal/gcf_knn.h>
#include <tapeline/geodesic/internal/gcf_wavefront.h>
#include <tapeline/geodesic/point_cloud_types.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <numeric>
#include <queue>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

namespace tapeline::geodesic::internal::gcf::points {

using Clock = std::chrono::steady_clock;
inline double since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}
constexpr double kInf = std::numeric_limits<double>::infinity();
/// Largest ambient dimension of the grid adjacency (3^D - 1 neighbour cells are looked up).
constexpr std::size_t kMaxGridDimension = 8;
/// Largest manifold dimension of the MLS projection (its quadric has 1 + k + k (k + 1) / 2 terms).
constexpr std::size_t kMaxMlsDimension = 8;

inline std::size_t mls_terms(std::size_t k) {
    return 1 + k + k * (k + 1) / 2;
}

/// The checked input and everything that does not depend on the dimension templates: the
/// coordinates, the kNN graph, the grid and its adjacency.
struct Prepared {
    std::size_t n = 0, dim = 0, k = 0, d = 0;
    std::vector<double> xyz;         ///< n * dim
    std::vector<double> normals;     ///< n * dim when a normal map was given (codimension 1)
    std::vector<std::uint32_t> knn;  ///< n * d: the d nearest points of each (itself first)
    double cell = 0;
    std::vector<double> origin;                          ///< grid origin (minimum corner)
    std::vector<std::uint32_t> point_node;               ///< node (non-empty cell) of each point
    std::vector<std::uint32_t> node_start, node_points;  ///< CSR node -> its points
    std::vector<std::uint32_t> adj_start, adj;           ///< CSR node -> neighbouring nodes
    std::vector<std::uint32_t> component;                ///< per node
    PointCloudDistanceReport report;                     ///< sizes and set-up timings
    const double* at(std::size_t i) const { return xyz.data() + dim * i; }
};

/// Builds Prepared from flat coordinates (dimension dim): checks, kNN graph, manifold dimension,
/// grid. `where` prefixes messages.
inline void prepare(Prepared& pr, const PointCloudDistanceOptions& o, const char* where) {
    const auto t0 = Clock::now();
    auto bad = [&](const std::string& what) {
        throw InvalidInput(std::string(where) + ": " + what);
    };
    const std::size_t n = pr.n, D = pr.dim;
    if (!std::isfinite(o.cell_size) || o.cell_size < 0)
        bad("cell_size must be finite and >= 0 (0 = from the point spacing)");
    if (!std::isfinite(o.sample_spacing) || o.sample_spacing < 0)
        bad("sample_spacing must be finite and >= 0 (0 = the cell size)");
    if (o.neighbours < 3)
        bad("neighbours must be at least 3 (given " + std::to_string(o.neighbours) + ")");
    for (const CurvatureFlowOptions* f : {&o.flow, &o.path_flow}) {
        if (f->solver == CurvatureFlowSolver::ceres)
            bad("the ceres flow solver is for meshes only; use an Eigen solver on point sets");
        if (!std::isfinite(f->step) || !(f->step > 0) || !std::isfinite(f->tolerance) ||
            f->tolerance < 0 || !std::isfinite(f->update_tolerance) || f->update_tolerance < 0 ||
            !std::isfinite(f->endpoint_weight) || !(f->endpoint_weight > 0))
            bad("flow options: step and endpoint_weight must be finite and > 0, tolerances "
                "finite and >= 0");
    }
    if (D < 2)
        bad("points need at least 2 coordinates (got " + std::to_string(D) + ")");
    if (D > kMaxGridDimension)
        bad("points in R^" + std::to_string(D) +
            ": the grid adjacency supports D <= " + std::to_string(kMaxGridDimension));
    if (o.manifold_dimension >= D)
        bad("manifold_dimension " + std::to_string(o.manifold_dimension) +
            " must be below the ambient dimension " + std::to_string(D));
    if (n < o.neighbours + 1)
        bad(std::to_string(n) +
            " points, fewer than neighbours + 1 = " + std::to_string(o.neighbours + 1));
    if (n >= kNone / 2)
        bad("too many points (32-bit indices)");
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < D; ++j)
            if (!std::isfinite(pr.xyz[D * i + j]))
                bad("point #" + std::to_string(i) + " has a non-finite coordinate");
    if (!pr.normals.empty()) {
        for (std::size_t i = 0; i < n; ++i) {
            double s = 0;
            for (std::size_t j = 0; j < D; ++j)
                s += pr.normals[D * i + j] * pr.normals[D * i + j];
            if (!(s > 0) || !std::isfinite(s))
                bad("normal #" + std::to_string(i) + " is zero or not finite");
        }
    }
    pr.d = o.neighbours;
    PointCloudDistanceReport& r = pr.report;
    r.points = n;
    r.dimension = D;
    r.neighbours = pr.d;
    r.window = o.window;
    r.projection = to_string(o.projection);

    // kNN graph (d nearest, itself included), and duplicates: a point whose second nearest is at
    // distance 0.
    const PointCloudKnn backend = knn::resolve(o.knn, where);
    r.knn = to_string(backend);
    const auto tk = Clock::now();
    std::vector<double> d2;
    const knn::PointArray arr{n, D, pr.xyz.data()};
    knn::knn_graph(arr, arr, pr.d, backend, pr.knn, d2);
    r.knn_seconds = since(tk);
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = 0; j < pr.d; ++j) {
            const std::uint32_t q = pr.knn[i * pr.d + j];
            if (q != i && d2[i * pr.d + j] == 0)
                bad("points #" + std::to_string(std::min<std::size_t>(i, q)) + " and #" +
                    std::to_string(std::max<std::size_t>(i, q)) + " coincide (duplicate points)");
        }
        // Ties at distance 0 may list the point itself later; put it first.
        for (std::size_t j = 1; j < pr.d; ++j)
            if (pr.knn[i * pr.d + j] == i)
                std::swap(pr.knn[i * pr.d + j], pr.knn[i * pr.d]);
    }

    // Manifold dimension: per sampled neighbourhood, the index of the largest eigenvalue ratio
    // lambda_j / lambda_{j+1} among the eigenvalues above 5 % of the largest (so that a tiny
    // curvature or noise eigenvalue against an exactly zero one does not win); the median.
    std::size_t k = o.manifold_dimension;
    std::vector<double> spacing;
    {
        const std::size_t stride = std::max<std::size_t>(1, n / 256);
        std::vector<std::size_t> votes;
        for (std::size_t i = 0; i < n; i += stride) {
            Eigen::MatrixXd nb(static_cast<Eigen::Index>(D), static_cast<Eigen::Index>(pr.d));
            for (std::size_t j = 0; j < pr.d; ++j)
                for (std::size_t c = 0; c < D; ++c)
                    nb(static_cast<Eigen::Index>(c), static_cast<Eigen::Index>(j)) =
                        pr.xyz[D * pr.knn[i * pr.d + j] + c];
            spacing.push_back(std::sqrt(d2[i * pr.d + pr.d - 1]));
            if (k != 0)
                continue;
            const Eigen::VectorXd mean = nb.rowwise().mean();
            nb.colwise() -= mean;
            Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(nb * nb.transpose(),
                                                              Eigen::EigenvaluesOnly);
            const Eigen::VectorXd ev = es.eigenvalues().reverse();  // descending
            std::size_t best = 1;
            double best_ratio = -1;
            for (std::size_t j = 0; j + 1 < D; ++j) {
                const auto jj = static_cast<Eigen::Index>(j);
                if (ev(jj) < 0.05 * ev(0))
                    break;
                const double ratio = ev(jj) / std::max(ev(jj + 1), 1e-300);
                if (ratio > best_ratio) {
                    best_ratio = ratio;
                    best = j + 1;
                }
            }
            votes.push_back(best);
        }
        if (k == 0) {
            std::nth_element(votes.begin(),
                             votes.begin() + static_cast<std::ptrdiff_t>(votes.size() / 2),
                             votes.end());
            k = votes[votes.size() / 2];
            r.manifold_dimension_estimated = true;
        }
    }
    pr.k = k;
    r.manifold_dimension = k;
    if (o.projection == PointCloudProjection::mls) {
        if (k > kMaxMlsDimension)
            bad("the mls projection supports manifold dimensions up to " +
                std::to_string(kMaxMlsDimension) + " (k = " + std::to_string(k) +
                "); use the plane projection");
        if (pr.d < mls_terms(k) + 2)
            bad("the mls projection of a " + std::to_string(k) + "-manifold needs at least " +
                std::to_string(mls_terms(k) + 2) + " neighbours (given " + std::to_string(pr.d) +
                ")");
    }
    if (!pr.normals.empty() && k + 1 != D)
        bad("a normal_map needs a hypersurface (manifold dimension " + std::to_string(D - 1) +
            "), the points have k = " + std::to_string(k));

    // Grid.
    const auto tg = Clock::now();
    std::nth_element(spacing.begin(),
                     spacing.begin() + static_cast<std::ptrdiff_t>(spacing.size() / 2),
                     spacing.end());
    pr.cell = o.cell_size > 0 ? o.cell_size : spacing[spacing.size() / 2];
    if (!(pr.cell > 0))
        bad("the points span no volume (cell size 0)");
    r.cell_size = pr.cell;
    pr.origin.assign(D, kInf);
    std::vector<double> hi(D, -kInf);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t c = 0; c < D; ++c) {
            pr.origin[c] = std::min(pr.origin[c], pr.xyz[D * i + c]);
            hi[c] = std::max(hi[c], pr.xyz[D * i + c]);
        }
    if (o.cell_size > 0) {
        double diagonal2 = 0;
        for (std::size_t c = 0; c < D; ++c)
            diagonal2 += (hi[c] - pr.origin[c]) * (hi[c] - pr.origin[c]);
        // Fewer than ~10 cells across leaves paths no room to bend: the distances would be
        // straight chords through the shape.
        if (pr.cell > 0.1 * std::sqrt(diagonal2))
            bad("cell size " + std::to_string(pr.cell) + " is more than a tenth of the extent of " +
                "the points (bounding-box diagonal " + std::to_string(std::sqrt(diagonal2)) +
                "): distances would be straight chords; give a smaller cell or 0 (automatic)");
    }
    // Mixed-radix key of the integer cell coordinates: exact (no collisions) while the grid has
    // fewer than 2^62 cells.
    std::vector<std::uint64_t> radix(D), stride(D);
    std::uint64_t total = 1;
    for (std::size_t c = 0; c < D; ++c) {
        const double cells = std::floor((hi[c] - pr.origin[c]) / pr.cell) + 1;
        if (!(cells < 4e18) ||
            static_cast<double>(total) * cells > static_cast<double>(std::uint64_t(1) << 62))
            bad("cell size " + std::to_string(pr.cell) +
                " is too small for the extent of the points (more than 2^62 grid cells)");
        radix[c] = static_cast<std::uint64_t>(cells);
        stride[c] = total;
        total *= radix[c];
    }
    std::vector<std::uint32_t> coord(n * D);
    std::unordered_map<std::uint64_t, std::uint32_t> cells;
    cells.reserve(n / 2 + 16);
    pr.point_node.resize(n);
    std::vector<std::uint32_t> node_first;  // a point of each node (its cell coordinates)
    for (std::size_t i = 0; i < n; ++i) {
        std::uint64_t key = 0;
        for (std::size_t c = 0; c < D; ++c) {
            auto q = static_cast<std::uint64_t>(
                std::floor((pr.xyz[D * i + c] - pr.origin[c]) / pr.cell));
            q = std::min(q, radix[c] - 1);
            coord[D * i + c] = static_cast<std::uint32_t>(q);
            key += q * stride[c];
        }
        const auto ins = cells.emplace(key, static_cast<std::uint32_t>(node_first.size()));
        if (ins.second)
            node_first.push_back(static_cast<std::uint32_t>(i));
        pr.point_node[i] = ins.first->second;
    }
    const std::size_t nodes = node_first.size();
    pr.node_start.assign(nodes + 1, 0);
    for (std::size_t i = 0; i < n; ++i)
        ++pr.node_start[pr.point_node[i] + 1];
    for (std::size_t v = 0; v < nodes; ++v)
        pr.node_start[v + 1] += pr.node_start[v];
    pr.node_points.resize(n);
    {
        std::vector<std::uint32_t> fill(pr.node_start.begin(), pr.node_start.end() - 1);
        for (std::size_t i = 0; i < n; ++i)
            pr.node_points[fill[pr.point_node[i]]++] = static_cast<std::uint32_t>(i);
    }
    // Adjacency: the non-empty cells among the 3^D - 1 around each.
    std::size_t offsets = 1;
    for (std::size_t c = 0; c < D; ++c)
        offsets *= 3;
    std::vector<std::vector<std::uint32_t>> adj(nodes);
    for (std::size_t v = 0; v < nodes; ++v) {
        const std::uint32_t* cv = &coord[D * node_first[v]];
        for (std::size_t off = 0; off < offsets; ++off) {
            std::size_t rest = off;
            std::uint64_t key = 0;
            bool inside = true, self = true;
            for (std::size_t c = 0; c < D && inside; ++c) {
                const int delta = static_cast<int>(rest % 3) - 1;
                rest /= 3;
                self = self && delta == 0;
                const std::int64_t q = static_cast<std::int64_t>(cv[c]) + delta;
                inside = q >= 0 && q < static_cast<std::int64_t>(radix[c]);
                key += static_cast<std::uint64_t>(q) * stride[c];
            }
            if (!inside || self)
                continue;
            const auto it = cells.find(key);
            if (it != cells.end())
                adj[v].push_back(it->second);
        }
        std::sort(adj[v].begin(), adj[v].end());
    }
    // Components of the node graph.
    std::vector<std::uint32_t> component(nodes, kNone);
    auto label_components = [&] {
        component.assign(nodes, kNone);
        std::uint32_t label = 0;
        std::vector<std::uint32_t> stack;
        for (std::size_t s = 0; s < nodes; ++s) {
            if (component[s] != kNone)
                continue;
            stack.assign(1, static_cast<std::uint32_t>(s));
            component[s] = label;
            while (!stack.empty()) {
                const std::uint32_t v = stack.back();
                stack.pop_back();
                for (const std::uint32_t w : adj[v])
                    if (component[w] == kNone) {
                        component[w] = label;
                        stack.push_back(w);
                    }
            }
            ++label;
        }
        return label;
    };
    // Where sampling is sparser than the cell size (the cell is a median spacing), a connected
    // surface can leave cells with no non-empty cell around them. The k-nearest-neighbour graph
    // still joins them: its shortest pairs between different grid components become node edges
    // (Kruskal over the components, so a grid graph that is already connected is unchanged and
    // only truly separate pieces stay separate).
    if (label_components() > 1) {
        struct Pair {
            double d2;
            std::uint32_t a, b;
        };
        std::vector<Pair> pairs;
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 1; j < pr.d; ++j) {
                const std::uint32_t q = pr.knn[i * pr.d + j];
                const std::uint32_t a = pr.point_node[i], b = pr.point_node[q];
                if (component[a] != component[b])
                    pairs.push_back({d2[i * pr.d + j], a, b});
            }
        std::sort(pairs.begin(), pairs.end(),
                  [](const Pair& x, const Pair& y) { return x.d2 < y.d2; });
        std::vector<std::uint32_t> parent(nodes);
        std::iota(parent.begin(), parent.end(), 0u);
        auto find = [&](std::uint32_t c) {
            while (parent[c] != c)
                c = parent[c] = parent[parent[c]];
            return c;
        };
        for (const Pair& e : pairs) {
            const std::uint32_t ca = find(component[e.a]), cb = find(component[e.b]);
            if (ca == cb)
                continue;
            parent[ca] = cb;
            adj[e.a].insert(std::lower_bound(adj[e.a].begin(), adj[e.a].end(), e.b), e.b);
            adj[e.b].insert(std::lower_bound(adj[e.b].begin(), adj[e.b].end(), e.a), e.a);
            ++r.bridged_components;
        }
        label_components();
    }
    pr.adj_start.assign(nodes + 1, 0);
    for (std::size_t v = 0; v < nodes; ++v)
        pr.adj_start[v + 1] = pr.adj_start[v] + static_cast<std::uint32_t>(adj[v].size());
    pr.adj.clear();
    pr.adj.reserve(pr.adj_start[nodes]);
    for (auto& a : adj)
        pr.adj.insert(pr.adj.end(), a.begin(), a.end());
    pr.component = std::move(component);
    r.nodes = nodes;
    r.node_edges = pr.adj.size() / 2;
    r.grid_seconds = since(tg);
    r.prepare_seconds = since(t0);
}

/// What a query gives back: per-point distances (empty for paths), or a path.
struct QueryResult {
    std::vector<double> d;
    std::vector<double> path;  ///< dim per sample
    double length = kInf;
    FlowCounts counts;
    std::size_t reached_nodes = 0;
    std::size_t charts = 0;
    double propagate_seconds = 0, interpolate_seconds = 0;
    std::string status = "ok";
};

class EngineBase {
public:
    virtual ~EngineBase() = default;
    virtual QueryResult distances(std::uint32_t source) const = 0;
    virtual QueryResult path(std::uint32_t from, std::uint32_t to) const = 0;
};

/// The flow and the propagation for samples in R^D with k-dimensional tangent spaces; D and K are
/// compile-time sizes (3 and 2 for surfaces in space) or Eigen::Dynamic.
template <int D, int K>
class Engine final : public EngineBase {
public:
    static constexpr int C = (D == Eigen::Dynamic || K == Eigen::Dynamic) ? Eigen::Dynamic : D - K;
    static constexpr int M = K == Eigen::Dynamic ? Eigen::Dynamic : 1 + K + K * (K + 1) / 2;
    using Vec = Eigen::Matrix<double, D, 1>;
    using Basis = Eigen::Matrix<double, D, K>;
    using Frame = Eigen::Matrix<double, D, D>;
    using Coords = Eigen::Matrix<double, K, 1>;
    using NVec = Eigen::Matrix<double, C, 1>;

    struct Sample {
        Vec p;
        Basis t;                      ///< orthonormal tangent basis at p
        std::uint32_t point = kNone;  ///< a nearest input point (chart)
    };
    struct Chart {
        Vec c;
        Frame frame;  ///< tangent columns first (descending variance), then the normal ones
        Eigen::Matrix<double, M, C> coef;  ///< MLS quadric: normal coords of (u / r)
        double r = 1;
    };

    Engine(const Prepared& pr, const PointCloudDistanceOptions& o)
        : pr_(pr),
          o_(o),
          dim_(static_cast<Eigen::Index>(pr.dim)),
          k_(static_cast<Eigen::Index>(pr.k)),
          spacing_(o.sample_spacing > 0 ? o.sample_spacing : pr.cell),
          mls_(o.projection == PointCloudProjection::mls) {
        charts_.reset(pr.n);
        const std::size_t nodes = pr.node_start.size() - 1;
        node_.resize(nodes);
        auto place = [&](std::size_t v) {
            Vec mean = Vec::Zero(dim_);
            const std::uint32_t b = pr.node_start[v], e = pr.node_start[v + 1];
            for (std::uint32_t j = b; j < e; ++j)
                mean += point(pr.node_points[j]);
            mean /= static_cast<double>(e - b);
            std::uint32_t best = pr.node_points[b];
            double best_d = kInf;
            for (std::uint32_t j = b; j < e; ++j) {
                const double dd = (point(pr.node_points[j]) - mean).squaredNorm();
                if (dd < best_d) {
                    best_d = dd;
                    best = pr.node_points[j];
                }
            }
            Sample s;
            s.p = mean;
            s.point = best;
            project(s);
            node_[v] = s;
        };
        knn::parallel_range(nodes, place);
    }

    QueryResult distances(std::uint32_t src) const override;
    QueryResult path(std::uint32_t from, std::uint32_t to) const override;

private:
    Vec point(std::size_t i) const { return Eigen::Map<const Vec>(pr_.at(i), dim_); }

    /// Greedy descent over the kNN graph to a point nearer to p than all its d neighbours.
    std::uint32_t walk(const Vec& p, std::uint32_t v) const {
        double best = (point(v) - p).squaredNorm();
        for (std::size_t guard = 0; guard < pr_.n; ++guard) {
            std::uint32_t next = v;
            for (std::size_t j = 1; j < pr_.d; ++j) {
                const std::uint32_t q = pr_.knn[v * pr_.d + j];
                const double dd = (point(q) - p).squaredNorm();
                if (dd < best) {
                    best = dd;
                    next = q;
                }
            }
            if (next == v)
                break;
            v = next;
        }
        return v;
    }

    /// Monomials of the quadric in u (k values) and their derivatives dm[t * k + j] = dm_t/du_j.
    void monomials(const Coords& u, double* m, double* dm) const {
        const auto k = static_cast<std::size_t>(k_);
        const std::size_t terms = mls_terms(k);
        std::fill(dm, dm + terms * k, 0.0);
        m[0] = 1;
        for (std::size_t j = 0; j < k; ++j) {
            m[1 + j] = u(static_cast<Eigen::Index>(j));
            dm[(1 + j) * k + j] = 1;
        }
        std::size_t t = 1 + k;
        for (std::size_t a = 0; a < k; ++a)
            for (std::size_t b = a; b < k; ++b, ++t) {
                const double ua = u(static_cast<Eigen::Index>(a)),
                             ub = u(static_cast<Eigen::Index>(b));
                m[t] = ua * ub;
                dm[t * k + a] += ub;
                dm[t * k + b] += ua;
            }
    }

    Chart make_chart(std::uint32_t i) const {
        Chart ch;
        const std::size_t d = pr_.d;
        ch.c = Vec::Zero(dim_);
        for (std::size_t j = 0; j < d; ++j)
            ch.c += point(pr_.knn[i * d + j]);
        ch.c /= static_cast<double>(d);
        Frame cov = Frame::Zero(dim_, dim_);
        double r2 = 0;
        for (std::size_t j = 0; j < d; ++j) {
            const Vec y = point(pr_.knn[i * d + j]) - ch.c;
            cov.noalias() += y * y.transpose();
            r2 = std::max(r2, y.squaredNorm());
        }
        ch.r = r2 > 0 ? std::sqrt(r2) : 1.0;
        if (!pr_.normals.empty()) {  // tangent space orthogonal to the given normal
            Vec nrm = Eigen::Map<const Vec>(pr_.normals.data() + pr_.dim * i, dim_);
            nrm.normalize();
            const Frame proj = Frame::Identity(dim_, dim_) - nrm * nrm.transpose();
            cov = proj * cov * proj;
        }
        Eigen::SelfAdjointEigenSolver<Frame> es(cov);
        ch.frame.resize(dim_, dim_);
        // Ascending eigenvalues: tangent = the k largest, in descending order, then the normals.
        for (Eigen::Index j = 0; j < dim_; ++j)
            ch.frame.col(j) = es.eigenvectors().col(dim_ - 1 - j);
        if (!mls_)
            return ch;
        const auto k = static_cast<std::size_t>(k_);
        const std::size_t terms = mls_terms(k);
        const Eigen::Index cn = dim_ - k_;
        Eigen::MatrixXd ata = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(terms),
                                                    static_cast<Eigen::Index>(terms));
        Eigen::MatrixXd aty = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(terms), cn);
        std::array<double, 64> m{};
        std::array<double, 64 * kMaxMlsDimension> dm{};
        const auto tangent = ch.frame.leftCols(k_);
        const auto normal = ch.frame.rightCols(cn);
        for (std::size_t j = 0; j < d; ++j) {
            const Vec y = point(pr_.knn[i * d + j]) - ch.c;
            const Coords u = (tangent.transpose() * y) / ch.r;
            const Eigen::VectorXd h = normal.transpose() * y;
            const double w = std::exp(-2.0 * y.squaredNorm() / r2);
            monomials(u, m.data(), dm.data());
            const Eigen::Map<const Eigen::VectorXd> mv(m.data(), static_cast<Eigen::Index>(terms));
            ata.noalias() += w * mv * mv.transpose();
            aty.noalias() += w * mv * h.transpose();
        }
        ata.diagonal().array() += 1e-12 * ata.trace();
        const Eigen::MatrixXd coef = ata.ldlt().solve(aty);
        ch.coef = coef;
        return ch;
    }

    /// Calls f(chart of point i), fitting and keeping the chart on first use.
    template <class F>
    void with_chart(std::uint32_t i, const F& f) const {
        if (const Chart* c = charts_.find(i)) {
            f(*c);
            return;
        }
        const Chart c = make_chart(i);
        charts_.put(i, c);
        f(c);
    }

    static void orthonormalise(Basis& t) {
        for (Eigen::Index j = 0; j < t.cols(); ++j) {
            for (Eigen::Index l = 0; l < j; ++l)
                t.col(j) -= t.col(l).dot(t.col(j)) * t.col(l);
            t.col(j).normalize();
        }
    }

    /// Moves s onto the local surface of its nearest input point and sets its tangent basis.
    void project(Sample& s) const {
        s.point = walk(s.p, s.point);
        with_chart(s.point, [&](const Chart& ch) {
            const auto tangent = ch.frame.template leftCols<K>(k_);
            const Vec y = s.p - ch.c;
            const Coords u = tangent.transpose() * y;
            if (!mls_) {
                s.p = ch.c + tangent * u;
                s.t = tangent;
                return;
            }
            const auto normal = ch.frame.template rightCols<C>(dim_ - k_);
            const auto k = static_cast<std::size_t>(k_);
            const std::size_t terms = mls_terms(k);
            std::array<double, 64> m{};
            std::array<double, 64 * kMaxMlsDimension> dm{};
            monomials(Coords(u / ch.r), m.data(), dm.data());
            NVec h = NVec::Zero(dim_ - k_);
            Eigen::Matrix<double, C, K> jac = Eigen::Matrix<double, C, K>::Zero(dim_ - k_, k_);
            for (std::size_t t = 0; t < terms; ++t) {
                const auto row = ch.coef.row(static_cast<Eigen::Index>(t)).transpose();
                h += m[t] * row;
                for (std::size_t j = 0; j < k; ++j)
                    jac.col(static_cast<Eigen::Index>(j)) += (dm[t * k + j] / ch.r) * row;
            }
            s.p = ch.c + tangent * u + normal * h;
            s.t = tangent + normal * jac;
            orthonormalise(s.t);
        });
    }

    Vec tangent_dir(const Sample& s, const Vec& v) const {
        const Vec t = s.t * (s.t.transpose() * v);
        const double len = t.norm();
        return len > 0 ? Vec(t / len) : Vec(Vec::Zero(dim_));
    }

    static double length_of(const std::vector<Sample>& s, std::size_t from, std::size_t to) {
        double len = 0;
        for (std::size_t i = from + 1; i <= to; ++i)
            len += (s[i].p - s[i - 1].p).norm();
        return len;
    }

    /// max |T_iᵀ second difference| over the interior samples.
    static double curvature(const std::vector<Sample>& s) {
        double kmax = 0;
        for (std::size_t i = 1; i + 1 < s.size(); ++i)
            kmax = std::max(kmax,
                            (s[i].t.transpose() * (s[i - 1].p - 2 * s[i].p + s[i + 1].p)).norm());
        return kmax;
    }

    /// The flow of gcf_engine.h (solve_tangent_step) on s, endpoints fixed, until converged,
    /// stalled or max_iterations (as flow_to_convergence does on meshes).
    void flow(std::vector<Sample>& s, FlowCounts& counts, bool whole_path = false) const {
        ++counts.flows;
        if (s.size() < 3) {
            ++counts.converged;
            return;
        }
        const CurvatureFlowOptions& o = whole_path ? o_.path_flow : o_.flow;
        const double h = spacing_;
        auto scaled = [&](double kmax) {
            const double dh = length_of(s, 0, s.size() - 1) / static_cast<double>(s.size() - 1);
            return dh > 0 ? kmax / (dh * dh) * h : 0.0;
        };
        if (scaled(curvature(s)) <= o.tolerance) {
            ++counts.converged;
            return;
        }
        const std::size_t n = s.size();
        std::vector<Basis> t(n);
        Eigen::VectorXd x;
        const auto pos = [&s](std::size_t i) -> const Vec& { return s[i].p; };
        for (std::size_t it = 0; it < o.max_iterations; ++it) {
            for (std::size_t i = 0; i < n; ++i)
                t[i] = s[i].t;
            if (!solve_tangent_step<D, K>(n, pos, t, k_, o, o.step, x) || !x.allFinite()) {
                ++counts.failed;
                return;
            }
            ++counts.iterations;
            double upd = 0;
            for (std::size_t i = 1; i + 1 < n; ++i) {
                const Vec before = s[i].p;
                s[i].p += t[i] * x.template segment<K>(k_ * static_cast<Eigen::Index>(i), k_);
                project(s[i]);
                upd = std::max(upd, (s[i].p - before).norm());
            }
            if (scaled(curvature(s)) <= o.tolerance) {
                ++counts.converged;
                return;
            }
            if (upd <= o.update_tolerance * h) {
                ++counts.stalled;
                return;
            }
        }
        ++counts.max_iterations;
    }

    /// Appends the chord from the last sample of c to q (a sample on the surface), subdivided at
    /// the spacing, the intermediate samples projected.
    void append_chord(std::vector<Sample>& c, const Sample& q) const {
        const Sample a = c.back();
        const double len = (q.p - a.p).norm();
        const std::size_t pieces =
            std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(len / spacing_ - 1e-9)));
        std::uint32_t hint = a.point;
        for (std::size_t j = 1; j < pieces; ++j) {
            Sample s;
            s.p = a.p + (static_cast<double>(j) / static_cast<double>(pieces)) * (q.p - a.p);
            s.point = hint;
            project(s);
            hint = s.point;
            c.push_back(s);
        }
        c.push_back(q);
    }

    const Prepared& pr_;
    PointCloudDistanceOptions o_;
    Eigen::Index dim_, k_;
    double spacing_;
    bool mls_;
    std::vector<Sample> node_;
    LazySlots<Chart> charts_;
};

// -------------------------------------------------------------------------------------------------

template <int D, int K>
QueryResult Engine<D, K>::distances(std::uint32_t src_point) const {
    const auto t0 = Clock::now();
    const Prepared& pr = pr_;
    const std::size_t nodes = node_.size();
    const std::size_t window = o_.window;
    const std::size_t near_source =
        o_.near_source_samples > 0 ? o_.near_source_samples : 2 * window + 1;
    QueryResult out;
    // The source node is the source point (projected onto its local surface).
    const std::uint32_t src = pr.point_node[src_point];
    Sample source;
    source.p = point(src_point);
    source.point = src_point;
    project(source);
    auto node = [&](std::uint32_t v) -> const Sample& { return v == src ? source : node_[v]; };

    auto position = [&node](std::uint32_t v) -> const Vec& { return node(v).p; };
    Wavefront<Sample, Vec, decltype(position)> wf(pr.adj_start, pr.adj, position,
                                                  Vec(Vec::Zero(dim_)));
    std::vector<double>& d = wf.d;
    std::vector<double>& prefix = wf.prefix;
    std::vector<Vec>& arrival = wf.arrival;
    std::vector<std::vector<Sample>>& tail = wf.tail;
    std::vector<char>& visited = wf.visited;
    std::vector<char>& whole_path = wf.whole_path;
    visited[src] = 1;
    d[src] = 0;
    whole_path[src] = 1;
    tail[src] = {source};
    wf.relax(src);

    // Distance at x (a sample with its tangent basis) interpolated from the visited nodes of its
    // cell and the cells around: d_v + (g_v + g_x) . (x - v) / 2 (the trapezoid rule along the
    // chord, second order), weights 1 / |x - v|^2. g_x is `dir` when given (the direction the
    // flowed window leaves x in), else the weighted mean of the g_v, returned in grad. Within
    // four cells of the source: |x - (v - d_v g_v)| (see below). The source itself: |x - s|.
    const double near_source_field = 4 * pr.cell;
    auto field_at = [&](const Sample& x, const Vec* dir, Vec* grad) {
        const std::uint32_t c = pr.point_node[x.point];
        Vec gsum = Vec::Zero(dim_);
        double wsum = 0;
        auto each = [&](const auto& f) {
            f(c);
            for (std::uint32_t j = pr.adj_start[c]; j < pr.adj_start[c + 1]; ++j)
                f(pr.adj[j]);
        };
        each([&](std::uint32_t v) {
            if (!visited[v] || v == src || !std::isfinite(d[v]))
                return;
            const double w = 1.0 / ((x.p - node(v).p).squaredNorm() + 1e-12 * pr.cell * pr.cell);
            gsum += w * arrival[v];
            wsum += w;
        });
        const Vec gx = dir ? *dir : tangent_dir(x, gsum);
        if (grad)
            *grad = tangent_dir(x, gsum);
        double sum = 0;
        wsum = 0;
        each([&](std::uint32_t v) {
            if (!visited[v] || !std::isfinite(d[v]))
                return;
            const Vec dx = x.p - node(v).p;
            const double w = 1.0 / (dx.squaredNorm() + 1e-12 * pr.cell * pr.cell);
            // Near the source the field is too curved for the trapezoid rule (the arrival
            // directions turn by a large angle over a cell): there the distance from the virtual
            // source v - d_v g_v, exact for a point source in the plane, is used instead.
            const double est = v == src                   ? dx.norm()
                               : d[v] < near_source_field ? (d[v] * arrival[v] + dx).norm()
                                                          : d[v] + 0.5 * (arrival[v] + gx).dot(dx);
            sum += w * est;
            wsum += w;
        });
        return wsum > 0 ? sum / wsum : kInf;
    };

    auto flow_part = [&](std::vector<Sample>& c, std::size_t start, FlowCounts& counts) {
        std::vector<Sample> part(c.begin() + static_cast<std::ptrdiff_t>(start), c.end());
        flow(part, counts);
        std::copy(part.begin(), part.end(), c.begin() + static_cast<std::ptrdiff_t>(start));
    };
    // The anchor c[start] slid sideways until the window leaves it in the field's direction (as on
    // meshes); returns its interpolated distance.
    auto slide_anchor = [&](std::vector<Sample>& c, std::size_t start, FlowCounts& counts) {
        Sample& a = c[start];
        Vec t_in;
        double da = field_at(a, nullptr, &t_in);
        for (std::size_t it = 0; it < o_.anchor_slides && std::isfinite(da); ++it) {
            const Vec t_out = tangent_dir(a, c[start + 1].p - a.p);
            if (t_in.squaredNorm() == 0 || t_out.squaredNorm() == 0)
                break;
            const double len = length_of(c, start, c.size() - 1);
            const Vec shift = (t_out - t_out.dot(t_in) * t_in) * (da * len / (da + len));
            if (shift.norm() <= 1e-9 * pr.cell)
                break;
            a.p += shift;
            project(a);
            flow_part(c, start, counts);
            da = field_at(a, nullptr, &t_in);
        }
        if (!std::isfinite(da))
            return da;
        const Vec t_out = tangent_dir(a, c[start + 1].p - a.p);
        return field_at(a, &t_out, nullptr);
    };

    struct Solved {
        std::vector<Sample> c;
        double len = kInf;
        std::uint32_t chosen = kNone;
        bool whole = false;
        FlowCounts counts;
    };
    auto solve = [&](std::uint32_t w, Solved& r) {
        // The straightest continuation, plus the cut-locus guard, as on meshes.
        bool next_to_source = false;
        std::vector<std::uint32_t> parents = wf.visited_neighbours(w, src, &next_to_source);
        if (next_to_source) {
            parents.assign(1, src);
        } else {
            const std::uint32_t best_u = wf.straightest(w, parents);
            parents = o_.cut_locus_guard ? wf.guarded(w, best_u, parents)
                                         : std::vector<std::uint32_t>{best_u};
        }
        std::vector<Sample> c;
        for (const std::uint32_t u : parents) {
            c = tail[u];
            append_chord(c, node(w));
            const bool whole = window == 0 || (whole_path[u] && c.size() <= near_source);
            const std::size_t start = whole ? 0 : c.size() - (window + 1);
            flow_part(c, start, r.counts);
            double len;
            if (start > 0) {
                const double da = slide_anchor(c, start, r.counts);
                len = std::isfinite(da) ? da + length_of(c, start, c.size() - 1)
                                        : prefix[u] + length_of(c, 0, c.size() - 1);
            } else {
                len = prefix[u] + length_of(c, 0, c.size() - 1);
            }
            if (len < r.len) {
                r.len = len;
                r.c.swap(c);
                r.chosen = u;
                r.whole = whole;
            }
        }
    };
    auto commit = [&](std::uint32_t w, Solved& r) {
        std::vector<Sample>& c = r.c;
        const std::size_t first = window_start(c.size(), window, r.whole);
        prefix[w] = prefix[r.chosen] + (first > 0 ? length_of(c, 0, first) : 0.0);
        d[w] = r.len;
        whole_path[w] = r.whole ? 1 : 0;
        arrival[w] = tangent_dir(c.back(), c.back().p - c[c.size() - 2].p);
        wf.store(w, c, first);
        out.counts.add(r.counts);
        wf.relax(w);
    };

    Progress progress("gcf point-cloud distances: nodes", nodes);
    wf.template run<Solved>(solve, commit, progress);
    out.propagate_seconds = since(t0);
    for (std::size_t v = 0; v < nodes; ++v)
        out.reached_nodes += std::isfinite(d[v]) ? 1 : 0;

    // Every input point from the nodes of its cell and the cells around.
    const auto t1 = Clock::now();
    out.d.assign(pr.n, kInf);
    knn::parallel_range(pr.n, [&](std::size_t i) {
        if (!visited[pr.point_node[i]])
            return;
        Sample x;
        x.p = point(i);
        x.point = static_cast<std::uint32_t>(i);
        // The tangent space of the nearest node (no chart fitted per input point).
        x.t = node(pr.point_node[i]).t;
        out.d[i] = field_at(x, nullptr, nullptr);
    });
    out.d[src_point] = 0;
    out.interpolate_seconds = since(t1);
    for (std::size_t i = 0; i < pr.n; ++i)
        out.charts += charts_.find(i) ? 1 : 0;
    return out;
}

template <int D, int K>
QueryResult Engine<D, K>::path(std::uint32_t from, std::uint32_t to) const {
    const auto t0 = Clock::now();
    const Prepared& pr = pr_;
    QueryResult out;
    const std::uint32_t na = pr.point_node[from], nb = pr.point_node[to];
    if (pr.component[na] != pr.component[nb]) {
        out.status = "unreachable";
        return out;
    }
    Sample a, b;
    a.p = point(from);
    a.point = from;
    project(a);
    b.p = point(to);
    b.point = to;
    project(b);
    // Dijkstra over the nodes for the initial polyline.
    std::vector<double> dist;
    std::vector<std::uint32_t> pred;
    dijkstra_to(
        pr.adj_start, pr.adj, na, nb,
        [this](std::uint32_t v, std::uint32_t w) { return (node_[w].p - node_[v].p).norm(); }, dist,
        pred);
    std::vector<std::uint32_t> chain;
    for (std::uint32_t v = pred[nb]; v != kNone && v != na; v = pred[v])
        chain.push_back(v);
    std::reverse(chain.begin(), chain.end());
    std::vector<Sample> c{a};
    for (const std::uint32_t v : chain)
        append_chord(c, node_[v]);
    append_chord(c, b);
    flow(c, out.counts, true);
    out.status = out.counts.converged ? "converged"
                 : out.counts.stalled ? "stalled"
                 : out.counts.failed  ? "solver_failure"
                                      : "max_iterations";
    out.path.reserve(c.size() * pr.dim);
    for (const Sample& s : c)
        for (Eigen::Index j = 0; j < dim_; ++j)
            out.path.push_back(s.p(j));
    out.length = length_of(c, 0, c.size() - 1);
    out.propagate_seconds = since(t0);
    return out;
}

/// The engine for the dimensions of pr: fixed-size Eigen types for surfaces in space.
inline std::unique_ptr<EngineBase> make_engine(const Prepared& pr,
                                               const PointCloudDistanceOptions& o) {
    if (pr.dim == 3 && pr.k == 2)
        return std::make_unique<Engine<3, 2>>(pr, o);
    return std::make_unique<Engine<Eigen::Dynamic, Eigen::Dynamic>>(pr, o);
}

}  // namespace tapeline::geodesic::internal::gcf::points
