// The measurement picture (measurement/picture.h): front and side views of a measured body as SVG
// and PNG. Oracles: the measurement's own points (every tape drawn with one vertex per point, its
// projection exactly the orthographic map the report states), XML well-formedness, the PNG
// signature and header, and pixels that must be body, tape or background.
#include <tapeline/core/errors.h>
#include <tapeline/core/xml_escape.h>
#include <tapeline/measurement/synthetic_body.h>
#include <tapeline_test/picture.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace tapeline_test::measurement;
namespace fs = std::filesystem;

namespace {

struct Element {
    std::string name;
    std::map<std::string, std::string> attrs;
    std::string text;  ///< character data right after the start tag
};

/// A small XML reader: start, end and empty tags must balance; attributes are name="value".
/// Returns the elements in document order, or an error.
bool parse_xml(const std::string& s, std::vector<Element>& out, std::string& error) {
    std::vector<std::string> open;
    std::size_t i = 0;
    while ((i = s.find('<', i)) != std::string::npos) {
        if (s.compare(i, 2, "<?") == 0) {
            i = s.find("?>", i);
            if (i == std::string::npos) {
                error = "unterminated <?";
                return false;
            }
            continue;
        }
        if (s.compare(i, 2, "</") == 0) {
            const std::size_t e = s.find('>', i);
            const std::string name = s.substr(i + 2, e - i - 2);
            if (open.empty() || open.back() != name) {
                error = "</" + name + "> closes " + (open.empty() ? "nothing" : open.back());
                return false;
            }
            open.pop_back();
            i = e + 1;
            continue;
        }
        Element el;
        std::size_t j = i + 1;
        while (j < s.size() && !std::isspace(static_cast<unsigned char>(s[j])) && s[j] != '>' &&
               s[j] != '/') {
            el.name += s[j++];
        }
        bool empty = false;
        for (;;) {
            while (j < s.size() && std::isspace(static_cast<unsigned char>(s[j]))) {
                ++j;
            }
            if (j >= s.size()) {
                error = "unterminated <" + el.name;
                return false;
            }
            if (s[j] == '>') {
                ++j;
                break;
            }
            if (s.compare(j, 2, "/>") == 0) {
                empty = true;
                j += 2;
                break;
            }
            const std::size_t eq = s.find('=', j);
            if (eq == std::string::npos || s[eq + 1] != '"') {
                error = "bad attribute in <" + el.name;
                return false;
            }
            const std::string key = s.substr(j, eq - j);
            const std::size_t end = s.find('"', eq + 2);
            if (end == std::string::npos) {
                error = "unterminated attribute " + key;
                return false;
            }
            const std::string value = s.substr(eq + 2, end - eq - 2);
            if (value.find('<') != std::string::npos) {
                error = "raw < in attribute " + key;
                return false;
            }
            if (!el.attrs.emplace(key, value).second) {
                error = "duplicate attribute " + key;
                return false;
            }
            j = end + 1;
        }
        if (!empty) {
            open.push_back(el.name);
            const std::size_t next = s.find('<', j);
            el.text = s.substr(j, next - j);
        }
        out.push_back(std::move(el));
        i = j;
    }
    if (!open.empty()) {
        error = "<" + open.back() + "> not closed";
        return false;
    }
    return true;
}

std::vector<std::pair<double, double>> parse_points(const std::string& attr) {
    std::vector<std::pair<double, double>> pts;
    std::istringstream in(attr);
    std::string pair;
    while (in >> pair) {
        const std::size_t comma = pair.find(',');
        pts.emplace_back(std::stod(pair.substr(0, comma)), std::stod(pair.substr(comma + 1)));
    }
    return pts;
}

std::string value_text(const Measurement& m) {
    char s[32];
    std::snprintf(s, sizeof s, m.kind == MeasurementKind::angle ? "%.1f deg" : "%.1f mm", m.value);
    return s;
}

double distance_to_segment(double px, double py, double ax, double ay, double bx, double by) {
    const double dx = bx - ax, dy = by - ay, len2 = dx * dx + dy * dy;
    const double t = len2 > 0 ? std::clamp(((px - ax) * dx + (py - ay) * dy) / len2, 0.0, 1.0) : 0;
    return std::hypot(px - ax - t * dx, py - ay - t * dy);
}

/// The synthetic body (analytic test body of the module), measured, with canonical points.
struct Measured {
    std::vector<Vec3> points;
    Triangles triangles;
    Result result;
};

const Measured& synthetic() {
    static const Measured m = [] {
        Measured out;
        const SyntheticBody body;
        out.result = measure_synthetic({});
        for (const auto& p : body.points()) {
            // measure_synthetic reads the points in mm, +Y up, +Z front: canonical up to the floor.
            out.points.push_back(out.result.frame.to_canonical(p));
        }
        out.triangles = body.triangles();
        // A length along the skin down the front of the torso (an open path), and a name that
        // needs escaping.
        Measurement len;
        len.name = "front<length>&test";
        len.kind = MeasurementKind::length;
        for (double y = 1300; y >= 900; y -= 50) {
            len.points.push_back({0, y, SyntheticBody().torso_depth(y) + 1});
        }
        len.value = 400;
        out.result.measurements.add(len);
        return out;
    }();
    return m;
}

const Picture& synthetic_picture() {
    static const Picture p = [] {
        PictureOptions o;
        o.title = "synthetic body";
        const Measured& m = synthetic();
        return draw_picture(m.points, m.triangles, m.result.measurements, m.result.landmarks, o);
    }();
    return p;
}

std::vector<Element> svg_elements() {
    std::vector<Element> els;
    std::string error;
    EXPECT_TRUE(parse_xml(synthetic_picture().svg, els, error)) << error;
    return els;
}

}  // namespace

TEST(MeasurementPicture, SvgWellFormedWithOneLabelledTapePerMeasurementAndView) {
    const Measured& m = synthetic();
    ASSERT_GE(m.result.measurements.measurements.size(), 8u);
    const std::vector<Element> els = svg_elements();
    ASSERT_FALSE(els.empty());
    EXPECT_EQ(els.front().name, "svg");
    for (const Measurement& meas : m.result.measurements.measurements) {
        SCOPED_TRACE(meas.name);
        const std::string escaped = tapeline::xml_escape(meas.name);
        int groups = 0, labels = 0;
        std::map<std::string, int> tapes;
        for (const Element& e : els) {
            const auto name = e.attrs.find("data-name");
            if (e.name == "g" && name != e.attrs.end() && name->second == escaped) {
                ++groups;
                char v[32];
                std::snprintf(v, sizeof v, "%.2f", meas.value);
                const bool angle = meas.kind == MeasurementKind::angle;
                const auto value = e.attrs.find(angle ? "data-value-degrees" : "data-value-mm");
                ASSERT_NE(value, e.attrs.end());
                EXPECT_EQ(value->second, v);
            }
            const auto tm = e.attrs.find("data-measurement");
            if (tm != e.attrs.end() && tm->second == escaped) {
                const std::string view = e.attrs.at("data-view");
                ++tapes[view];
                EXPECT_EQ(e.name, meas.closed ? "polygon" : "polyline");
                EXPECT_EQ(parse_points(e.attrs.at("points")).size(), meas.points.size());
            }
            if (e.name == "text" && e.attrs.count("class") && e.attrs.at("class") == "label" &&
                e.text == escaped + " " + value_text(meas)) {
                ++labels;
            }
        }
        EXPECT_EQ(groups, 1);
        EXPECT_EQ(labels, 1);
        EXPECT_EQ(tapes["front"], 1);
        EXPECT_EQ(tapes["side"], 1);
    }
    EXPECT_NE(synthetic_picture().svg.find("front&lt;length&gt;&amp;test"), std::string::npos);
    EXPECT_EQ(synthetic_picture().svg.find("front<length>"), std::string::npos);
    EXPECT_EQ(synthetic_picture().svg_report.measurements_drawn,
              m.result.measurements.measurements.size());
    // Every available landmark is a dot in both views.
    std::size_t dots = 0;
    for (const Element& e : els) {
        dots += e.name == "circle" && e.attrs.count("data-landmark");
    }
    EXPECT_EQ(dots, 2 * m.result.landmarks.available_count());
    EXPECT_GT(m.result.landmarks.available_count(), 10u);
}

TEST(MeasurementPicture, TapesAreTheOrthographicProjectionOfTheMeasurementPoints) {
    const Measured& m = synthetic();
    const PictureReport& rep = synthetic_picture().svg_report;
    ASSERT_EQ(rep.views.size(), 2u);
    EXPECT_EQ(rep.views[0].name, "front");
    EXPECT_EQ(rep.views[1].name, "side");
    // The figure faces the viewer: a tailor facing the client sees the client's left hand (+x)
    // on the right. The side view is seen from the body's left: its front (+z) points left.
    EXPECT_EQ(rep.views[0].right, (Vec3{1, 0, 0}));
    EXPECT_EQ(rep.views[1].right, (Vec3{0, 0, -1}));
    const std::vector<Element> els = svg_elements();
    for (const char* name : {"waist_girth", "hip_girth", "bust_girth", "front<length>&test"}) {
        SCOPED_TRACE(name);
        const Measurement* meas = m.result.measurements.find(name);
        ASSERT_NE(meas, nullptr);
        for (int k = 0; k < 2; ++k) {
            const PictureView& v = rep.views[std::size_t(k)];
            const Element* tape = nullptr;
            for (const Element& e : els) {
                if (e.attrs.count("data-measurement") &&
                    e.attrs.at("data-measurement") == tapeline::xml_escape(name) &&
                    e.attrs.at("data-view") == v.name) {
                    tape = &e;
                }
            }
            ASSERT_NE(tape, nullptr);
            const auto pts = parse_points(tape->attrs.at("points"));
            ASSERT_EQ(pts.size(), meas->points.size());
            double lo = 1e300, hi = -1e300, plo = 1e300, phi = -1e300;
            for (std::size_t i = 0; i < pts.size(); ++i) {
                const Vec3& p = meas->points[i];
                const double u = p[0] * v.right[0] + p[1] * v.right[1] + p[2] * v.right[2];
                // Written with two decimals: within 0.005 mm plus rounding of the sum.
                EXPECT_NEAR(pts[i].first, v.origin_x_mm + rep.scale * u, 0.006);
                EXPECT_NEAR(pts[i].second, v.origin_y_mm - rep.scale * p[1], 0.006);
                lo = std::min(lo, u);
                hi = std::max(hi, u);
                plo = std::min(plo, pts[i].first);
                phi = std::max(phi, pts[i].first);
            }
            // The drawn extent is the measurement's extent at the picture's scale.
            EXPECT_NEAR(phi - plo, rep.scale * (hi - lo), 0.012);
            // Inside the view's box.
            EXPECT_GE(plo, v.left_mm - 0.01);
            EXPECT_LE(phi, v.left_mm + v.width_mm + 0.01);
        }
    }
    // The waist girth is an ellipse 2 × 135 wide across the front view (synthetic truth).
    const Measurement* waist = m.result.measurements.find("waist_girth");
    double lo = 1e300, hi = -1e300;
    for (const Vec3& p : waist->points) {
        lo = std::min(lo, p[0]);
        hi = std::max(hi, p[0]);
    }
    EXPECT_NEAR(hi - lo, 2 * SyntheticBody().torso_half_width(SyntheticBody::kWaist), 3.0);
}

TEST(MeasurementPicture, LoopsHalfHiddenLabelsApartAndInsideThePage) {
    const Measured& m = synthetic();
    const Picture& pic = synthetic_picture();
    const std::vector<Element> els = svg_elements();
    // Front view of the waist loop: its front half is visible, its back half hidden.
    const Measurement* waist = m.result.measurements.find("waist_girth");
    std::size_t visible_points = 0;
    bool inside_group = false;
    for (const Element& e : els) {
        if (e.name == "g" && e.attrs.count("data-name")) {
            inside_group = e.attrs.at("data-name") == "waist_girth";
        }
        if (inside_group && e.attrs.count("class") && e.attrs.at("class") == "tape-visible" &&
            e.attrs.at("data-view") == "front") {
            visible_points += parse_points(e.attrs.at("points")).size();
        }
    }
    EXPECT_GT(double(visible_points), 0.3 * double(waist->points.size()));
    EXPECT_LT(double(visible_points), 0.8 * double(waist->points.size()));
    // Labels: one per measurement, inside the page, apart by more than a font size per column.
    const PictureReport& rep = pic.svg_report;
    ASSERT_EQ(rep.labels.size(), m.result.measurements.measurements.size());
    std::map<double, std::vector<double>> columns;
    for (const PictureLabel& l : rep.labels) {
        SCOPED_TRACE(l.measurement);
        EXPECT_GT(l.x_mm, 0);
        EXPECT_LT(l.x_mm, rep.width_mm);
        EXPECT_GT(l.y_mm, 0);
        EXPECT_LT(l.y_mm, rep.height_mm);
        columns[std::round(l.x_mm)].push_back(l.y_mm);
        // The leader ends on the tape.
        const Measurement* meas = m.result.measurements.find(l.measurement);
        const PictureView& v = rep.views[l.view == "front" ? 0 : 1];
        double best = 1e300;
        for (const Vec3& p : meas->points) {
            const double u = p[0] * v.right[0] + p[1] * v.right[1] + p[2] * v.right[2];
            best = std::min(best, std::hypot(l.anchor_x_mm - (v.origin_x_mm + rep.scale * u),
                                             l.anchor_y_mm - (v.origin_y_mm - rep.scale * p[1])));
        }
        EXPECT_LT(best, 1e-6);
        // Left-column labels are left of the front view, the others right of it.
        EXPECT_TRUE(l.x_mm < rep.views[0].left_mm ||
                    l.x_mm > rep.views[0].left_mm + rep.views[0].width_mm);
    }
    for (auto& [x, ys] : columns) {
        std::sort(ys.begin(), ys.end());
        for (std::size_t i = 1; i < ys.size(); ++i) {
            EXPECT_GT(ys[i] - ys[i - 1], 1.2 * PictureOptions{}.font_size_mm) << "column " << x;
        }
    }
}

TEST(MeasurementPicture, PngSignatureSizeAndPixels) {
    const Measured& m = synthetic();
    const Picture& pic = synthetic_picture();
    const std::vector<std::uint8_t>& png = pic.png;
    ASSERT_GT(png.size(), 33u);
    const std::uint8_t sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    EXPECT_TRUE(std::equal(sig, sig + 8, png.begin()));
    EXPECT_EQ(std::string(png.begin() + 12, png.begin() + 16), "IHDR");
    const auto be32 = [&](std::size_t at) {
        return (std::uint32_t(png[at]) << 24) | (std::uint32_t(png[at + 1]) << 16) |
               (std::uint32_t(png[at + 2]) << 8) | std::uint32_t(png[at + 3]);
    };
    const PictureReport& rep = pic.png_report;
    EXPECT_EQ(rep.format, PictureFormat::png);
    EXPECT_EQ(be32(16), rep.width_px);
    EXPECT_EQ(be32(20), rep.height_px);
    const double r = PictureOptions{}.pixels_per_mm;
    EXPECT_EQ(rep.width_px, std::size_t(std::ceil(rep.width_mm * r)));
    EXPECT_EQ(rep.height_px, std::size_t(std::ceil(rep.height_mm * r)));
    EXPECT_EQ(pic.image.width, rep.width_px);
    EXPECT_EQ(rep.bytes, png.size());

    const auto pixel = [&](double x_mm, double y_mm) {
        const std::size_t x = std::size_t(x_mm * r), y = std::size_t(y_mm * r);
        const std::uint8_t* p = &pic.image.rgba[4 * (y * pic.image.width + x)];
        return std::array<int, 4>{p[0], p[1], p[2], p[3]};
    };
    const auto at = [&](int view, const Vec3& p) {
        const PictureView& v = rep.views[std::size_t(view)];
        const double u = p[0] * v.right[0] + p[1] * v.right[1] + p[2] * v.right[2];
        return std::pair{v.origin_x_mm + rep.scale * u, v.origin_y_mm - rep.scale * p[1]};
    };
    // How far a picture point is from every tape and leader drawn in a view (picture mm).
    const auto clearance = [&](int view, double x, double y) {
        double d = 1e300;
        for (const Measurement& meas : m.result.measurements.measurements) {
            const std::size_t n = meas.points.size();
            for (std::size_t i = 0; i < (meas.closed ? n : n - 1); ++i) {
                const auto [ax, ay] = at(view, meas.points[i]);
                const auto [bx, by] = at(view, meas.points[(i + 1) % n]);
                d = std::min(d, distance_to_segment(x, y, ax, ay, bx, by));
            }
        }
        for (const PictureLabel& l : rep.labels) {
            d = std::min(d,
                         distance_to_segment(x, y, l.x_mm, l.y_mm, l.anchor_x_mm, l.anchor_y_mm));
        }
        for (const Landmark& l : m.result.landmarks.landmarks) {
            if (l.available()) {
                const auto [lx, ly] = at(view, l.point);
                d = std::min(d, std::hypot(x - lx, y - ly));
            }
        }
        return d;
    };
    // Body: grey (shaded) and opaque inside the thighs and the torso, in both views, where no
    // tape, leader or landmark is drawn.
    int body_checks = 0;
    for (int view = 0; view < 2; ++view) {
        for (const Vec3& p :
             {Vec3{SyntheticBody::kLegX, 600, 0}, Vec3{-SyntheticBody::kLegX, 650, 0},
              Vec3{0, 1250, 0}, Vec3{40, 1110, 0}, Vec3{-40, 950, 0}}) {
            const auto [x, y] = at(view, p);
            const auto c = pixel(x, y);
            SCOPED_TRACE(std::to_string(view) + " at " + std::to_string(p[1]));
            EXPECT_LT(c[0], 245);
            EXPECT_EQ(c[3], 255);
            if (clearance(view, x, y) > 1.5) {
                ++body_checks;
                EXPECT_LE(std::max({c[0], c[1], c[2]}) - std::min({c[0], c[1], c[2]}), 12);
            }
        }
    }
    EXPECT_GE(body_checks, 4);
    // Background: white between the legs below the knees in the front view, and in the margin.
    {
        const auto [x, y] = at(0, {20, 300, 0});
        EXPECT_GT(clearance(0, x, y), 1.5);
        EXPECT_EQ(pixel(x, y), (std::array<int, 4>{255, 255, 255, 255}));
        EXPECT_EQ(pixel(1, 1), (std::array<int, 4>{255, 255, 255, 255}));
    }
    // Tape: a point of the waist loop's front half, off the centre line, is drawn in colour.
    const Measurement* waist = m.result.measurements.find("waist_girth");
    Vec3 front = waist->points.front();
    for (const Vec3& p : waist->points) {
        front = p[0] + p[2] > front[0] + front[2] ? p : front;
    }
    const auto [x, y] = at(0, front);
    const auto c = pixel(x, y);
    EXPECT_GT(std::max({c[0], c[1], c[2]}) - std::min({c[0], c[1], c[2]}), 60)
        << c[0] << " " << c[1] << " " << c[2];
}

TEST(MeasurementPicture, WritesAtomicallyByExtensionAndRejectsBadInput) {
    const Measured& m = synthetic();
    const fs::path dir =
        fs::temp_directory_path() /
        ("tapeline_picture_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const auto& set = m.result.measurements;
    const auto& lms = m.result.landmarks;
    const PictureReport svg =
        write_picture((dir / "b.svg").string(), m.points, m.triangles, set, lms);
    const PictureReport png =
        write_picture((dir / "b.PNG").string(), m.points, m.triangles, set, lms);
    EXPECT_EQ(svg.format, PictureFormat::svg);
    EXPECT_EQ(png.format, PictureFormat::png);
    EXPECT_EQ(fs::file_size(dir / "b.svg"), svg.bytes);
    EXPECT_EQ(fs::file_size(dir / "b.PNG"), png.bytes);
    std::ifstream in(dir / "b.svg");
    std::string head(5, ' ');
    in.read(&head[0], 5);
    EXPECT_EQ(head, "<?xml");
    EXPECT_LT(svg.bytes, 2u << 20);

    const auto expect_invalid = [](const auto& f, const std::string& part) {
        try {
            f();
            ADD_FAILURE() << "no exception, expected one mentioning " << part;
        } catch (const tapeline::InvalidInput& e) {
            EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
        }
    };
    expect_invalid([] { picture_format("body.jpg", "--picture"); },
                   "--picture: body.jpg: expected a .svg or .png file");
    expect_invalid([] { picture_format("dir.svg/body", "--picture"); }, "expected a .svg or .png");
    EXPECT_EQ(picture_format("A.Svg", "x"), PictureFormat::svg);
    expect_invalid(
        [&] { write_picture((dir / "c.pdf").string(), m.points, m.triangles, set, lms); },
        "c.pdf: expected a .svg or .png file");
    expect_invalid(
        [&] {
            write_picture((dir / "no_dir" / "c.svg").string(), m.points, m.triangles, set, lms);
        },
        "cannot open for writing");
    expect_invalid([&] { draw_picture({}, {}, set, lms); }, "empty body mesh");
    expect_invalid(
        [&] {
            draw_picture(m.points, {{0, 1, 99999999}}, set, lms);
        },
        "references vertex 99999999");
    PictureOptions bad;
    bad.scale = 0;
    expect_invalid([&] { draw_picture(m.points, m.triangles, set, lms, bad); }, "scale");
    PictureOptions huge;
    huge.pixels_per_mm = 1000;
    expect_invalid(
        [&] { write_picture((dir / "d.png").string(), m.points, m.triangles, set, lms, huge); },
        "Mpx");
    // Nothing half-written is left behind: only the two good pictures exist.
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) {
        names.push_back(e.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    EXPECT_EQ(names, (std::vector<std::string>{"b.PNG", "b.svg"}));
    fs::remove_all(dir);
}

TEST(MeasurementPicture, MakeHumanBodyWithLengthsAlongTheSkin) {
    const std::string path = std::string(TAPELINE_DATA_DIR) + "/bodies/mh_female_average.obj";
    if (!fs::exists(path)) {
        GTEST_SKIP() << path << " absent";
    }
    BodyOptions o;
    o.unit = LengthUnit::dm;
    const FilePicture f = picture_file(path, o);
    const auto& ms = f.measured.measurements.measurements;
    std::size_t lengths = 0, girths = 0;
    for (const Measurement& m : ms) {
        lengths += m.kind == MeasurementKind::length;
        girths += m.kind == MeasurementKind::girth;
    }
    EXPECT_GE(lengths, 5u);
    EXPECT_GE(girths, 8u);
    // A 13k-vertex body stays a small SVG: the shading is an embedded raster.
    EXPECT_GT(f.mesh.triangles.size(), 10000u);
    EXPECT_LT(f.picture.svg.size(), 2u << 20);
    std::vector<Element> els;
    std::string error;
    ASSERT_TRUE(parse_xml(f.picture.svg, els, error)) << error;
    std::map<std::string, std::size_t> tapes;
    for (const Element& e : els) {
        if (e.attrs.count("data-measurement")) {
            const Measurement* m = f.measured.measurements.find(e.attrs.at("data-measurement"));
            ASSERT_NE(m, nullptr) << e.attrs.at("data-measurement");
            EXPECT_EQ(parse_points(e.attrs.at("points")).size(), m->points.size()) << m->name;
            EXPECT_EQ(e.name, m->closed ? "polygon" : "polyline") << m->name;
            ++tapes[m->name];
        }
    }
    EXPECT_EQ(tapes.size(), ms.size());
    for (const auto& [name, n] : tapes) {
        EXPECT_EQ(n, 2u) << name;
    }
    // The canonical mesh of picture_mesh is the body's: its height is the frame's.
    double top = 0, bottom = 1e300;
    for (const Vec3& p : f.mesh.points) {
        top = std::max(top, p[1]);
        bottom = std::min(bottom, p[1]);
    }
    EXPECT_NEAR(bottom, 0.0, 1e-9);
    EXPECT_NEAR(top, f.measured.frame.height, 1e-6);
}
