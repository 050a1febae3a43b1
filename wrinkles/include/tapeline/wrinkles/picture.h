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

/// The coarse drape coloured by class (above) and the fine drape coloured by its height over the
/// coarse one (below: blue more than `band_mm` inside, grey within, red more than `band_mm`
/// outside), the views of garment_views_picture.
inline draw::RgbaImage comparison_picture(const garment::GarmentMesh& coarse,
                                          const WrinkleField& field,
                                          const garment::GarmentMesh& fine,
                                          const Embedding& embedding, const std::string& title,
                                          double band_mm = 2, double scale = 0.12,
                                          double pixels_per_mm = 5) {
    const draw::RgbaImage top =
        wrinkle_picture(coarse, field, title + ": coarse, by class", {}, {}, scale, pixels_per_mm);
    std::vector<int> cls(fine.triangles.size(), 1);
    for (std::size_t f = 0; f < fine.triangles.size(); ++f) {
        double h = 0;
        for (std::uint32_t v : fine.triangles[f]) {
            h += v < embedding.vertices.size() ? embedding.vertices[v].height_mm / 3 : 0;
        }
        cls[f] = h < -band_mm ? 0 : h > band_mm ? 2 : 1;
    }
    char band[32];
    std::snprintf(band, sizeof band, "%g", band_mm);
    const draw::RgbaImage bottom = garment::garment_views_picture(
        {}, {}, fine, cls, {{0.2, 0.4, 0.9}, {0.75, 0.75, 0.75}, {0.9, 0.25, 0.2}}, {},
        title + ": fine, height over coarse", scale, pixels_per_mm,
        {std::string("< -") + band + " mm", "within", std::string("> ") + band + " mm"});
    draw::RgbaImage page =
        draw::RgbaImage::filled(std::max(top.width, bottom.width), top.height + bottom.height, 255);
    draw::Canvas canvas(page, pixels_per_mm);
    canvas.paste(top, 0, 0);
    canvas.paste(bottom, 0, long(top.height));
    return page;
}

}  // namespace tapeline::wrinkles
