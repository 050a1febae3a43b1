// From a fabric's bending rigidity (N·m, per direction) to the stiffness of the discrete bending
// hinges of the cloth solver (drape_solver.h). No CGAL, no Eigen.
//
// Model. Each interior edge e of the rest mesh carries the hinge energy
//     E_e = ½ · B(ψ_e) · (|e|² / A_e) · θ_e²,
// with θ_e the dihedral angle (flat at rest), |e| the rest edge length, A_e the rest area of the
// two triangles and B(ψ_e) the rigidity for curvature across the edge: ψ_e is the angle between
// the warp and the in-plane normal of the edge (a hinge along the warp bends the weft).
//
// Derivation. The surface z = ½·κ·s² (a cylinder of curvature κ across direction s) sampled at
// the vertices of a mesh gives every triangle the plane of the interpolated quadratic; the
// dihedral angle across an edge is the jump of the slope normal to the edge, θ_e = κ_n·(h₁+h₂)/2
// for a bend across the edge (h₁, h₂ the heights of the two triangles over the edge), so
// θ_e² · |e|²/A_e = κ_n²·(h₁+h₂)²/4 · |e|² / (|e|(h₁+h₂)/2) = κ_n² · |e|(h₁+h₂)/2 = κ_n²·A_e.
// An edge perpendicular to the bend thus stores ½·B·κ²·A_e. Each triangle belongs to three
// edges; summing over the edges of a regular mesh weighs every triangle's area once:
//  - equilateral meshes: the three edge directions at 60° share the bend so that the sum is
//    ½·B·κ²·area for a bend in any direction (Σ_k cos⁴(ψ − 60°k) = 9/8 and the heights work out
//    to exactly one area; tests/garment/test_fabric.cpp checks it);
//  - grids of right triangles: exact for bends along the grid lines; a bend along a diagonal
//    is stiffer (≈ 1.5×), since both legs and one diagonal see it. With alternating diagonals
//    the cylinder is exact but a loaded strip is not: each hinge's wings are every other vertex
//    of the next grid line, and the strip sags through the zigzag between them (17 % beyond its
//    beam; fabric_tests.h meshes its cantilever strip near-equilateral for that reason).
// The weight |e|²/A_e is dimensionless, so the energy per area does not depend on the edge
// length: the same fabric bends the same at 20, 10 or 5 mm on meshes of the same shape.
// ARCSim (Narain et al. 2012) uses E_e = k_e·|e|²·θ²/(8·A_e); the same cylinder argument gives
// B = k_e / 4 for its bending constant.
//
// Direction. An orthotropic sheet with rigidities B₁ (warp), B₂ (weft) and B₄₅ (bias) has, for a
// bend whose direction makes angle ψ with the warp,
//     B(ψ) = B₁·cos⁴ψ + (4·B₄₅ − B₁ − B₂)·cos²ψ·sin²ψ + B₂·sin⁴ψ
// (the classical orthotropic plate, D₁₁c⁴ + 2(D₁₂ + 2D₆₆)c²s² + D₂₂s⁴, with 2(D₁₂ + 2D₆₆) fixed
// by the bias value). Per hinge it is evaluated at the edge normal: exact for bends along the warp
// and the weft on grids aligned with the grain; elsewhere a hinge also sees bends that are not
// across it, so a strongly anisotropic fabric (B₂/B₁ of 4) bends between 0.8 and 1.7 times its B(ψ)
// along intermediate directions on equilateral meshes. Isotropic fabrics are exact in every
// direction on equilateral meshes.
#pragma once

#include <tapeline/garment/drape_types.h>

#include <algorithm>
#include <cmath>

namespace tapeline::garment {

/// Bending rigidity of a strip cut along the weft, µN·m (bending_un_m when not given).
inline double bending_weft_of(const FabricParams& f) {
    return f.bending_weft_un_m >= 0 ? f.bending_weft_un_m : f.bending_un_m;
}

/// Bending rigidity of a strip cut on the bias, µN·m (the mean of warp and weft when not given).
inline double bending_bias_of(const FabricParams& f) {
    return f.bending_bias_un_m >= 0 ? f.bending_bias_un_m
                                    : 0.5 * (f.bending_un_m + bending_weft_of(f));
}

/// Bending rigidity (µN·m) for curvature along the in-plane direction (c, s) = (cos ψ, sin ψ)
/// measured from the warp (need not be unit: it is normalised). Never negative.
inline double bending_rigidity_un_m(const FabricParams& f, double c, double s) {
    const double len2 = c * c + s * s;
    if (!(len2 > 0)) {
        return f.bending_un_m;
    }
    const double c2 = c * c / len2, s2 = s * s / len2;
    const double b1 = f.bending_un_m, b2 = bending_weft_of(f), b45 = bending_bias_of(f);
    return std::max(0.0, b1 * c2 * c2 + (4 * b45 - b1 - b2) * c2 * s2 + b2 * s2 * s2);
}

/// Stiffness k_e (µN·m) of the hinge on a rest edge: E_e = ½·k_e·θ² (k_e·1e-6 J per rad²). `edge`
/// is the edge vector and `grain` the unit warp direction, both in the rest (pattern) plane;
/// `area_e` is the rest area of the two triangles, in the unit of edge squared.
inline double hinge_stiffness_un_m(const FabricParams& f, const UV& edge, const UV& grain,
                                   double area_e) {
    const double len2 = edge[0] * edge[0] + edge[1] * edge[1];
    // In-plane normal of the edge, in the grain frame (warp, weft).
    const UV normal{-edge[1], edge[0]};
    const double c = normal[0] * grain[0] + normal[1] * grain[1];
    const double s = -normal[0] * grain[1] + normal[1] * grain[0];
    return bending_rigidity_un_m(f, c, s) * len2 / area_e;
}

}  // namespace tapeline::garment
