// What FreeSewing's JSON leaves out and its designs imply: the seams of each design, derived from
// FreeSewing's point-naming conventions (FreeSewing exports only outline paths and named points,
// no stitch information). Each side of a seam is a list of outline chains between named outline
// vertices (the shorter way round unless a `via` vertex is given), e.g. the side seam (front hem →
// armhole against back hem → armhole) or the sleeve cap against the front and back armholes.
// The FreeSewing importer (io_freesewing.h) stores the seams of one range per side in the pattern;
// freesewing_seams() gives every seam of the design, chains of several ranges included.
#pragma once

#include <tapeline/pattern/pattern.h>
#include <tapeline/pattern/seam_chains.h>

#include <algorithm>
#include <string>
#include <vector>

namespace tapeline::pattern {

/// Seams of the FreeSewing designs, per design (a rule applies to a pattern whose name starts with
/// the design). Sides need not be equal: sleeve-cap ease and a binding strip shorter than the edge
/// it binds are part of the draft.
inline const std::vector<NamedSeamRule>& freesewing_seam_rules() {
    static const std::vector<NamedSeamRule> rules = {
        {"aaron", "side", {{"front", "hem", "armhole"}}, {{"back", "hem", "armhole"}}},
        {"aaron",
         "shoulder",
         {{"front", "strapRight", "strapLeft"}},
         {{"back", "strapRight", "strapLeft"}}},
        {"aaron",
         "armhole binding",
         {{"armBinding", "topLeft", "bottomLeft"}},
         {{"front", "armhole", "strapRight"}, {"back", "armhole", "strapRight"}}},
        {"aaron",
         "neck binding",
         {{"neckBinding", "topLeft", "bottomLeft"}},
         {{"front", "strapLeft", "cfNeck"}, {"back", "strapLeft", "cbNeck"}}},
        {"brian", "side", {{"front", "hips", "armhole"}}, {{"back", "hips", "armhole"}}},
        {"brian", "shoulder", {{"front", "shoulder", "neck"}}, {{"back", "shoulder", "neck"}}},
        {"brian",
         "armhole",
         {{"sleeve", "bicepsRight", "bicepsLeft", "capQ2"}},
         {{"front", "armhole", "shoulder"}, {"back", "armhole", "shoulder"}}},
        {"brian",
         "sleeve",
         {{"sleeve", "bicepsLeft", "wristLeft"}},
         {{"sleeve", "bicepsRight", "wristRight"}}},
        {"teagan", "side", {{"front", "hem", "armhole"}}, {{"back", "hem", "armhole"}}},
        {"teagan", "shoulder", {{"front", "shoulder", "neck"}}, {{"back", "shoulder", "neck"}}},
        {"teagan",
         "armhole",
         {{"sleeve", "bicepsRight", "bicepsLeft", "capQ2"}},
         {{"front", "armhole", "shoulder"}, {"back", "armhole", "shoulder"}}},
        {"teagan",
         "sleeve",
         {{"sleeve", "bicepsLeft", "hemLeft"}},
         {{"sleeve", "bicepsRight", "hemRight"}}},
        {"titan",
         "outseam",
         {{"front", "styleWaistOut", "floorOut"}},
         {{"back", "styleWaistOut", "floorOut"}}},
        {"titan", "inseam", {{"front", "fork", "floorIn"}}, {{"back", "fork", "floorIn"}}},
        {"simon", "side", {{"frontRight", "hem", "armhole"}}, {{"back", "hem", "armhole"}}},
        {"simon", "shoulder", {{"frontRight", "shoulder", "neck"}}, {{"yoke", "shoulder", "neck"}}},
        {"simon",
         "armhole",
         {{"sleeve", "bicepsRight", "bicepsLeft", "capQ2"}},
         {{"frontRight", "armhole", "shoulder"},
          {"back", "armhole", "armholeYokeSplit"},
          {"yoke", "armholeYokeSplit", "shoulder"}}},
        {"simon",
         "sleeve",
         {{"sleeve", "bicepsLeft", "wristLeft"}},
         {{"sleeve", "bicepsRight", "wristRight"}}},
        {"simon",
         "cuff",
         {{"cuff", "bottomLeft", "bottomRight"}},
         {{"sleeve", "wristLeft", "wristRight", "cuffMid"}}},
    };
    return rules;
}

/// Seams between a piece of a FreeSewing design and its own mirror image: trousers are drafted as
/// one leg (a front and a back, cut twice), and the crotch seam joins the two fronts from the
/// centre-front waist to the fork, the two backs likewise. Side B names the mirrored copy,
/// "PIECE (mirror)", which exists once the pattern is unfolded for dressing (garment/unfold.h);
/// these rules are applied there, not on import.
inline const std::vector<NamedSeamRule>& freesewing_mirror_seam_rules() {
    static const std::vector<NamedSeamRule> rules = {
        {"titan",
         "crotch front",
         {{"front", "styleWaistIn", "fork"}},
         {{"front (mirror)", "styleWaistIn", "fork"}}},
        {"titan",
         "crotch back",
         {{"back", "styleWaistIn", "fork"}},
         {{"back (mirror)", "styleWaistIn", "fork"}}},
    };
    return rules;
}

/// The label of the outline edges a garment is held up by when dressed (garment/README.md:
/// waistbands); GarmentCode marks the same edges `lower_interface`.
inline const std::string& waist_label() {
    static const std::string label = "waist";
    return label;
}

/// The waist edges of FreeSewing's trouser designs, from the centre waist to the side: the
/// edges dressing holds at their height (a waistband) where nothing is sewn to them.
inline const std::vector<NamedLabelRule>& freesewing_label_rules() {
    static const std::vector<NamedLabelRule> rules = {
        {"titan", waist_label(), {"front", "styleWaistIn", "styleWaistOut", ""}},
        {"titan", waist_label(), {"back", "styleWaistIn", "styleWaistOut", ""}},
    };
    return rules;
}

/// The seams FreeSewing's designs imply (freesewing_seam_rules) for a pattern imported from
/// FreeSewing; a rule whose chains are not all found on this draft is named in `skipped`.
inline std::vector<SeamSpec> freesewing_seams(const Pattern& p,
                                              std::vector<std::string>* skipped = nullptr) {
    return named_seams(p, freesewing_seam_rules(), skipped);
}

/// Adds to `p.seams` the seams of freesewing_seams(p) that a Pattern can hold (one edge range per
/// side) and that it does not hold yet (by name); returns how many were added.
inline std::size_t add_freesewing_seams(Pattern& p, std::vector<std::string>* skipped = nullptr) {
    std::size_t added = 0;
    for (Seam& s : pattern_seams(freesewing_seams(p, skipped))) {
        const bool held = std::any_of(p.seams.begin(), p.seams.end(),
                                      [&](const Seam& q) { return q.name == s.name; });
        if (!held) {
            p.seams.push_back(std::move(s));
            ++added;
        }
    }
    return added;
}

}  // namespace tapeline::pattern
