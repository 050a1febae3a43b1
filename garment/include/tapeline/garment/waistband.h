// Waistbands: the open waist of a skirt or a pair of trousers is held at its height while the
// garment drapes, as a waistband or a belt holds it; nothing else holds trousers up but the
// hips and friction, and a waist wider than the body's slides down over them.
//
// A pattern asks for it by labelling outline edges: `waist` (tapeline pattern JSON; FreeSewing
// trousers get it from the design table, pattern/freesewing_designs.h) or GarmentCode's
// `lower_interface`. Only edges no seam sews are held: a waist sewn to a bodice (a jumpsuit, a
// dress) hangs from it. Each vertex of those edges is held by an attachment along the vertical
// axis at the height it has when the sewing ends (DrapeSolver's axis attachments): it may slide
// round the body and in or out, and sink only as far as a spring lets it (DressOptions::
// waistband_sag_mm: the band alone would carry the garment's weight that far down).
#pragma once

#include <tapeline/garment/drape_types.h>
#include <tapeline/pattern/freesewing_designs.h>
#include <tapeline/pattern/meshing_types.h>
#include <tapeline/pattern/pattern.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

namespace tapeline::garment {

/// True for the outline-edge labels that ask for a waistband: `waist` and GarmentCode's
/// `lower_interface`.
inline bool is_waistband_label(const std::string& label) {
    return label == pattern::waist_label() || label == "lower_interface";
}

/// The vertices (indices into the pieces' meshes laid end to end: `offsets`, stitching.h's
/// piece_offsets) of the outline edges labelled for a waistband that no seam of `p` sews, sorted.
/// `pm` is `p` meshed (one PieceMesh per piece, in order).
inline std::vector<std::uint32_t> waistband_vertices(const pattern::Pattern& p,
                                                     const pattern::PatternMesh& pm,
                                                     const std::vector<std::uint32_t>& offsets) {
    std::vector<std::uint32_t> out;
    for (std::size_t i = 0; i < p.pieces.size() && i < pm.pieces.size(); ++i) {
        const pattern::Piece& piece = p.pieces[i];
        const std::size_t n = piece.outline.edges.size();
        std::vector<std::uint8_t> sewn(n, 0);
        for (const pattern::Seam& s : p.seams) {
            for (const pattern::EdgeRange* r : {&s.a, &s.b}) {
                if (r->piece != piece.name) {
                    continue;
                }
                for (std::size_t k = 0; k < r->count && n > 0; ++k) {
                    sewn[(r->first_edge + k) % n] = 1;
                }
            }
        }
        for (std::size_t e = 0; e < n && e < pm.pieces[i].edge_vertices.size(); ++e) {
            if (sewn[e] || !is_waistband_label(piece.outline.edges[e].label)) {
                continue;
            }
            for (std::uint32_t v : pm.pieces[i].edge_vertices[e]) {
                out.push_back(offsets[i] + v);
            }
        }
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

/// The XPBD compliance (mm/N) of each of `held` vertices' holds such that together, springs in
/// parallel, they carry a garment weighing `weight_n` (N) `sag_mm` below their height:
/// held·sag / weight (0 for a weightless garment: hard holds).
inline double waistband_compliance(double weight_n, std::size_t held, double sag_mm) {
    return weight_n > 0 ? double(held) * sag_mm / weight_n : 0.0;
}

/// Attachments holding each of `vertices` (indices into `x`, distinct) at its height in `x`: along
/// the vertical axis (y) only, with XPBD `compliance` (mm/N).
inline std::vector<Attachment> waistband_attachments(const std::vector<Vec3>& x,
                                                     const std::vector<std::uint32_t>& vertices,
                                                     double compliance) {
    std::vector<Attachment> out;
    out.reserve(vertices.size());
    for (std::uint32_t v : vertices) {
        Attachment a;
        a.vertex = v;
        a.target = x[v];
        a.compliance = compliance;
        a.axis = {0, 1, 0};
        out.push_back(a);
    }
    return out;
}

}  // namespace tapeline::garment
