// The 2D plot (draw/plot.h): nice axes (1, 2, 5 × 10^k steps, ranges rounded outwards), tick
// labels with the decimals the step needs, tick marks at the pixel columns and rows the layout
// promises with their labels centred on them, data points where x_px/y_px put them, and a legend
// whose ink stays inside the legend's box.
#include <tapeline/core/errors.h>
#include <tapeline/draw/plot.h>

#include <tapeline_test/image.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

using namespace tapeline::draw;
using tapeline_test::Decoded;
using tapeline_test::from_image;

TEST(DrawPlot, NiceAxes) {
    const PlotAxis a = nice_axis(0, 9.3, 5);
    EXPECT_EQ(a.step, 2);
    EXPECT_EQ(a.lo, 0);
    EXPECT_EQ(a.hi, 10);
    EXPECT_EQ(a.ticks, (std::vector<double>{0, 2, 4, 6, 8, 10}));
    const PlotAxis b = nice_axis(-3, 7, 5);
    EXPECT_EQ(b.step, 2);
    EXPECT_EQ(b.lo, -4);
    EXPECT_EQ(b.hi, 8);
    const PlotAxis c = nice_axis(0, 0.0047, 5);
    EXPECT_DOUBLE_EQ(c.step, 0.001);
    EXPECT_DOUBLE_EQ(c.hi, 0.005);
    EXPECT_EQ(c.ticks.size(), 6u);
    const PlotAxis d = nice_axis(5, 5, 5);
    EXPECT_EQ(d.lo, 5);
    EXPECT_GT(d.hi, 5);
    EXPECT_EQ(nice_step(0.3), 0.5);
    EXPECT_EQ(nice_step(1), 1);
    EXPECT_EQ(nice_step(120), 200);
    for (const auto& [lo, hi] : {std::pair{1.0, 0.0}, std::pair{0.0, HUGE_VAL}}) {
        try {
            nice_axis(lo, hi, 5);
            ADD_FAILURE() << lo << " " << hi;
        } catch (const tapeline::InvalidInput& e) {
            EXPECT_NE(std::string(e.what()).find("is not a finite interval"), std::string::npos)
                << e.what();
        }
    }
}

TEST(DrawPlot, TickLabels) {
    EXPECT_EQ(tick_label(4, 2), "4");
    EXPECT_EQ(tick_label(0.5, 0.5), "0.5");
    EXPECT_EQ(tick_label(0.02, 0.01), "0.02");
    EXPECT_EQ(tick_label(-0.0, 1), "0");
    EXPECT_EQ(tick_label(2e6, 1e6), "2e+06");
}

TEST(DrawPlot, TicksAtTheirPixels) {
    PlotOptions o;
    o.width_px = 400;
    o.height_px = 300;
    o.left_px = 60;
    o.right_px = 20;
    o.top_px = 30;
    o.bottom_px = 50;
    PlotSeries s;
    s.points = {{0.5, 0.5}, {9.3, 4.2}};
    PlotLayout l;
    const Decoded img = from_image(scatter_plot({s}, o, &l));
    ASSERT_EQ(img.width, 400u);
    ASSERT_EQ(img.height, 300u);
    // x: 0..10 by 2 over pixel centres 60.5..380.5; y: 0..5 by 1 over 250.5 (bottom)..30.5 (top).
    EXPECT_EQ(l.box_left, 60.5);
    EXPECT_EQ(l.box_right, 380.5);
    EXPECT_EQ(l.x.ticks, (std::vector<double>{0, 2, 4, 6, 8, 10}));
    EXPECT_EQ(l.y.ticks, (std::vector<double>{0, 1, 2, 3, 4, 5}));
    EXPECT_EQ(l.x_px(4), 188.5);
    EXPECT_EQ(l.y_px(3), 118.5);
    for (const double t : l.x.ticks) {
        SCOPED_TRACE("x tick " + std::to_string(t));
        const long col = long(l.x_px(t));         // the pixel whose centre is x_px
        const long row = long(l.box_bottom) + 3;  // on the tick mark, below the axis
        EXPECT_EQ(img.grey(col, row), 0);
        EXPECT_EQ(img.grey(col - 2, row), 255);
        EXPECT_EQ(img.grey(col + 2, row), 255);
        // The label's ink is centred on the tick (within a pixel and a half).
        double sum = 0, n = 0;
        for (long y = long(l.box_bottom) + 6; y < long(l.box_bottom) + 25; ++y) {
            for (long x = col - 15; x <= col + 15; ++x) {
                const double ink = 1 - img.grey(x, y) / 255;
                sum += ink * (x + 0.5);
                n += ink;
            }
        }
        ASSERT_GT(n, 5);
        EXPECT_NEAR(sum / n, l.x_px(t), 1.5);
    }
    for (const double t : l.y.ticks) {
        SCOPED_TRACE("y tick " + std::to_string(t));
        const long row = long(l.y_px(t));
        const long col = long(l.box_left) - 3;
        EXPECT_EQ(img.grey(col, row), 0);
        EXPECT_EQ(img.grey(col, row - 2), 255);
        EXPECT_EQ(img.grey(col, row + 2), 255);
        // The label is left of the tick mark, its ink vertically centred on the tick's row.
        double sum = 0, n = 0;
        for (long y = row - 10; y <= row + 10; ++y) {
            for (long x = col - 40; x < col - 3; ++x) {
                const double ink = 1 - img.grey(x, y) / 255;
                sum += ink * (y + 0.5);
                n += ink;
            }
        }
        ASSERT_GT(n, 5);
        EXPECT_NEAR(sum / n, l.y_px(t), 1.5);
    }
    // Between two ticks, below the axis: no tick mark.
    EXPECT_EQ(img.grey(long(l.x_px(5)), long(l.box_bottom) + 3), 255);
    // The data point (9.3, 4.2) is a black disc at its pixel.
    EXPECT_EQ(img.grey(long(l.x_px(9.3)), long(l.y_px(4.2))), 0);
}

TEST(DrawPlot, LegendInsideItsBox) {
    PlotSeries s;
    s.points = {{1, 1}, {2, 0.5}};
    s.colour = {1, 0, 0};
    PlotLayout without_layout, with_layout;
    const Decoded without = from_image(scatter_plot({s}, {}, &without_layout));
    EXPECT_EQ(without_layout.legend_right, 0);
    s.label = "front members";
    const Decoded with = from_image(scatter_plot({s}, {}, &with_layout));
    const PlotLayout& l = with_layout;
    ASSERT_GT(l.legend_right, l.legend_left);
    EXPECT_LE(l.legend_right, l.box_right);
    EXPECT_GE(l.legend_top, l.box_top);
    std::size_t changed = 0, outside = 0, red = 0, dark = 0;
    for (long y = 0; y < long(with.height); ++y) {
        for (long x = 0; x < long(with.width); ++x) {
            if (std::memcmp(with.at(x, y), without.at(x, y), 4) != 0) {
                ++changed;
                outside += x + 1 < l.legend_left || x > l.legend_right + 1 ||
                           y + 1 < l.legend_top || y > l.legend_bottom + 1;
                const std::uint8_t* p = with.at(x, y);
                red += p[0] == 255 && p[1] == 0 && p[2] == 0;
                dark += with.grey(x, y) < 64;
            }
        }
    }
    EXPECT_GT(changed, 0u);
    EXPECT_EQ(outside, 0u);
    EXPECT_GT(red, 10u);   // the marker
    EXPECT_GT(dark, 40u);  // the label's ink
}
