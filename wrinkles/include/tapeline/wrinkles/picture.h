// A picture of a classified garment: front, left side and back views (garment/picture.h), every
// triangle in the colour of its wrinkle class (classify.h: none grey-blue, tension orange, shear
// violet, compression red), over the body when one is given.
#pragma once

#include <tapeline/garment/picture.h>
#include <tapeline/wrinkles/classify.h>

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

}  // namespace tapeline::wrinkles
