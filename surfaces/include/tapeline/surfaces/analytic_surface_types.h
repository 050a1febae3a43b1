// Analytic test surfaces as polygon soups, and their spec strings (no CGAL, no GeographicLib).
//
// This header is the light half of <tapeline/surfaces/analytic_surfaces.h>: test facades,
// loggers and <tapeline/surfaces/analytic_geodesics.h> include it without paying for CGAL
// (DESIGN.md §5). Users include <tapeline/surfaces/analytic_surfaces.h> for meshes, or this
// header for specs and soups.
//
// Surfaces: icosphere (Loop-style midpoint subdivision of the icosahedron, midpoints projected to
// the unit sphere), UV sphere, ellipsoid (icosphere mapped by (x,y,z) -> (Ax,By,Cz)), torus and
// open cylinder, all with outward orientation, and an optional seeded tangential jitter.
//
// Reproducibility: the jitter draws from std::mt19937_64 (whose output the standard fixes) and
// turns its bits into doubles itself; the jitter and the icosphere use only + - * / and sqrt,
// which IEEE 754 rounds exactly, so the same spec gives bit-identical points on every IEEE machine
// that does not contract a*b+c into a fused multiply-add. The UV sphere, torus and cylinder use
// sin/cos, which may differ in the last bit between C libraries.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/core/vec3.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace tapeline {

enum class SurfaceKind { icosphere, uvsphere, ellipsoid, torus, cylinder };

/// One analytic test surface at one resolution.
///
/// Spec strings (KIND:SHAPE:RESOLUTION[:JITTER][:seed=N]):
///   icosphere:LEVEL[:JITTER]              unit sphere, V = 10*4^LEVEL + 2, LEVEL in 0..10
///   uvsphere:NLAT,NLON[:JITTER]           unit sphere, NLAT >= 2 latitude bands, NLON >= 3
///   ellipsoid:A,B,C:LEVEL[:JITTER]        semi-axes along x, y, z; icosphere mapped
///   torus:R,r:NU,NV[:JITTER]              0 < r < R; NU >= 3 around the z axis, NV >= 3 around
///                                         the tube
///   cylinder:R,H:NU,NV[:JITTER]           axis z, z in [-H/2, H/2], open at both ends;
///                                         NU >= 3 around, NV >= 1 segments along the height
/// JITTER in [0, 0.5) moves each vertex tangentially by up to JITTER times its local mean edge
/// length; `seed=N` (default 1) selects the random stream.
struct SurfaceSpec {
    SurfaceKind kind = SurfaceKind::icosphere;  ///< which surface
    int level = 0;                              ///< subdivision level: icosphere, ellipsoid
    /// Latitude and longitude segments (uvsphere).
    ///@{
    int nlat = 0, nlon = 0;  // uvsphere
    ///@}
    /// Ellipsoid semi-axes along x, y, z.
    ///@{
    double a = 1, b = 1, c = 1;  // ellipsoid semi-axes along x, y, z
    ///@}
    /// Torus radii: of the tube's centre circle and of the tube.
    ///@{
    double major_radius = 1, minor_radius = 0.5;  // torus
    ///@}
    /// Cylinder radius and height.
    ///@{
    double radius = 1, height = 1;  // cylinder
    ///@}
    /// Segments around and along (torus, cylinder).
    ///@{
    int nu = 0, nv = 0;  // torus, cylinder
    ///@}
    double jitter = 0;       ///< tangential vertex jitter, times the local mean edge length
    std::uint64_t seed = 1;  ///< random stream of the jitter

    /// Parses a spec string; throws InvalidInput naming the spec and the bad part.
    static SurfaceSpec parse(const std::string& text);
    /// Canonical spec string (shortest round-trip numbers); parse(to_string()) == *this.
    std::string to_string() const;
    /// The spec without its resolution and seed, e.g. "icosphere", "ellipsoid:1,0.6,0.3:j0.25";
    /// groups the sizes of one surface in scaling plots.
    std::string family() const;
    /// Throws InvalidInput if a field is out of range (parse() and generate_surface() call it).
    void validate() const;
    /// Number of vertices and faces generate_surface() will produce (no generation).
    std::size_t vertex_count() const;
    /// Number of faces generate_surface() will produce.
    std::size_t face_count() const;
    /// Closed surfaces (everything but the cylinder).
    bool closed() const { return kind != SurfaceKind::cylinder; }
};

/// Equality of the fields that the kind uses (others are ignored); seed only matters with jitter
/// but is compared anyway so that round trips are exact.
inline bool operator==(const SurfaceSpec& s, const SurfaceSpec& t);
inline bool operator!=(const SurfaceSpec& s, const SurfaceSpec& t) {
    return !(s == t);
}

/// A generated surface as a triangle soup (shared vertices, indices into `points`).
struct SurfaceSoup {
    std::vector<std::array<double, 3>> points;          ///< vertex positions
    std::vector<std::array<std::size_t, 3>> triangles;  ///< corner indices, counter-clockwise
};

/// Builds the surface; triangles are oriented counter-clockwise seen from outside.
///
/// \throws InvalidInput when a field of `spec` is out of range.
inline SurfaceSoup generate_surface(const SurfaceSpec& spec);

// -------------------------------------------------------------------------------------------------
namespace internal {

using vec3::add;
using vec3::cross;
using vec3::dot;
using vec3::norm;
using vec3::normalized;
using vec3::scale;
using vec3::sub;
using Vec3 = vec3::Vec3;

/// Uniform double in [0, 1) from the top 53 bits of one mt19937_64 draw. The standard fixes the
/// engine's output but not std::uniform_real_distribution's, hence this.
inline double uniform01(std::mt19937_64& rng) {
    return static_cast<double>(rng() >> 11) * (1.0 / 9007199254740992.0);  // 2^-53
}

inline std::string format_number(double x) {
    char buf[64];
    auto res = std::to_chars(buf, buf + sizeof buf, x);
    return std::string(buf, res.ptr);
}

inline const char* kind_name(SurfaceKind k) {
    switch (k) {
        case SurfaceKind::icosphere:
            return "icosphere";
        case SurfaceKind::uvsphere:
            return "uvsphere";
        case SurfaceKind::ellipsoid:
            return "ellipsoid";
        case SurfaceKind::torus:
            return "torus";
        case SurfaceKind::cylinder:
            return "cylinder";
    }
    return "?";
}

inline const char* kind_form(SurfaceKind k) {
    switch (k) {
        case SurfaceKind::icosphere:
            return "icosphere:LEVEL[:JITTER]";
        case SurfaceKind::uvsphere:
            return "uvsphere:NLAT,NLON[:JITTER]";
        case SurfaceKind::ellipsoid:
            return "ellipsoid:A,B,C:LEVEL[:JITTER]";
        case SurfaceKind::torus:
            return "torus:R,r:NU,NV[:JITTER]";
        case SurfaceKind::cylinder:
            return "cylinder:R,H:NU,NV[:JITTER]";
    }
    return "?";
}

// Largest mesh we agree to build (icosphere level 10 has 10,485,762 vertices).
constexpr std::uint64_t max_surface_vertices = 100000000;

[[noreturn]] inline void spec_error(const std::string& spec, const std::string& what) {
    throw InvalidInput("invalid surface spec \"" + spec + "\": " + what);
}

inline std::vector<std::string> split(const std::string& s, char sep) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    while (true) {
        std::size_t pos = s.find(sep, start);
        parts.push_back(
            s.substr(start, pos == std::string::npos ? std::string::npos : pos - start));
        if (pos == std::string::npos)
            break;
        start = pos + 1;
    }
    return parts;
}

inline double parse_double(const std::string& spec, const std::string& field, const char* what) {
    double x = 0;
    const char* first = field.data();
    const char* last = field.data() + field.size();
    auto res = std::from_chars(first, last, x);
    if (field.empty() || res.ec != std::errc() || res.ptr != last)
        spec_error(spec, std::string(what) + " '" + field + "' is not a number");
    if (!std::isfinite(x))
        spec_error(spec, std::string(what) + " '" + field + "' is not a finite number");
    return x;
}

inline long long parse_integer(const std::string& spec, const std::string& field,
                               const char* what) {
    long long x = 0;
    const char* first = field.data();
    const char* last = field.data() + field.size();
    auto res = std::from_chars(first, last, x);
    if (field.empty() || res.ec != std::errc() || res.ptr != last)
        spec_error(spec, std::string(what) + " '" + field + "' is not an integer");
    return x;
}

inline int parse_int_in(const std::string& spec, const std::string& field, const char* what,
                        long long lo, long long hi) {
    long long x = parse_integer(spec, field, what);
    if (x < lo || x > hi)
        spec_error(spec, std::string(what) + " " + field + " is outside " + std::to_string(lo) +
                             ".." + std::to_string(hi));
    return static_cast<int>(x);
}

inline std::vector<std::string> split_list(const std::string& spec, const std::string& field,
                                           std::size_t n, const char* what) {
    auto parts = split(field, ',');
    if (parts.size() != n)
        spec_error(spec, "expected " + std::to_string(n) + " comma-separated " + what + ", got '" +
                             field + "'");
    return parts;
}

inline void check_positive(const std::string& spec, double x, const char* what) {
    if (!(x > 0) || !std::isfinite(x))
        spec_error(spec, std::string(what) + " = " + format_number(x) + " must be positive");
}

inline void validate_spec(const SurfaceSpec& s, const std::string& text) {
    if (!(s.jitter >= 0 && s.jitter < 0.5))
        spec_error(text, "jitter " + format_number(s.jitter) + " is outside [0, 0.5)");
    switch (s.kind) {
        case SurfaceKind::icosphere:
        case SurfaceKind::ellipsoid:
            if (s.level < 0 || s.level > 10)
                spec_error(text, "level " + std::to_string(s.level) + " is outside 0..10");
            if (s.kind == SurfaceKind::ellipsoid) {
                check_positive(text, s.a, "semi-axis A");
                check_positive(text, s.b, "semi-axis B");
                check_positive(text, s.c, "semi-axis C");
            }
            break;
        case SurfaceKind::uvsphere:
            if (s.nlat < 2)
                spec_error(text,
                           "NLAT " + std::to_string(s.nlat) + " must be at least 2 latitude bands");
            if (s.nlon < 3)
                spec_error(text,
                           "NLON " + std::to_string(s.nlon) + " must be at least 3 longitudes");
            break;
        case SurfaceKind::torus:
            check_positive(text, s.major_radius, "major radius R");
            check_positive(text, s.minor_radius, "minor radius r");
            if (!(s.minor_radius < s.major_radius))
                spec_error(text, "minor radius r = " + format_number(s.minor_radius) +
                                     " must be smaller than major radius R = " +
                                     format_number(s.major_radius));
            if (s.nu < 3)
                spec_error(text, "NU " + std::to_string(s.nu) +
                                     " must be at least 3 (vertices around the z axis)");
            if (s.nv < 3)
                spec_error(text, "NV " + std::to_string(s.nv) +
                                     " must be at least 3 (vertices around the tube)");
            break;
        case SurfaceKind::cylinder:
            check_positive(text, s.radius, "radius R");
            check_positive(text, s.height, "height H");
            if (s.nu < 3)
                spec_error(text, "NU " + std::to_string(s.nu) +
                                     " must be at least 3 (vertices around the axis)");
            if (s.nv < 1)
                spec_error(text, "NV " + std::to_string(s.nv) +
                                     " must be at least 1 (segments along the height)");
            break;
        default:
            spec_error(text, "unknown surface kind");
    }
    // Vertex count in 64 bits: each factor is below 2^31, so the products cannot overflow.
    std::uint64_t v = 0;
    switch (s.kind) {
        case SurfaceKind::icosphere:
        case SurfaceKind::ellipsoid:
            v = 10 * (std::uint64_t(1) << (2 * s.level)) + 2;
            break;
        case SurfaceKind::uvsphere:
            v = std::uint64_t(s.nlat - 1) * std::uint64_t(s.nlon) + 2;
            break;
        case SurfaceKind::torus:
            v = std::uint64_t(s.nu) * std::uint64_t(s.nv);
            break;
        case SurfaceKind::cylinder:
            v = std::uint64_t(s.nu) * (std::uint64_t(s.nv) + 1);
            break;
    }
    if (v > max_surface_vertices)
        spec_error(text, "too large: " + std::to_string(v) + " vertices (limit " +
                             std::to_string(max_surface_vertices) + ")");
}

// ---- generation ---------------------------------------------------------------------------------

inline void icosahedron(SurfaceSoup& soup) {
    // Vertices (0, ±1, ±phi) and cyclic permutations; edges are the pairs at distance 2. The faces
    // are found rather than typed in, then turned to face outward.
    const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
    std::vector<Vec3> p;
    for (double s1 : {-1.0, 1.0})
        for (double s2 : {-1.0, 1.0}) {
            p.push_back({0.0, s1, s2 * phi});
            p.push_back({s1, s2 * phi, 0.0});
            p.push_back({s2 * phi, 0.0, s1});
        }
    auto is_edge = [&](std::size_t i, std::size_t j) {
        Vec3 d = sub(p[i], p[j]);
        return std::abs(dot(d, d) - 4.0) < 1e-9;
    };
    soup.points.clear();
    soup.triangles.clear();
    for (const Vec3& q : p)
        soup.points.push_back(normalized(q));
    for (std::size_t i = 0; i < 12; ++i)
        for (std::size_t j = i + 1; j < 12; ++j)
            for (std::size_t k = j + 1; k < 12; ++k)
                if (is_edge(i, j) && is_edge(j, k) && is_edge(i, k)) {
                    Vec3 n = cross(sub(p[j], p[i]), sub(p[k], p[i]));
                    if (dot(n, add(add(p[i], p[j]), p[k])) > 0)
                        soup.triangles.push_back({i, j, k});
                    else
                        soup.triangles.push_back({i, k, j});
                }
    if (soup.triangles.size() != 20)
        throw std::logic_error("tapeline: icosahedron construction failed");
}

inline void subdivide_on_sphere(SurfaceSoup& soup) {
    // Each vertex has degree <= 6 on an icosphere, so the midpoint of edge (lo, hi) is stored in a
    // fixed slot array of its lower endpoint: no hash map, memory linear in |V|.
    struct Slots {
        std::uint32_t other[6];
        std::uint32_t mid[6];
        std::uint8_t n = 0;
    };
    const std::size_t nv = soup.points.size();
    std::vector<Slots> slots(nv);
    soup.points.reserve(nv + soup.triangles.size() * 3 / 2);
    auto midpoint = [&](std::size_t i, std::size_t j) -> std::size_t {
        std::size_t lo = std::min(i, j), hi = std::max(i, j);
        Slots& s = slots[lo];
        for (std::uint8_t t = 0; t < s.n; ++t)
            if (s.other[t] == hi)
                return s.mid[t];
        if (s.n == 6)
            throw std::logic_error("tapeline: icosphere vertex of degree > 6");
        std::size_t m = soup.points.size();
        soup.points.push_back(normalized(add(soup.points[lo], soup.points[hi])));
        s.other[s.n] = static_cast<std::uint32_t>(hi);
        s.mid[s.n] = static_cast<std::uint32_t>(m);
        ++s.n;
        return m;
    };
    std::vector<std::array<std::size_t, 3>> out;
    out.reserve(soup.triangles.size() * 4);
    for (const auto& t : soup.triangles) {
        std::size_t ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
        out.push_back({t[0], ab, ca});
        out.push_back({ab, t[1], bc});
        out.push_back({ca, bc, t[2]});
        out.push_back({ab, bc, ca});
    }
    soup.triangles = std::move(out);
}

inline void icosphere(SurfaceSoup& soup, int level) {
    icosahedron(soup);
    for (int l = 0; l < level; ++l)
        subdivide_on_sphere(soup);
}

inline void uv_sphere(SurfaceSoup& soup, int nlat, int nlon) {
    // Vertex 0 is the north pole, then rings of nlon vertices from north to south, then the south
    // pole. In the (east, north) tangent frame east x north points outward, so counter-clockwise
    // there is counter-clockwise seen from outside.
    const double pi = 3.14159265358979323846;
    soup.points.clear();
    soup.triangles.clear();
    soup.points.push_back({0.0, 0.0, 1.0});
    for (int i = 1; i < nlat; ++i) {
        double theta = pi * i / nlat;
        double st = std::sin(theta), ct = std::cos(theta);
        for (int j = 0; j < nlon; ++j) {
            double ph = 2 * pi * j / nlon;
            soup.points.push_back(normalized({st * std::cos(ph), st * std::sin(ph), ct}));
        }
    }
    soup.points.push_back({0.0, 0.0, -1.0});
    const std::size_t south = soup.points.size() - 1;
    auto ring = [&](int i, int j) -> std::size_t {
        return 1 + std::size_t(i - 1) * nlon + std::size_t(j % nlon);
    };
    for (int j = 0; j < nlon; ++j)
        soup.triangles.push_back({0, ring(1, j), ring(1, j + 1)});
    for (int i = 1; i + 1 < nlat; ++i)
        for (int j = 0; j < nlon; ++j) {
            std::size_t up0 = ring(i, j), up1 = ring(i, j + 1);
            std::size_t lo0 = ring(i + 1, j), lo1 = ring(i + 1, j + 1);
            soup.triangles.push_back({lo0, lo1, up1});
            soup.triangles.push_back({lo0, up1, up0});
        }
    for (int j = 0; j < nlon; ++j)
        soup.triangles.push_back({south, ring(nlat - 1, j + 1), ring(nlat - 1, j)});
}

// Quad grid with vertex (i, k) at index index(i, k), i periodic in nu, (u, v) right-handed with
// respect to the outward normal.
template <class Index>
inline void grid_triangles(SurfaceSoup& soup, int nu, int nv_cells, Index index) {
    for (int k = 0; k < nv_cells; ++k)
        for (int i = 0; i < nu; ++i) {
            std::size_t a = index(i, k), b = index(i + 1, k), c = index(i + 1, k + 1),
                        d = index(i, k + 1);
            soup.triangles.push_back({a, b, c});
            soup.triangles.push_back({a, c, d});
        }
}

inline void torus(SurfaceSoup& soup, double R, double r, int nu, int nv) {
    const double pi = 3.14159265358979323846;
    soup.points.clear();
    soup.triangles.clear();
    for (int k = 0; k < nv; ++k) {
        double v = 2 * pi * k / nv;
        double cv = std::cos(v), sv = std::sin(v);
        for (int i = 0; i < nu; ++i) {
            double u = 2 * pi * i / nu;
            double rho = R + r * cv;
            soup.points.push_back({rho * std::cos(u), rho * std::sin(u), r * sv});
        }
    }
    grid_triangles(soup, nu, nv, [nu, nv](int i, int k) {
        return std::size_t(k % nv) * std::size_t(nu) + std::size_t(i % nu);
    });
}

inline void cylinder(SurfaceSoup& soup, double R, double H, int nu, int nv) {
    const double pi = 3.14159265358979323846;
    soup.points.clear();
    soup.triangles.clear();
    for (int k = 0; k <= nv; ++k) {
        // k/nv is exactly 0 or 1 at the ends, so the boundary rings sit exactly at z = ±H/2.
        double z = H * (static_cast<double>(k) / nv - 0.5);
        for (int i = 0; i < nu; ++i) {
            double u = 2 * pi * i / nu;
            soup.points.push_back({R * std::cos(u), R * std::sin(u), z});
        }
    }
    grid_triangles(soup, nu, nv, [nu](int i, int k) {
        return std::size_t(k) * std::size_t(nu) + std::size_t(i % nu);
    });
}

/// Unit outward normal of the analytic surface at (or near) p.
inline Vec3 surface_normal(const SurfaceSpec& s, const Vec3& p) {
    switch (s.kind) {
        case SurfaceKind::icosphere:
        case SurfaceKind::uvsphere:
            return normalized(p);
        case SurfaceKind::ellipsoid:
            return normalized({p[0] / (s.a * s.a), p[1] / (s.b * s.b), p[2] / (s.c * s.c)});
        case SurfaceKind::torus: {
            double rho = std::hypot(p[0], p[1]);
            Vec3 center = {s.major_radius * p[0] / rho, s.major_radius * p[1] / rho, 0.0};
            return normalized(sub(p, center));
        }
        case SurfaceKind::cylinder:
            return normalized({p[0], p[1], 0.0});
    }
    return {0, 0, 1};
}

/// Puts a point near the surface back exactly onto it: radially for spheres and ellipsoids,
/// nearest point for the torus and the cylinder (whose z is clamped to [-H/2, H/2]).
inline Vec3 project_to_surface(const SurfaceSpec& s, const Vec3& p) {
    switch (s.kind) {
        case SurfaceKind::icosphere:
        case SurfaceKind::uvsphere:
            return normalized(p);
        case SurfaceKind::ellipsoid: {
            double q = std::sqrt(p[0] * p[0] / (s.a * s.a) + p[1] * p[1] / (s.b * s.b) +
                                 p[2] * p[2] / (s.c * s.c));
            return scale(p, 1.0 / q);
        }
        case SurfaceKind::torus: {
            double rho = std::hypot(p[0], p[1]);
            Vec3 center = {s.major_radius * p[0] / rho, s.major_radius * p[1] / rho, 0.0};
            return add(center, scale(normalized(sub(p, center)), s.minor_radius));
        }
        case SurfaceKind::cylinder: {
            double rho = std::hypot(p[0], p[1]);
            double h = 0.5 * s.height;
            return {s.radius * p[0] / rho, s.radius * p[1] / rho, std::clamp(p[2], -h, h)};
        }
    }
    return p;
}

/// Orthonormal tangent basis at unit normal n (sqrt only, so reproducible).
inline std::pair<Vec3, Vec3> tangent_basis(const Vec3& n) {
    Vec3 helper = std::abs(n[0]) < 0.9 ? Vec3{1.0, 0.0, 0.0} : Vec3{0.0, 1.0, 0.0};
    Vec3 e1 = normalized(cross(n, helper));
    Vec3 e2 = cross(n, e1);
    return {e1, e2};
}

/// Seeded tangential jitter. Each vertex, in index order, moves by a vector uniform in the tangent
/// disk of radius jitter x (mean length of its incident edges in the unjittered mesh), and is
/// projected back onto the surface; the final move never exceeds that radius. Cylinder boundary
/// vertices move along their boundary circle only. A move that would leave an incident triangle
/// with less than 5% of its original area (measured along the original normal), or flip it, is
/// halved up to four times and otherwise dropped, so the mesh stays embedded and consistently
/// oriented.
inline void apply_jitter(const SurfaceSpec& s, SurfaceSoup& soup) {
    const std::size_t nv = soup.points.size();
    const auto& tri = soup.triangles;
    std::vector<double> edge_sum(nv, 0.0);
    std::vector<std::uint32_t> edge_count(nv, 0);
    std::vector<std::uint32_t> first(nv + 1, 0);
    for (const auto& t : tri)
        for (int e = 0; e < 3; ++e) {
            std::size_t i = t[e], j = t[(e + 1) % 3];
            double len = norm(sub(soup.points[i], soup.points[j]));
            edge_sum[i] += len;
            edge_sum[j] += len;
            ++edge_count[i];
            ++edge_count[j];
            ++first[i + 1];
        }
    // Vertex -> incident faces (CSR), and original face normals.
    for (std::size_t v = 0; v < nv; ++v)
        first[v + 1] += first[v];
    std::vector<std::uint32_t> incident(first[nv]);
    {
        std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
        for (std::size_t f = 0; f < tri.size(); ++f)
            for (int e = 0; e < 3; ++e)
                incident[fill[tri[f][e]]++] = static_cast<std::uint32_t>(f);
    }
    auto face_normal = [&](std::size_t f) {
        const auto& t = tri[f];
        const auto& p = soup.points;
        return cross(sub(p[t[1]], p[t[0]]), sub(p[t[2]], p[t[0]]));
    };
    std::vector<Vec3> original_normal(tri.size());
    for (std::size_t f = 0; f < tri.size(); ++f)
        original_normal[f] = face_normal(f);

    const double h = 0.5 * s.height;
    std::mt19937_64 rng(s.seed);
    for (std::size_t v = 0; v < nv; ++v) {
        const Vec3 p0 = soup.points[v];
        const double max_move = s.jitter * edge_sum[v] / edge_count[v];
        const bool on_rim = s.kind == SurfaceKind::cylinder && (p0[2] == h || p0[2] == -h);
        Vec3 move{};
        if (on_rim) {
            double t = 2 * uniform01(rng) - 1;
            Vec3 tangent = normalized({-p0[1], p0[0], 0.0});
            move = scale(tangent, t * max_move);
        } else {
            double x, y;
            do {
                x = 2 * uniform01(rng) - 1;
                y = 2 * uniform01(rng) - 1;
            } while (x * x + y * y >= 1);
            auto [e1, e2] = tangent_basis(surface_normal(s, p0));
            move = add(scale(e1, x * max_move), scale(e2, y * max_move));
        }
        for (int attempt = 0; attempt < 5; ++attempt, move = scale(move, 0.5)) {
            Vec3 p = project_to_surface(s, add(p0, move));
            if (on_rim)
                p[2] = p0[2];
            soup.points[v] = p;
            // The projection may lengthen the move on a strongly curved surface; the bound holds.
            bool ok = norm(sub(p, p0)) <= max_move;
            for (std::uint32_t k = first[v]; k < first[v + 1] && ok; ++k) {
                const Vec3& n0 = original_normal[incident[k]];
                ok = dot(face_normal(incident[k]), n0) >= 0.05 * dot(n0, n0);
            }
            if (ok)
                break;
            soup.points[v] = p0;
        }
    }
}

}  // namespace internal

// -------------------------------------------------------------------------------------------------

inline bool operator==(const SurfaceSpec& s, const SurfaceSpec& t) {
    if (s.kind != t.kind || s.jitter != t.jitter || s.seed != t.seed)
        return false;
    switch (s.kind) {
        case SurfaceKind::icosphere:
            return s.level == t.level;
        case SurfaceKind::uvsphere:
            return s.nlat == t.nlat && s.nlon == t.nlon;
        case SurfaceKind::ellipsoid:
            return s.level == t.level && s.a == t.a && s.b == t.b && s.c == t.c;
        case SurfaceKind::torus:
            return s.major_radius == t.major_radius && s.minor_radius == t.minor_radius &&
                   s.nu == t.nu && s.nv == t.nv;
        case SurfaceKind::cylinder:
            return s.radius == t.radius && s.height == t.height && s.nu == t.nu && s.nv == t.nv;
    }
    return false;
}

inline SurfaceSpec SurfaceSpec::parse(const std::string& text) {
    using namespace internal;
    if (text.empty())
        spec_error(text,
                   "empty spec (expected e.g. icosphere:4, uvsphere:32,64, "
                   "ellipsoid:1,1,0.3:4, torus:1,0.3:64,32, cylinder:1,2:64,16)");
    std::vector<std::string> f = split(text, ':');
    SurfaceSpec s;
    const std::string& kind = f[0];
    if (kind == "icosphere")
        s.kind = SurfaceKind::icosphere;
    else if (kind == "uvsphere")
        s.kind = SurfaceKind::uvsphere;
    else if (kind == "ellipsoid")
        s.kind = SurfaceKind::ellipsoid;
    else if (kind == "torus")
        s.kind = SurfaceKind::torus;
    else if (kind == "cylinder")
        s.kind = SurfaceKind::cylinder;
    else
        spec_error(text, "unknown surface kind '" + kind +
                             "' (expected icosphere, uvsphere, ellipsoid, torus or cylinder)");
    const std::string form = kind_form(s.kind);

    // Optional trailing seed=N.
    if (f.size() > 1 && f.back().rfind("seed=", 0) == 0) {
        std::string digits = f.back().substr(5);
        std::uint64_t seed = 0;
        auto res = std::from_chars(digits.data(), digits.data() + digits.size(), seed);
        if (digits.empty() || res.ec != std::errc() || res.ptr != digits.data() + digits.size())
            spec_error(text, "seed '" + digits + "' is not an unsigned 64-bit integer");
        s.seed = seed;
        f.pop_back();
    }
    const bool has_shape = s.kind == SurfaceKind::ellipsoid || s.kind == SurfaceKind::torus ||
                           s.kind == SurfaceKind::cylinder;
    const std::size_t required = has_shape ? 3 : 2;  // kind, [shape,] resolution
    if (f.size() < required)
        spec_error(text, "missing parts (expected " + form + ")");
    if (f.size() > required + 1)
        spec_error(text, "unexpected trailing part '" + f[required + 1] + "' (expected " + form +
                             "[:seed=N])");
    if (f.size() == required + 1)
        s.jitter = parse_double(text, f[required], "jitter");

    const std::string& res = f[required - 1];
    switch (s.kind) {
        case SurfaceKind::icosphere:
            s.level = parse_int_in(text, res, "level", 0, 10);
            break;
        case SurfaceKind::uvsphere: {
            auto n = split_list(text, res, 2, "counts NLAT,NLON");
            s.nlat = parse_int_in(text, n[0], "NLAT", 2, std::numeric_limits<int>::max());
            s.nlon = parse_int_in(text, n[1], "NLON", 3, std::numeric_limits<int>::max());
            break;
        }
        case SurfaceKind::ellipsoid: {
            auto n = split_list(text, f[1], 3, "semi-axes A,B,C");
            s.a = parse_double(text, n[0], "semi-axis A");
            s.b = parse_double(text, n[1], "semi-axis B");
            s.c = parse_double(text, n[2], "semi-axis C");
            s.level = parse_int_in(text, res, "level", 0, 10);
            break;
        }
        case SurfaceKind::torus: {
            auto n = split_list(text, f[1], 2, "radii R,r");
            s.major_radius = parse_double(text, n[0], "major radius R");
            s.minor_radius = parse_double(text, n[1], "minor radius r");
            auto m = split_list(text, res, 2, "counts NU,NV");
            s.nu = parse_int_in(text, m[0], "NU", 3, std::numeric_limits<int>::max());
            s.nv = parse_int_in(text, m[1], "NV", 3, std::numeric_limits<int>::max());
            break;
        }
        case SurfaceKind::cylinder: {
            auto n = split_list(text, f[1], 2, "sizes R,H");
            s.radius = parse_double(text, n[0], "radius R");
            s.height = parse_double(text, n[1], "height H");
            auto m = split_list(text, res, 2, "counts NU,NV");
            s.nu = parse_int_in(text, m[0], "NU", 3, std::numeric_limits<int>::max());
            s.nv = parse_int_in(text, m[1], "NV", 1, std::numeric_limits<int>::max());
            break;
        }
    }
    validate_spec(s, text);
    return s;
}

inline void SurfaceSpec::validate() const {
    internal::validate_spec(*this, to_string());
}

inline std::string SurfaceSpec::family() const {
    using internal::format_number;
    std::string out = internal::kind_name(kind);
    switch (kind) {
        case SurfaceKind::icosphere:
        case SurfaceKind::uvsphere:
            break;
        case SurfaceKind::ellipsoid:
            out += ":" + format_number(a) + "," + format_number(b) + "," + format_number(c);
            break;
        case SurfaceKind::torus:
            out += ":" + format_number(major_radius) + "," + format_number(minor_radius);
            break;
        case SurfaceKind::cylinder:
            out += ":" + format_number(radius) + "," + format_number(height);
            break;
    }
    if (jitter != 0)
        out += ":j" + format_number(jitter);
    return out;
}

inline std::string SurfaceSpec::to_string() const {
    using internal::format_number;
    std::string out = internal::kind_name(kind);
    switch (kind) {
        case SurfaceKind::icosphere:
            out += ":" + std::to_string(level);
            break;
        case SurfaceKind::uvsphere:
            out += ":" + std::to_string(nlat) + "," + std::to_string(nlon);
            break;
        case SurfaceKind::ellipsoid:
            out += ":" + format_number(a) + "," + format_number(b) + "," + format_number(c) + ":" +
                   std::to_string(level);
            break;
        case SurfaceKind::torus:
            out += ":" + format_number(major_radius) + "," + format_number(minor_radius) + ":" +
                   std::to_string(nu) + "," + std::to_string(nv);
            break;
        case SurfaceKind::cylinder:
            out += ":" + format_number(radius) + "," + format_number(height) + ":" +
                   std::to_string(nu) + "," + std::to_string(nv);
            break;
    }
    if (jitter != 0)
        out += ":" + format_number(jitter);
    if (seed != 1)
        out += ":seed=" + std::to_string(seed);
    return out;
}

inline std::size_t SurfaceSpec::vertex_count() const {
    switch (kind) {
        case SurfaceKind::icosphere:
        case SurfaceKind::ellipsoid:
            return 10 * (std::size_t(1) << (2 * level)) + 2;
        case SurfaceKind::uvsphere:
            return std::size_t(nlat - 1) * std::size_t(nlon) + 2;
        case SurfaceKind::torus:
            return std::size_t(nu) * std::size_t(nv);
        case SurfaceKind::cylinder:
            return std::size_t(nu) * (std::size_t(nv) + 1);
    }
    return 0;
}

inline std::size_t SurfaceSpec::face_count() const {
    switch (kind) {
        case SurfaceKind::icosphere:
        case SurfaceKind::ellipsoid:
            return 20 * (std::size_t(1) << (2 * level));
        case SurfaceKind::uvsphere:
            return 2 * std::size_t(nlat - 1) * std::size_t(nlon);
        case SurfaceKind::torus:
        case SurfaceKind::cylinder:
            return 2 * std::size_t(nu) * std::size_t(nv);
    }
    return 0;
}

inline SurfaceSoup generate_surface(const SurfaceSpec& spec) {
    spec.validate();
    SurfaceSoup soup;
    switch (spec.kind) {
        case SurfaceKind::icosphere:
            internal::icosphere(soup, spec.level);
            break;
        case SurfaceKind::ellipsoid:
            // The linear map has a positive determinant, so orientation is kept.
            internal::icosphere(soup, spec.level);
            for (auto& p : soup.points)
                p = {spec.a * p[0], spec.b * p[1], spec.c * p[2]};
            break;
        case SurfaceKind::uvsphere:
            internal::uv_sphere(soup, spec.nlat, spec.nlon);
            break;
        case SurfaceKind::torus:
            internal::torus(soup, spec.major_radius, spec.minor_radius, spec.nu, spec.nv);
            break;
        case SurfaceKind::cylinder:
            internal::cylinder(soup, spec.radius, spec.height, spec.nu, spec.nv);
            break;
    }
    if (spec.jitter > 0)
        internal::apply_jitter(spec, soup);
    return soup;
}

}  // namespace tapeline
