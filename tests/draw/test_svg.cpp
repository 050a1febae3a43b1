// SVG helpers (draw/svg.h): numbers (fixed and trimmed, no "-0"), point lists, colours, base64
// against RFC 4648's test vectors, the PNG data URI decoding to the PNG bytes, and the document's
// opening tag.
#include <tapeline/draw/svg.h>

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

using namespace tapeline::draw;

TEST(DrawSvg, Numbers) {
    EXPECT_EQ(svg_fixed(1.5), "1.500");
    EXPECT_EQ(svg_fixed(2.0 / 3, 2), "0.67");
    EXPECT_EQ(svg_number(1.5), "1.5");
    EXPECT_EQ(svg_number(100), "100");
    EXPECT_EQ(svg_number(0.0004), "0");
    EXPECT_EQ(svg_number(-0.0004), "0");
    EXPECT_EQ(svg_number(-0.004, 2), "0");
    EXPECT_EQ(svg_number(-1.25, 1), "-1.2");  // printf rounding of the binary value 1.25
    EXPECT_EQ(svg_number(12.3456, 2), "12.35");
    EXPECT_EQ(svg_number(1e6, 0), "1000000");  // no decimals: nothing to trim
    EXPECT_EQ(svg_points({{1, 2.5}, {-0.0001, 3.14159}}, 2), "1,2.5 0,3.14");
    EXPECT_EQ(svg_points({{1, 2.5}}, 3, false), "1.000,2.500");
    EXPECT_EQ(svg_points({}), "");
}

TEST(DrawSvg, ColoursAndEscaping) {
    EXPECT_EQ(svg_colour({1, 0, 0.5}), "#ff0080");
    EXPECT_EQ(svg_colour({2, -1, 0}), "#ff0000");
    EXPECT_EQ(xml_escape("a<b & \"c\" 'd'>"), "a&lt;b &amp; &quot;c&quot; &apos;d&apos;&gt;");
}

TEST(DrawSvg, Base64Rfc4648Vectors) {
    const auto b64 = [](const std::string& s) {
        return base64(std::vector<std::uint8_t>(s.begin(), s.end()));
    };
    EXPECT_EQ(b64(""), "");
    EXPECT_EQ(b64("f"), "Zg==");
    EXPECT_EQ(b64("fo"), "Zm8=");
    EXPECT_EQ(b64("foo"), "Zm9v");
    EXPECT_EQ(b64("foob"), "Zm9vYg==");
    EXPECT_EQ(b64("fooba"), "Zm9vYmE=");
    EXPECT_EQ(b64("foobar"), "Zm9vYmFy");
}

TEST(DrawSvg, PngDataUriAndDocumentOpening) {
    const RgbaImage img = RgbaImage::filled(2, 2, 255);
    const std::string uri = png_data_uri(img, 1);
    const std::string prefix = "data:image/png;base64,";
    ASSERT_EQ(uri.rfind(prefix, 0), 0u);
    EXPECT_EQ(uri.substr(prefix.size()), base64(encode_png(img, 1)));
    std::ostringstream out;
    svg_open(out, "10", "20", "mm", " version=\"1.1\"", " font-family=\"sans-serif\"");
    EXPECT_EQ(
        out.str(),
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" "
        "version=\"1.1\" width=\"10mm\" height=\"20mm\" viewBox=\"0 0 10 20\" "
        "font-family=\"sans-serif\">\n");
}
