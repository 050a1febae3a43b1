// PNG encoding (draw/png.h), read back with libpng's simplified reader: the pixels come back as
// they were written, the header states the size, the pHYs chunk the resolution, a malformed image
// is refused with a message naming its size, and write_png to a path leaves the same bytes.
#include <tapeline/core/errors.h>
#include <tapeline/draw/png.h>

#include <tapeline_test/image.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

using namespace tapeline::draw;

namespace {

std::uint32_t be32(const std::vector<std::uint8_t>& b, std::size_t at) {
    return (std::uint32_t(b[at]) << 24) | (std::uint32_t(b[at + 1]) << 16) |
           (std::uint32_t(b[at + 2]) << 8) | std::uint32_t(b[at + 3]);
}

RgbaImage gradient(std::size_t w, std::size_t h) {
    RgbaImage img = RgbaImage::filled(w, h, 0);
    for (std::size_t y = 0; y < h; ++y) {
        for (std::size_t x = 0; x < w; ++x) {
            std::uint8_t* p = &img.rgba[4 * (y * w + x)];
            p[0] = std::uint8_t(x * 7);
            p[1] = std::uint8_t(y * 11);
            p[2] = std::uint8_t(x + y);
            p[3] = std::uint8_t(255 - x);
        }
    }
    return img;
}

}  // namespace

TEST(DrawPng, RoundTripHeaderAndResolution) {
    const RgbaImage img = gradient(13, 7);
    const std::vector<std::uint8_t> png = encode_png(img, 2.5);
    ASSERT_GT(png.size(), 33u);
    const std::uint8_t sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    EXPECT_TRUE(std::equal(sig, sig + 8, png.begin()));
    EXPECT_EQ(std::string(png.begin() + 12, png.begin() + 16), "IHDR");
    EXPECT_EQ(be32(png, 16), 13u);
    EXPECT_EQ(be32(png, 20), 7u);
    // pHYs: 2.5 px/mm is 2500 px per metre on both axes, unit byte 1 (metre).
    const std::string s(png.begin(), png.end());
    const std::size_t at = s.find("pHYs");
    ASSERT_NE(at, std::string::npos);
    EXPECT_EQ(be32(png, at + 4), 2500u);
    EXPECT_EQ(be32(png, at + 8), 2500u);
    EXPECT_EQ(png[at + 12], 1);
    // Straight (non-premultiplied) RGBA comes back unchanged.
    const tapeline_test::Decoded d = tapeline_test::decode(s);
    ASSERT_EQ(d.width, 13u);
    ASSERT_EQ(d.height, 7u);
    EXPECT_EQ(d.rgba, img.rgba);
}

TEST(DrawPng, WritesToStreamAndFileAlike) {
    const RgbaImage img = gradient(5, 4);
    std::ostringstream out;
    const std::size_t n = write_png(out, img, 1);
    const std::vector<std::uint8_t> bytes = encode_png(img, 1);
    EXPECT_EQ(n, bytes.size());
    EXPECT_EQ(out.str(), std::string(bytes.begin(), bytes.end()));
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() / "tapeline_draw_test_png.png";
    EXPECT_EQ(write_png(path.string(), img, 1), bytes.size());
    std::ifstream in(path, std::ios::binary);
    const std::string file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(file, out.str());
    std::filesystem::remove(path);
}

TEST(DrawPng, MalformedImageIsRefused) {
    RgbaImage bad;
    bad.width = 3;
    bad.height = 2;
    bad.rgba.assign(5, 0);
    for (const RgbaImage& img : {bad, RgbaImage{}}) {
        try {
            encode_png(img, 1);
            ADD_FAILURE() << "accepted " << img.width << " × " << img.height;
        } catch (const tapeline::InvalidInput& e) {
            const std::string m = e.what();
            EXPECT_NE(m.find("PNG encoding: image of " + std::to_string(img.width) + " × " +
                             std::to_string(img.height) + " pixels with " +
                             std::to_string(img.rgba.size()) + " bytes is malformed"),
                      std::string::npos)
                << m;
        }
    }
}
