// Compact storage of a pattern: coordinates quantised to a fixed grid (0.001 mm by default),
// written as zig-zag varint deltas, beside the rest of the model in CBOR, the whole compressed
// with zstd. This is the "pattern data compression" of the pattern-database literature:
// quantisation + delta coding + an entropy coder.
//
// How it works. The model goes through its JSON form (io_json.h) so that every field is kept.
// A copy of the pattern has its lengths rounded to the grid (edge points, named points, grain,
// notch offsets, internal lines, darts, fold, 3D translation; not arc radii, rotations or
// measurements, which stay exact). An edge whose rounded form moves more than `max_error_mm` from
// the original (an arc near a half circle: its centre moves by √(2·r·δ) when the chord changes by
// δ) keeps its exact coordinates. Every JSON float that is exactly k / units_per_mm goes to the
// integer stream as k (delta to the number two places back, so x follows x and y follows y);
// other floats stay in the CBOR skeleton bit for bit. Decoding reverses this exactly, so
// decode(encode(p)) equals the rounded copy, and its outline edges are within `max_error_mm` of
// the original at equal curve parameters.
//
// Blob layout: "TPZ" + format byte (1), then one zstd frame holding
// varint(units_per_mm) varint(|skeleton|) skeleton(CBOR) varint(n) n × zigzag-varint.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/pattern/io_json.h>
#include <tapeline/pattern/pattern.h>

#include <zstd.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace tapeline::pattern {

/// How patterns are quantised and compressed.
struct CompressionOptions {
    std::int64_t units_per_mm = 1000;  ///< grid of 1/units_per_mm mm (0.001 mm)
    int zstd_level = 19;               ///< zstd compression level
    double max_error_mm = 0.005;       ///< an edge moving more than this keeps exact coordinates
    bool measure_plain_zstd = false;   ///< also compress the plain JSON, for the report only
};

/// Sizes and error of one compressed pattern.
struct CompressionReport {
    std::size_t json_bytes = 0;       ///< compact JSON (io_json.h, no indentation)
    std::size_t json_zstd_bytes = 0;  ///< that JSON through zstd alone (measure_plain_zstd)
    std::size_t stored_bytes = 0;     ///< the blob
    double ratio = 0;                 ///< json_bytes / stored_bytes
    double max_error_mm = 0;          ///< largest edge deviation of the stored geometry
    /// Numbers stored on the grid, numbers kept exact, and edges kept exact.
    ///@{
    std::size_t quantised_numbers = 0, exact_numbers = 0, exact_edges = 0;
    ///@}
    double seconds = 0;  ///< wall-clock time
};

inline constexpr std::uint8_t pattern_blob_format = 1;

/// Largest distance between corresponding points (equal curve parameter, 33 per edge) of the
/// outline edges, internal lines and darts of two patterns with the same structure; +inf when
/// the structures differ.
inline double max_edge_deviation(const Pattern& a, const Pattern& b);

namespace internal {

inline double edge_deviation(const Edge& a, const Edge& b) {
    if (a.curve.index() != b.curve.index()) {
        return std::numeric_limits<double>::infinity();
    }
    double d = 0;
    for (int k = 0; k <= 32; ++k) {
        d = std::max(d, distance(point_at(a.curve, k / 32.0), point_at(b.curve, k / 32.0)));
    }
    return d;
}

inline double edges_deviation(const std::vector<Edge>& a, const std::vector<Edge>& b) {
    if (a.size() != b.size()) {
        return std::numeric_limits<double>::infinity();
    }
    double d = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        d = std::max(d, edge_deviation(a[i], b[i]));
    }
    return d;
}

struct Quantiser {
    double scale;  // units per mm
    double q(double x) const { return std::round(x * scale) / scale; }
    Point2 q(const Point2& p) const { return {q(p.x), q(p.y)}; }
    Curve q(const Curve& c) const {
        if (const auto* l = std::get_if<Line>(&c)) {
            return Line{q(l->a), q(l->b)};
        }
        if (const auto* b = std::get_if<CubicBezier>(&c)) {
            return CubicBezier{q(b->p0), q(b->p1), q(b->p2), q(b->p3)};
        }
        Arc a = std::get<Arc>(c);
        a.a = q(a.a);
        a.b = q(a.b);
        return a;
    }
    /// Rounds each edge, keeping it exact when rounding moves it more than `tol`.
    void edges(std::vector<Edge>& es, double tol, double& max_err, std::size_t& exact) const {
        for (Edge& e : es) {
            Edge r{q(e.curve), e.label};
            const double d = edge_deviation(e, r);
            if (d <= tol) {
                max_err = std::max(max_err, d);
                e = std::move(r);
            } else {
                ++exact;
            }
        }
    }
};

inline void put_varint(std::vector<std::uint8_t>& out, std::uint64_t v) {
    while (v >= 0x80) {
        out.push_back(static_cast<std::uint8_t>(v | 0x80));
        v >>= 7;
    }
    out.push_back(static_cast<std::uint8_t>(v));
}

struct ByteReader {
    const std::uint8_t* p;
    const std::uint8_t* end;
    const std::string& where;
    std::uint64_t varint() {
        std::uint64_t v = 0;
        for (int shift = 0; shift < 64; shift += 7) {
            if (p == end) {
                throw InvalidInput(where + ": compressed pattern is truncated");
            }
            const std::uint8_t b = *p++;
            v |= std::uint64_t(b & 0x7f) << shift;
            if (!(b & 0x80)) {
                return v;
            }
        }
        throw InvalidInput(where + ": compressed pattern holds a malformed number");
    }
};

inline std::uint64_t zigzag(std::int64_t v) {
    return (static_cast<std::uint64_t>(v) << 1) ^ static_cast<std::uint64_t>(v >> 63);
}
inline std::int64_t unzigzag(std::uint64_t v) {
    return static_cast<std::int64_t>(v >> 1) ^ -static_cast<std::int64_t>(v & 1);
}

/// Moves grid numbers out of `j` into `ks` (replacing them by null), depth first in key order.
inline void extract_grid_numbers(Json& j, double scale, std::vector<std::int64_t>& ks,
                                 std::size_t& exact) {
    if (j.is_object() || j.is_array()) {
        for (auto& v : j) {
            extract_grid_numbers(v, scale, ks, exact);
        }
    } else if (j.is_number_float()) {
        const double x = j.get<double>();
        const double r = std::round(x * scale);
        if (std::abs(r) < 9e15 && r / scale == x) {
            ks.push_back(static_cast<std::int64_t>(r));
            j = nullptr;
        } else {
            ++exact;
        }
    } else if (j.is_null()) {
        throw std::logic_error("compress_pattern: the pattern JSON holds a null");
    }
}

inline void restore_grid_numbers(Json& j, double scale, const std::vector<std::int64_t>& ks,
                                 std::size_t& next, const std::string& where) {
    if (j.is_object() || j.is_array()) {
        for (auto& v : j) {
            restore_grid_numbers(v, scale, ks, next, where);
        }
    } else if (j.is_null()) {
        if (next >= ks.size()) {
            throw InvalidInput(where + ": compressed pattern has too few coordinates");
        }
        j = double(ks[next++]) / scale;
    }
}

}  // namespace internal

inline double max_edge_deviation(const Pattern& a, const Pattern& b) {
    if (a.pieces.size() != b.pieces.size()) {
        return std::numeric_limits<double>::infinity();
    }
    double d = 0;
    for (std::size_t i = 0; i < a.pieces.size(); ++i) {
        const Piece &pa = a.pieces[i], &pb = b.pieces[i];
        d = std::max(d, internal::edges_deviation(pa.outline.edges, pb.outline.edges));
        if (pa.internal_lines.size() != pb.internal_lines.size() ||
            pa.darts.size() != pb.darts.size()) {
            return std::numeric_limits<double>::infinity();
        }
        for (std::size_t k = 0; k < pa.internal_lines.size(); ++k) {
            d = std::max(d, internal::edges_deviation(pa.internal_lines[k].edges,
                                                      pb.internal_lines[k].edges));
        }
        for (std::size_t k = 0; k < pa.darts.size(); ++k) {
            d = std::max(d, internal::edges_deviation(pa.darts[k].edges, pb.darts[k].edges));
        }
    }
    return d;
}

/// The pattern with its lengths rounded to the grid as compress_pattern stores them.
///
/// \throws InvalidInput when `o.units_per_mm` is outside 1..1e9.
inline Pattern quantised_pattern(const Pattern& p, const CompressionOptions& o = {},
                                 CompressionReport* report = nullptr) {
    if (o.units_per_mm < 1 || o.units_per_mm > 1000000000) {
        throw InvalidInput("pattern compression: units_per_mm " + std::to_string(o.units_per_mm) +
                           " is outside 1..1e9");
    }
    const internal::Quantiser qz{double(o.units_per_mm)};
    Pattern out = p;
    double err = 0;
    std::size_t exact = 0;
    for (Piece& piece : out.pieces) {
        qz.edges(piece.outline.edges, o.max_error_mm, err, exact);
        for (InternalLine& l : piece.internal_lines) {
            qz.edges(l.edges, o.max_error_mm, err, exact);
        }
        for (Dart& d : piece.darts) {
            qz.edges(d.edges, o.max_error_mm, err, exact);
        }
        for (auto& [name, pt] : piece.points) {
            pt = qz.q(pt);
        }
        if (piece.grain) {
            piece.grain = GrainLine{qz.q(piece.grain->from), qz.q(piece.grain->to)};
        }
        for (Notch& n : piece.notches) {
            n.offset = qz.q(n.offset);
        }
        if (piece.fold) {
            piece.fold->line = Line{qz.q(piece.fold->line.a), qz.q(piece.fold->line.b)};
        }
        if (piece.placement) {
            for (double& t : piece.placement->translation) {
                t = qz.q(t);
            }
        }
    }
    if (report) {
        report->max_error_mm = err;
        report->exact_edges = exact;
    }
    return out;
}

/// The compressed blob of `p` (see the file comment).
///
/// \throws InvalidInput when `o.units_per_mm` is outside 1..1e9.
/// \throws std::runtime_error when zstd fails.
inline std::vector<std::uint8_t> compress_pattern(const Pattern& p,
                                                  const CompressionOptions& o = {},
                                                  CompressionReport* report = nullptr) {
    using namespace internal;
    const auto t0 = std::chrono::steady_clock::now();
    CompressionReport rep;
    Json j = to_json(quantised_pattern(p, o, &rep));
    std::vector<std::int64_t> ks;
    extract_grid_numbers(j, double(o.units_per_mm), ks, rep.exact_numbers);
    rep.quantised_numbers = ks.size();

    std::vector<std::uint8_t> raw;
    put_varint(raw, static_cast<std::uint64_t>(o.units_per_mm));
    const std::vector<std::uint8_t> skeleton = Json::to_cbor(j);
    put_varint(raw, skeleton.size());
    raw.insert(raw.end(), skeleton.begin(), skeleton.end());
    put_varint(raw, ks.size());
    for (std::size_t i = 0; i < ks.size(); ++i) {
        put_varint(raw, zigzag(ks[i] - (i >= 2 ? ks[i - 2] : 0)));
    }

    std::vector<std::uint8_t> blob(4 + ZSTD_compressBound(raw.size()));
    blob[0] = 'T';
    blob[1] = 'P';
    blob[2] = 'Z';
    blob[3] = pattern_blob_format;
    const std::size_t n =
        ZSTD_compress(blob.data() + 4, blob.size() - 4, raw.data(), raw.size(), o.zstd_level);
    if (ZSTD_isError(n)) {
        throw std::runtime_error(std::string("zstd compression failed: ") + ZSTD_getErrorName(n));
    }
    blob.resize(4 + n);
    if (report) {
        const std::string plain = to_json(p).dump();
        rep.json_bytes = plain.size();
        if (o.measure_plain_zstd) {
            std::vector<char> tmp(ZSTD_compressBound(plain.size()));
            const std::size_t m =
                ZSTD_compress(tmp.data(), tmp.size(), plain.data(), plain.size(), o.zstd_level);
            rep.json_zstd_bytes = ZSTD_isError(m) ? 0 : m;
        }
        rep.stored_bytes = blob.size();
        rep.ratio = double(rep.json_bytes) / double(blob.size());
        rep.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        *report = rep;
    }
    return blob;
}

/// Decodes a blob made by compress_pattern; `where` names it in messages ("db.sqlite: pattern
/// 'x'"). A damaged blob is an InvalidInput.
///
/// \throws InvalidInput naming `where` for a blob that is not one, of another format version,
///         truncated or malformed.
inline Pattern decompress_pattern(const void* data, std::size_t size, const std::string& where) {
    using namespace internal;
    const auto* b = static_cast<const std::uint8_t*>(data);
    if (size < 4 || b[0] != 'T' || b[1] != 'P' || b[2] != 'Z') {
        throw InvalidInput(where + ": not a compressed Tapeline pattern (bad magic)");
    }
    if (b[3] != pattern_blob_format) {
        throw InvalidInput(where + ": compressed pattern format " + std::to_string(b[3]) +
                           " is not supported (this reader knows " +
                           std::to_string(pattern_blob_format) + ")");
    }
    const unsigned long long raw_size = ZSTD_getFrameContentSize(b + 4, size - 4);
    if (raw_size == ZSTD_CONTENTSIZE_ERROR || raw_size == ZSTD_CONTENTSIZE_UNKNOWN) {
        throw InvalidInput(where + ": compressed pattern is damaged (bad zstd frame header)");
    }
    // The header's size is a claim: a zstd block of at most 128 KiB takes at least 4 bytes (an
    // RLE block), so a frame of n bytes holds at most n * 32768; a claim beyond that, or beyond
    // the largest document read, is refused before anything is allocated for it.
    const unsigned long long most =
        std::min<unsigned long long>((size - 4) * 32768ull, 256ull << 20);
    if (raw_size > most) {
        throw InvalidInput(where + ": compressed pattern is damaged (its header claims " +
                           std::to_string(raw_size) + " bytes, more than its " +
                           std::to_string(size - 4) + " compressed bytes can hold)");
    }
    std::vector<std::uint8_t> raw(raw_size);
    const std::size_t n = ZSTD_decompress(raw.data(), raw.size(), b + 4, size - 4);
    if (ZSTD_isError(n) || n != raw.size()) {
        throw InvalidInput(where + ": compressed pattern is damaged (" +
                           (ZSTD_isError(n) ? ZSTD_getErrorName(n) : "short frame") + ")");
    }
    ByteReader rd{raw.data(), raw.data() + raw.size(), where};
    const std::uint64_t units = rd.varint();
    if (units < 1 || units > 1000000000) {
        throw InvalidInput(where + ": compressed pattern has a bad grid (" + std::to_string(units) +
                           " units per mm)");
    }
    const std::uint64_t skel = rd.varint();
    if (skel > std::uint64_t(rd.end - rd.p)) {
        throw InvalidInput(where + ": compressed pattern is truncated");
    }
    Json j;
    try {
        j = Json::from_cbor(rd.p, rd.p + skel);
    } catch (const nlohmann::json::exception& e) {
        throw InvalidInput(where + ": compressed pattern is damaged (" + e.what() + ")");
    }
    rd.p += skel;
    const std::uint64_t count = rd.varint();
    if (count > std::uint64_t(rd.end - rd.p)) {  // each number takes at least one byte
        throw InvalidInput(where + ": compressed pattern is truncated");
    }
    std::vector<std::int64_t> ks(count);
    for (std::size_t i = 0; i < count; ++i) {
        ks[i] = unzigzag(rd.varint()) + (i >= 2 ? ks[i - 2] : 0);
    }
    std::size_t next = 0;
    restore_grid_numbers(j, double(units), ks, next, where);
    if (next != ks.size() || rd.p != rd.end) {
        throw InvalidInput(where + ": compressed pattern has trailing data");
    }
    return from_json(j, where);
}

inline Pattern decompress_pattern(const std::vector<std::uint8_t>& blob, const std::string& where) {
    return decompress_pattern(blob.data(), blob.size(), where);
}

}  // namespace tapeline::pattern
