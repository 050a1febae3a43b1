// Reading pictures back in tests: PNG bytes decoded with libpng's simplified reader (a different
// code path from the writer, draw/png.h), grey levels composited on white, and the pixel box a
// text of the bitmap font may ink. Header-only (libpng and gtest only).
#pragma once

#include <tapeline/draw/canvas.h>

#include <gtest/gtest.h>
#include <png.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace tapeline_test {

struct Decoded {
    std::size_t width = 0, height = 0;
    std::vector<std::uint8_t> rgba;
    const std::uint8_t* at(long x, long y) const { return &rgba[4 * (std::size_t(y) * width + x)]; }
    /// Darkest grey level (mean of RGB, alpha-composited on white) in the 3 × 3 block around.
    double darkest(long x, long y) const {
        double best = 255;
        for (long dy = -1; dy <= 1; ++dy) {
            for (long dx = -1; dx <= 1; ++dx) {
                const long xx = std::clamp(x + dx, 0L, long(width) - 1);
                const long yy = std::clamp(y + dy, 0L, long(height) - 1);
                best = std::min(best, grey(xx, yy));
            }
        }
        return best;
    }
    double grey(long x, long y) const {
        const std::uint8_t* p = at(x, y);
        const double a = p[3] / 255.0;
        return (p[0] + p[1] + p[2]) / 3.0 * a + 255 * (1 - a);
    }
};

inline Decoded decode(const std::string& bytes) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    Decoded d;
    if (!png_image_begin_read_from_memory(&image, bytes.data(), bytes.size())) {
        ADD_FAILURE() << "libpng cannot read the PNG: " << image.message;
        return d;
    }
    image.format = PNG_FORMAT_RGBA;
    d.width = image.width;
    d.height = image.height;
    d.rgba.resize(PNG_IMAGE_SIZE(image));
    if (!png_image_finish_read(&image, nullptr, d.rgba.data(), 0, nullptr)) {
        ADD_FAILURE() << "libpng decode failed: " << image.message;
    }
    return d;
}

inline Decoded from_image(const tapeline::draw::RgbaImage& img) {
    return {img.width, img.height, img.rgba};
}

/// Pixel box [x0, x1) × [y0, y1) where a text's ink may lie: the font's box (advance 0.6 em per
/// character, 0.7 em above the baseline, 0.1 em below) grown by `grow_cells` glyph cells
/// (0.6 × 0.8 em) on every side — the tolerance for a font whose exact proportions the test does
/// not pin down.
struct PixelBox {
    long x0, y0, x1, y1;
    bool contains(long x, long y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
};

inline PixelBox text_box(double x, double y, double size, bool middle, std::size_t n, double ppmm,
                         double grow_cells = 1) {
    const double w = 0.6 * size * double(n);
    const double left = middle ? x - 0.5 * w : x;
    const double gx = grow_cells * 0.6 * size, gy = grow_cells * 0.8 * size;
    return {long(std::floor((left - gx) * ppmm)), long(std::floor((y - 0.7 * size - gy) * ppmm)),
            long(std::ceil((left + w + gx) * ppmm)), long(std::ceil((y + 0.1 * size + gy) * ppmm))};
}

}  // namespace tapeline_test
