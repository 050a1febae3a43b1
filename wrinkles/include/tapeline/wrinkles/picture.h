// A picture of a classified garment: front, left side and back views (garment/picture.h), every
// triangle in the colour of its wrinkle class (classify.h: none grey-blue, tension orange, shear
// violet, compression red), over the body when one is given.
#pragma once

#include <tapeline/garment/picture.h>
#include <tapeline/wrinkles/classify.h>
#include <tapeline/wrinkles/embedding.h>

#include <algorithm>
#include <string>
#include <vector>

namespace tapeline::wrinkles {

/// The picture of `field` on `g` (positions mm, the frame the views assume: y up, z to the
/// front). `body_points`/`body_tris` may be empty.
inline draw::RgbaImage wrinkle_picture(const garment::GarmentMesh& g, const WrinkleField& field,
                                       const std::string& title,
                                       const std::vector<Vec3>& body_points = {},
                                       const std::vector<Tri>& body_tris = {}, double scale = 0.12,
                                       double pixels_per_mm = 5) {
    std::vector<int> cls(g.triangles.size(), 0);
    for (std::size_t f = 0; f < cls.size() && f < field.triangles.size(); ++f) {
        cls[f] = int(field.triangles[f].cls);
    }
    std::vector<std::string> legend;
    for (std::size_t c = 0; c < kWrinkleClasses; ++c) {
        legend.push_back(to_string(WrinkleClass(c)));
    }
    return garment::garment_views_picture(body_points, body_tris, g, cls, wrinkle_class_colours(),
                                          {}, title, scale, pixels_per_mm, legend);
}

/// A fine drape coloured by a height per vertex (blue more than `band_mm` inside, grey within,
/// red more than `band_mm` outside), the views of garment_views_picture.
inline draw::RgbaImage height_picture(const garment::GarmentMesh& fine,
                                      const std::vector<double>& height_mm,
                                      const std::string& title, double band_mm = 2,
                                      double scale = 0.12, double pixels_per_mm = 5) {
    std::vector<int> cls(fine.triangles.size(), 1);
    for (std::size_t f = 0; f < fine.triangles.size(); ++f) {
        double h = 0;
        for (std::uint32_t v : fine.triangles[f]) {
            h += v < height_mm.size() ? height_mm[v] / 3 : 0;
        }
        cls[f] = h < -band_mm ? 0 : h > band_mm ? 2 : 1;
    }
    char band[32];
    std::snprintf(band, sizeof band, "%g", band_mm);
    return garment::garment_views_picture(
        {}, {}, fine, cls, {{0.2, 0.4, 0.9}, {0.75, 0.75, 0.75}, {0.9, 0.25, 0.2}}, {}, title,
        scale, pixels_per_mm,
        {std::string("< -") + band + " mm", "within", std::string("> ") + band + " mm"});
}

/// Pictures stacked top to bottom on one white page.
inline draw::RgbaImage stacked(const std::vector<draw::RgbaImage>& parts,
                               double pixels_per_mm = 5) {
    std::size_t w = 0, h = 0;
    for (const auto& p : parts) {
        w = std::max(w, std::size_t(p.width));
        h += std::size_t(p.height);
    }
    draw::RgbaImage page = draw::RgbaImage::filled(w, h, 255);
    draw::Canvas canvas(page, pixels_per_mm);
    long y = 0;
    for (const auto& p : parts) {
        canvas.paste(p, 0, y);
        y += long(p.height);
    }
    return page;
}

/// The coarse drape coloured by class (above) and the fine drape coloured by its height over the
/// coarse one (below), the views of garment_views_picture.
inline draw::RgbaImage comparison_picture(const garment::GarmentMesh& coarse,
                                          const WrinkleField& field,
                                          const garment::GarmentMesh& fine,
                                          const Embedding& embedding, const std::string& title,
                                          double band_mm = 2, double scale = 0.12,
                                          double pixels_per_mm = 5) {
    std::vector<double> h(fine.positions.size(), 0.0);
    for (std::size_t v = 0; v < h.size() && v < embedding.vertices.size(); ++v) {
        h[v] = embedding.vertices[v].height_mm;
    }
    return stacked(
        {wrinkle_picture(coarse, field, title + ": coarse, by class", {}, {}, scale, pixels_per_mm),
         height_picture(fine, h, title + ": fine, height over coarse", band_mm, scale,
                        pixels_per_mm)},
        pixels_per_mm);
}

}  // namespace tapeline::wrinkles
