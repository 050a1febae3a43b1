// The in-plane strain of a draped cloth triangle against its pattern triangle, in the fabric's
// grain frame, and the normal curvature of the draped surface: the inputs of the wrinkle
// classification (classify.h). No CGAL.
//
// Strain. F = Ds·Dm⁻¹ (garment/deformation.h) maps the pattern triangle onto the draped one. Its
// principal stretches s_max ≥ s_min are the square roots of the eigenvalues of C = FᵀF, with the
// eigenvectors the pattern directions that are stretched most and least; their images F·v / s
// are the 3D directions. In the grain frame (warp g, weft g⊥ = g rotated by +90°): the warp and
// weft strains are |F·g| − 1 and |F·g⊥| − 1, the shear angle is 90° minus the angle between F·g
// and F·g⊥ (positive: the yarns close up), the quantities the solver's strain constraints act on
// (Müller et al., "Strain Based Dynamics", SCA 2014; drape_solver.h).
//
// Curvature. The shape operator of each triangle is fitted by least squares to the change of the
// area-weighted vertex normals along its three edges (Rusinkiewicz, "Estimating Curvatures and
// Their Derivatives on Triangle Meshes", 3DPVT 2004); the normal curvature along a direction d
// in the triangle's plane is dᵀ·S·d (1/mm, positive where the surface bends away from its
// normal, as on the outside of a sphere with outward normals).
#pragma once

#include <tapeline/core/vec3.h>
#include <tapeline/garment/deformation.h>
#include <tapeline/garment/drape_types.h>

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace tapeline::wrinkles {

using garment::Tri;
using garment::UV;
using garment::Vec3;

/// Area of a pattern triangle (unsigned, in the square of its unit).
inline double pattern_area(const std::array<UV, 3>& u) {
    return 0.5 * std::abs((u[1][0] - u[0][0]) * (u[2][1] - u[0][1]) -
                          (u[2][0] - u[0][0]) * (u[1][1] - u[0][1]));
}

/// Centroid of a pattern triangle.
inline UV pattern_centroid(const std::array<UV, 3>& u) {
    return {(u[0][0] + u[1][0] + u[2][0]) / 3, (u[0][1] + u[1][1] + u[2][1]) / 3};
}

/// The strain of one triangle against its pattern triangle (see the file comment).
struct TriangleStrain {
    bool valid = false;     ///< false: degenerate pattern triangle (nothing else is set)
    double s_max = 1;       ///< largest principal stretch
    double s_min = 1;       ///< smallest principal stretch
    UV rest_max{1, 0};      ///< pattern direction of s_max (unit, pattern coordinates)
    UV rest_min{0, 1};      ///< pattern direction of s_min
    Vec3 dir_max{1, 0, 0};  ///< 3D direction of s_max (unit)
    Vec3 dir_min{0, 1, 0};  ///< 3D direction of s_min (unit)
    /// Angle of the s_min direction from the warp, degrees in [0, 180).
    double min_angle_from_warp_deg = 0;
    double warp_strain = 0;  ///< |F·g| − 1
    double weft_strain = 0;  ///< |F·g⊥| − 1
    double shear_rad = 0;    ///< 90° minus the angle between F·g and F·g⊥, radians
};

/// The strain of the triangle (x0, x1, x2) against its pattern triangle `uv` (same unit as x),
/// `grain` the unit warp direction in pattern coordinates.
inline TriangleStrain triangle_strain(const Vec3& x0, const Vec3& x1, const Vec3& x2,
                                      const std::array<UV, 3>& uv, const UV& grain) {
    TriangleStrain s;
    Vec3 fu, fv;
    if (!garment::deformation_gradient(x0, x1, x2, uv, fu, fv)) {
        return s;
    }
    s.valid = true;
    const double p = vec3::dot(fu, fu), q = vec3::dot(fu, fv), r = vec3::dot(fv, fv);
    const double mean = 0.5 * (p + r), dev = std::sqrt(0.25 * (p - r) * (p - r) + q * q);
    const double l_max = mean + dev, l_min = std::max(0.0, mean - dev);
    s.s_max = std::sqrt(l_max);
    s.s_min = std::sqrt(l_min);
    // Eigenvector of C = [[p q][q r]] for l_max: (q, l_max − p) or (l_max − r, q), the better
    // conditioned of the two; (1, 0) when C is a multiple of the identity.
    UV e{1, 0};
    const UV a{q, l_max - p}, b{l_max - r, q};
    const double na = std::hypot(a[0], a[1]), nb = std::hypot(b[0], b[1]);
    if (na >= nb && na > 1e-300) {
        e = {a[0] / na, a[1] / na};
    } else if (nb > 1e-300) {
        e = {b[0] / nb, b[1] / nb};
    }
    s.rest_max = e;
    s.rest_min = {-e[1], e[0]};
    auto image = [&](const UV& d) {
        const Vec3 v = vec3::add(vec3::scale(fu, d[0]), vec3::scale(fv, d[1]));
        const double n = vec3::norm(v);
        return n > 1e-300 ? vec3::scale(v, 1 / n) : Vec3{0, 0, 0};
    };
    s.dir_max = image(s.rest_max);
    s.dir_min = image(s.rest_min);
    const UV weft{-grain[1], grain[0]};
    const double c = s.rest_min[0] * grain[0] + s.rest_min[1] * grain[1];
    const double sn = s.rest_min[0] * weft[0] + s.rest_min[1] * weft[1];
    double ang = std::atan2(sn, c) * 180 / M_PI;
    if (ang < 0) {
        ang += 180;
    }
    s.min_angle_from_warp_deg = ang >= 180 ? ang - 180 : ang;
    const Vec3 fw = vec3::add(vec3::scale(fu, grain[0]), vec3::scale(fv, grain[1]));
    const Vec3 ff = vec3::add(vec3::scale(fu, weft[0]), vec3::scale(fv, weft[1]));
    const double lw = vec3::norm(fw), lf = vec3::norm(ff);
    s.warp_strain = lw - 1;
    s.weft_strain = lf - 1;
    if (lw > 1e-300 && lf > 1e-300) {
        const double cosang = std::max(-1.0, std::min(1.0, vec3::dot(fw, ff) / (lw * lf)));
        s.shear_rad = M_PI / 2 - std::acos(cosang);
    }
    return s;
}

/// The triangle's shape operator fitted to its vertex normals `n` (draw::vertex_normals; see the
/// file comment), as a
/// function of a direction: the normal curvature (1/unit of x) along `d` (3D, need not lie in
/// the plane: it is projected; zero for a degenerate triangle or a zero direction).
struct TriangleCurvature {
    Vec3 t1{1, 0, 0}, t2{0, 1, 0};  ///< orthonormal basis of the triangle's plane
    double s11 = 0, s12 = 0, s22 = 0;
    double along(const Vec3& d) const {
        const double a = vec3::dot(d, t1), b = vec3::dot(d, t2);
        const double l2 = a * a + b * b;
        return l2 > 1e-300 ? (s11 * a * a + 2 * s12 * a * b + s22 * b * b) / l2 : 0;
    }
};

inline TriangleCurvature triangle_curvature(const std::vector<Vec3>& x, const Tri& f,
                                            const std::vector<Vec3>& n) {
    TriangleCurvature k;
    const Vec3 e1 = vec3::sub(x[f[1]], x[f[0]]);
    const Vec3 nf = vec3::cross(e1, vec3::sub(x[f[2]], x[f[0]]));
    const double ln = vec3::norm(nf), l1 = vec3::norm(e1);
    if (!(ln > 1e-300) || !(l1 > 1e-300)) {
        return k;
    }
    k.t1 = vec3::scale(e1, 1 / l1);
    k.t2 = vec3::cross(vec3::scale(nf, 1 / ln), k.t1);
    // Normal equations of S·[e·t1, e·t2] = [dn·t1, dn·t2] over the three edges, unknowns
    // (s11, s12, s22).
    double m[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}, rhs[3] = {0, 0, 0};
    for (int k0 = 0; k0 < 3; ++k0) {
        const std::uint32_t i = f[std::size_t(k0)], j = f[std::size_t((k0 + 1) % 3)];
        const Vec3 e = vec3::sub(x[j], x[i]), dn = vec3::sub(n[j], n[i]);
        const double a = vec3::dot(e, k.t1), b = vec3::dot(e, k.t2);
        const double u = vec3::dot(dn, k.t1), w = vec3::dot(dn, k.t2);
        // rows: [a b 0]·s = u, [0 a b]·s = w
        const double r1[3] = {a, b, 0}, r2[3] = {0, a, b};
        for (int p = 0; p < 3; ++p) {
            for (int q = 0; q < 3; ++q) {
                m[p][q] += r1[p] * r1[q] + r2[p] * r2[q];
            }
            rhs[p] += r1[p] * u + r2[p] * w;
        }
    }
    Eigen::Matrix3d mm;
    Eigen::Vector3d rr;
    for (int p = 0; p < 3; ++p) {
        rr(p) = rhs[p];
        for (int q = 0; q < 3; ++q) {
            mm(p, q) = m[p][q];
        }
    }
    const Eigen::LDLT<Eigen::Matrix3d> ldlt(mm);
    if (ldlt.info() != Eigen::Success || !(ldlt.vectorD().minCoeff() > 1e-12 * mm.trace())) {
        return k;
    }
    const Eigen::Vector3d sol = ldlt.solve(rr);
    k.s11 = sol(0);
    k.s12 = sol(1);
    k.s22 = sol(2);
    return k;
}

}  // namespace tapeline::wrinkles
