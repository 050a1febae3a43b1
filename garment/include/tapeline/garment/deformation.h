// The deformation of a cloth triangle against its pattern triangle (no CGAL, no Eigen): the
// deformation gradient from which stretch (quality.h) and wrinkle strains (wrinkles/strain.h) are
// read.
#pragma once

#include <tapeline/core/vec3.h>
#include <tapeline/garment/drape_types.h>

#include <array>
#include <cmath>

namespace tapeline::garment {

/// Deformation gradient of a triangle: F = Ds·Dm⁻¹, the linear map from its pattern triangle
/// (`uv`, pattern units) to its 3D triangle (x0, x1, x2), as the images of the pattern's unit u and
/// v directions. False (and F untouched) when the pattern triangle is degenerate (|det Dm| below
/// 1e-12).
inline bool deformation_gradient(const Vec3& x0, const Vec3& x1, const Vec3& x2,
                                 const std::array<UV, 3>& uv, Vec3& fu, Vec3& fv) {
    const double a = uv[1][0] - uv[0][0], b = uv[2][0] - uv[0][0];
    const double c = uv[1][1] - uv[0][1], d = uv[2][1] - uv[0][1];
    const double det = a * d - b * c;
    if (!(std::abs(det) >= 1e-12)) {
        return false;
    }
    // Dm = [[a b][c d]]; F = Ds·Dm⁻¹ (3×2).
    const double ia = d / det, ib = -b / det, ic = -c / det, id = a / det;
    const Vec3 e1 = vec3::sub(x1, x0), e2 = vec3::sub(x2, x0);
    fu = vec3::add(vec3::scale(e1, ia), vec3::scale(e2, ic));
    fv = vec3::add(vec3::scale(e1, ib), vec3::scale(e2, id));
    return true;
}

}  // namespace tapeline::garment
