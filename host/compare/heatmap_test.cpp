#include "compare/heatmap.h"

#include <gtest/gtest.h>

#include "compare/bitmap_font.h"

namespace tsis {
namespace {

ImageF relErrors(std::vector<float> v) {
    ImageF i;
    i.width = static_cast<int>(v.size());
    i.height = 1;
    i.channels = 1;
    i.pixels = std::move(v);
    return i;
}

TEST(Heatmap, ViridisEnds) {
    EXPECT_EQ(heatColour(0.0), (std::array<uint8_t, 3>{68, 1, 84}));
    EXPECT_EQ(heatColour(1.0), (std::array<uint8_t, 3>{253, 231, 37}));
    EXPECT_EQ(heatColour(7.0), heatColour(1.0)) << "saturates";
    EXPECT_EQ(heatColour(-1.0), heatColour(0.0));
}

TEST(Heatmap, ScaleIsARoundValueAboveThe99thPercentile) {
    EXPECT_DOUBLE_EQ(heatmapScale(relErrors({0.013f})), 0.02);
    EXPECT_DOUBLE_EQ(heatmapScale(relErrors({0.021f})), 0.025);
    EXPECT_DOUBLE_EQ(heatmapScale(relErrors({0.03f, -1.0f})), 0.05);
    EXPECT_DOUBLE_EQ(heatmapScale(relErrors({0.1f})), 0.1);
    EXPECT_DOUBLE_EQ(heatmapScale(relErrors({0.0f, -1.0f})), 1e-4);
    std::vector<float> many(1000, 0.01f);
    many[0] = 100.0f;  // one outlier does not set the scale
    EXPECT_DOUBLE_EQ(heatmapScale(relErrors(many)), 0.01);
}

TEST(Heatmap, PixelsLegendAndScaleText) {
    ImageF e;
    e.width = 64;
    e.height = 32;
    e.channels = 1;
    e.pixels.assign(64 * 32, -1.0f);
    e.pixels[0] = 0.05f;   // top-left: saturated at scale 0.05
    e.pixels[1] = 0.025f;  // half way
    const Heatmap h = renderHeatmap(e, 0.05);
    ASSERT_GE(h.width, 64);
    ASSERT_GT(h.height, 32 + 3 * kGlyphHeight);
    const int x0 = (h.width - 64) / 2;
    auto at = [&](int x, int y) {
        const size_t i = (static_cast<size_t>(y) * h.width + x) * 3;
        return std::array<uint8_t, 3>{h.rgb[i], h.rgb[i + 1], h.rgb[i + 2]};
    };
    EXPECT_EQ(at(x0, 0), heatColour(1.0));
    EXPECT_EQ(at(x0 + 1, 0), heatColour(0.5));
    EXPECT_EQ(at(x0 + 2, 0), (std::array<uint8_t, 3>{128, 128, 128})) << "outside the mask";
    // The legend has the bar's two ends and light text pixels.
    int text = 0, low = 0, high = 0;
    for (int y = 32; y < h.height; ++y)
        for (int x = 0; x < h.width; ++x) {
            const auto c = at(x, y);
            text += c[0] == 235 && c[1] == 235;
            low += c == heatColour(0.0);
            high += c == heatColour(1.0);
        }
    EXPECT_GT(text, 100);
    EXPECT_GT(low, 0);
    EXPECT_GT(high, 0);
}

TEST(BitmapFont, GlyphsAndWidths) {
    EXPECT_TRUE(glyphPixel('1', 2, 0));
    EXPECT_FALSE(glyphPixel('1', 0, 0));
    EXPECT_TRUE(glyphPixel('%', 0, 0));
    EXPECT_FALSE(glyphPixel(' ', 2, 3));
    EXPECT_TRUE(glyphPixel('~', 0, 3)) << "unknown characters draw as a box";
    EXPECT_FALSE(glyphPixel('~', 2, 3));
    EXPECT_FALSE(glyphPixel('1', 5, 0)) << "outside the cell";
    EXPECT_EQ(textWidth("", 2), 0);
    EXPECT_EQ(textWidth("5%", 1), 11);
    EXPECT_EQ(textWidth("5%", 2), 22);
    std::vector<uint8_t> rgb(8 * 8 * 3, 0);
    drawText(rgb, 8, 8, 1, 0, "1", 1, {255, 0, 0});
    EXPECT_EQ(rgb[(0 * 8 + 3) * 3], 255);  // '1' top row centre at x = 1 + 2
    EXPECT_EQ(rgb[(0 * 8 + 1) * 3], 0);
    drawText(rgb, 8, 8, 6, 6, "88", 2, {1, 1, 1});  // clipped, no crash
}

}  // namespace
}  // namespace tsis
