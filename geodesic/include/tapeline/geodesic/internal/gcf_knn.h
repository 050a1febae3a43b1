// k-nearest-neighbour graphs of point sets in R^D for the point-cloud flow (gcf_points.h): CGAL
// Spatial_searching (Kd_tree, Orthogonal_k_neighbor_search) over D-dimensional search traits that
// read the caller's flat coordinate array, and nanoflann (Debian libnanoflann-dev) when its header
// is available. Both answer the same question; the README says which is faster and by how much.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/geodesic/point_cloud_types.h>

#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits.h>

#include <cstdint>
#include <string>
#include <vector>

#if __has_include(<nanoflann.hpp>) && !defined(TAPELINE_NO_NANOFLANN)
#include <nanoflann.hpp>
#define TAPELINE_HAS_NANOFLANN 1
#endif

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

namespace tapeline::geodesic::internal::gcf::knn {

/// n points of dimension dim, stored contiguously (point i is [dim i, dim i + dim)).
struct PointArray {
    std::size_t n = 0, dim = 0;
    const double* xyz = nullptr;
    const double* at(std::size_t i) const { return xyz + dim * i; }
};

inline bool nanoflann_available() {
#ifdef TAPELINE_HAS_NANOFLANN
    return true;
#else
    return false;
#endif
}

/// The backend `requested` resolves to; InvalidInput for nanoflann when it was not compiled in.
inline PointCloudKnn resolve(PointCloudKnn requested, const char* where) {
    if (requested == PointCloudKnn::automatic)
        return nanoflann_available() ? PointCloudKnn::nanoflann : PointCloudKnn::cgal;
    if (requested == PointCloudKnn::nanoflann && !nanoflann_available())
        throw InvalidInput(std::string(where) +
                           ": knn nanoflann requested but <nanoflann.hpp> was not found at compile "
                           "time (Debian package libnanoflann-dev)");
    return requested;
}

// --- CGAL: a point is a pointer into the array, its end is dim further -------------------------
struct CgalPoint {
    const double* p = nullptr;
    std::uint32_t dim = 0;
    std::uint32_t index = 0;
};
struct CgalCoordinates {
    using result_type = const double*;
    const double* operator()(const CgalPoint& q) const { return q.p; }
    const double* operator()(const CgalPoint& q, int) const { return q.p + q.dim; }
};
using CgalTraits = CGAL::Search_traits<double, CgalPoint, const double*, CgalCoordinates,
                                       CGAL::Dynamic_dimension_tag>;
using CgalSearch = CGAL::Orthogonal_k_neighbor_search<CgalTraits>;

// --- nanoflann
// -------------------------------------------------------------------------------------
#ifdef TAPELINE_HAS_NANOFLANN
struct NanoAdaptor {
    const PointArray* a = nullptr;
    std::size_t kdtree_get_point_count() const { return a->n; }
    double kdtree_get_pt(std::size_t i, std::size_t d) const { return a->xyz[a->dim * i + d]; }
    template <class Box>
    bool kdtree_get_bbox(Box&) const {
        return false;
    }
};
using NanoTree =
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, NanoAdaptor>,
                                        NanoAdaptor, -1, std::uint32_t>;
#endif

template <class F>
void parallel_range(std::size_t n, const F& f) {
#ifdef CGAL_LINKED_WITH_TBB
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 256),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                          for (std::size_t i = r.begin(); i != r.end(); ++i)
                              f(i);
                      });
#else
    for (std::size_t i = 0; i < n; ++i)
        f(i);
#endif
}

/// For every query point, the indices of its k nearest points of `data` (itself included when it
/// is one of them), nearest first; out has k entries per query (k <= data.n) and d2 their squared
/// distances. Queries run in parallel (TBB); the result does not depend on the thread count.
inline void knn_graph(const PointArray& data, const PointArray& queries, std::size_t k,
                      PointCloudKnn backend, std::vector<std::uint32_t>& out,
                      std::vector<double>& d2) {
    out.assign(queries.n * k, 0);
    d2.assign(queries.n * k, 0.0);
    if (backend == PointCloudKnn::cgal) {
        std::vector<CgalPoint> pts(data.n);
        for (std::size_t i = 0; i < data.n; ++i)
            pts[i] = {data.at(i), static_cast<std::uint32_t>(data.dim),
                      static_cast<std::uint32_t>(i)};
        CgalSearch::Tree tree(pts.begin(), pts.end());
        tree.build();  // before the concurrent queries (the tree builds lazily otherwise)
        parallel_range(queries.n, [&](std::size_t q) {
            const CgalPoint query{queries.at(q), static_cast<std::uint32_t>(queries.dim), 0};
            CgalSearch search(tree, query, static_cast<unsigned int>(k));
            std::size_t j = 0;
            for (auto it = search.begin(); it != search.end() && j < k; ++it, ++j) {
                out[q * k + j] = it->first.index;
                d2[q * k + j] = it->second;
            }
        });
        return;
    }
#ifdef TAPELINE_HAS_NANOFLANN
    NanoAdaptor adaptor{&data};
    NanoTree tree(data.dim, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(10));
    parallel_range(queries.n, [&](std::size_t q) {
        tree.knnSearch(queries.at(q), k, out.data() + q * k, d2.data() + q * k);
    });
#endif
}

}  // namespace tapeline::geodesic::internal::gcf::knn
