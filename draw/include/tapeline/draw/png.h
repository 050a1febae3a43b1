// PNG encoding of an RGBA image (canvas.h) with libpng: 8-bit RGBA, a pHYs chunk giving the
// resolution so that viewers and printers can reproduce a 1:1 scale; and the same bytes written to
// a stream or, atomically, to a file. tapeline::draw links PNG::PNG.
#pragma once

#include <tapeline/core/atomic_write.h>
#include <tapeline/core/errors.h>
#include <tapeline/draw/canvas.h>

#include <png.h>

#include <cmath>
#include <cstdint>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace tapeline::draw {

namespace internal {

inline void png_write_to_vector(png_structp png, png_bytep data, png_size_t n) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(png_get_io_ptr(png));
    out->insert(out->end(), data, data + n);
}

inline void png_flush_nothing(png_structp) {}

inline void png_error_throw(png_structp png, png_const_charp msg) {
    *static_cast<std::string*>(png_get_error_ptr(png)) = msg;
    png_longjmp(png, 1);
}

inline void png_warning_ignore(png_structp, png_const_charp) {}

/// libpng reports errors by longjmp; this frame holds no C++ objects with destructors.
inline bool png_encode_raw(const RgbaImage& img, double ppmm, std::vector<std::uint8_t>* out,
                           std::string* error, png_bytep* rows) {
    png_structp png =
        png_create_write_struct(PNG_LIBPNG_VER_STRING, error, png_error_throw, png_warning_ignore);
    if (!png) {
        return false;
    }
    png_infop info = png_create_info_struct(png);
    if (!info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return false;
    }
    png_set_write_fn(png, out, png_write_to_vector, png_flush_nothing);
    png_set_IHDR(png, info, png_uint_32(img.width), png_uint_32(img.height), 8,
                 PNG_COLOR_TYPE_RGB_ALPHA, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    const auto ppm = png_uint_32(std::lround(ppmm * 1000.0));
    png_set_pHYs(png, info, ppm, ppm, PNG_RESOLUTION_METER);
    png_set_rows(png, info, rows);
    png_write_png(png, info, PNG_TRANSFORM_IDENTITY, nullptr);
    png_destroy_write_struct(&png, &info);
    return true;
}

}  // namespace internal

/// PNG bytes of an RGBA image; `pixels_per_mm` goes into the pHYs chunk.
///
/// \throws InvalidInput when the image is empty or its byte count is not 4 width height.
/// \throws std::runtime_error when libpng fails (out of memory).
inline std::vector<std::uint8_t> encode_png(const RgbaImage& img, double pixels_per_mm) {
    if (img.width == 0 || img.height == 0 || img.rgba.size() != 4 * img.width * img.height) {
        throw InvalidInput("PNG encoding: image of " + std::to_string(img.width) + " × " +
                           std::to_string(img.height) + " pixels with " +
                           std::to_string(img.rgba.size()) + " bytes is malformed");
    }
    std::vector<png_bytep> rows(img.height);
    for (std::size_t y = 0; y < img.height; ++y) {
        rows[y] = const_cast<png_bytep>(&img.rgba[4 * y * img.width]);
    }
    std::vector<std::uint8_t> out;
    std::string error = "out of memory";
    if (!internal::png_encode_raw(img, pixels_per_mm, &out, &error, rows.data())) {
        throw std::runtime_error("PNG encoding failed: " + error);
    }
    return out;
}

/// Writes the PNG of `img` to `out`; returns the number of bytes written.
///
/// \throws InvalidInput as encode_png.
/// \throws std::runtime_error as encode_png.
inline std::size_t write_png(std::ostream& out, const RgbaImage& img, double pixels_per_mm) {
    const std::vector<std::uint8_t> bytes = encode_png(img, pixels_per_mm);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    return bytes.size();
}

/// Writes the PNG of `img` to `path` atomically (no half-written file on failure).
///
/// \throws InvalidInput as encode_png, or naming `path` when it cannot be written.
/// \throws std::runtime_error as encode_png.
inline std::size_t write_png(const std::string& path, const RgbaImage& img, double pixels_per_mm) {
    std::size_t n = 0;
    write_file_atomically(
        path, [&](std::ostream& out) { n = write_png(out, img, pixels_per_mm); }, true);
    return n;
}

}  // namespace tapeline::draw
