#include "compare/heatmap.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "compare/bitmap_font.h"
#include "util/error.h"

namespace tsis {

namespace {

constexpr std::array<uint8_t, 3> kUnselected = {128, 128, 128};
constexpr std::array<uint8_t, 3> kBackground = {24, 24, 24};
constexpr std::array<uint8_t, 3> kText = {235, 235, 235};

// "2.5%"; three significant digits at most.
std::string percent(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g%%", 100.0 * v);
    return buf;
}

}  // namespace

std::array<uint8_t, 3> heatColour(double t) {
    static const double kViridis[9][3] = {{68, 1, 84},    {71, 45, 123},  {59, 82, 139},
                                          {44, 114, 142}, {33, 145, 140}, {40, 174, 128},
                                          {94, 201, 98},  {173, 220, 48}, {253, 231, 37}};
    if (!(t > 0)) t = 0;  // also NaN
    t = std::min(t, 1.0) * 8.0;
    const int i = std::min(static_cast<int>(t), 7);
    const double f = t - i;
    std::array<uint8_t, 3> c{};
    for (int k = 0; k < 3; ++k)
        c[k] = static_cast<uint8_t>(
            std::lround(kViridis[i][k] + f * (kViridis[i + 1][k] - kViridis[i][k])));
    return c;
}

double heatmapScale(const ImageF& relError) {
    std::vector<float> v;
    for (float e : relError.pixels)
        if (e >= 0) v.push_back(e);
    double p99 = 0;
    if (!v.empty()) {
        const size_t k =
            std::min(v.size() - 1, static_cast<size_t>(0.99 * static_cast<double>(v.size())));
        std::nth_element(v.begin(), v.begin() + static_cast<long>(k), v.end());
        p99 = v[k];
    }
    if (!std::isfinite(p99)) p99 = 1e9;
    p99 = std::max(p99, 1e-4);
    double decade = std::pow(10.0, std::floor(std::log10(p99)));
    for (;;) {
        for (double m : {1.0, 2.0, 2.5, 5.0})
            if (m * decade >= p99 * (1 - 1e-6)) return m * decade;
        decade *= 10;
    }
}

Heatmap renderHeatmap(const ImageF& relError, double scaleMax) {
    TSIS_CHECK_EQ(relError.channels, 1);
    TSIS_CHECK(scaleMax > 0);
    const int w = relError.width, h = relError.height;
    const int s = w >= 300 ? 2 : 1;  // font and bar scale
    const std::string title = "rel. error |A-B|/|B|";
    const int margin = 8 * s;
    const int barLeftRoom = textWidth("0%", s) / 2,
              barRightRoom = textWidth(percent(scaleMax) + "+", s) / 2;
    Heatmap out;
    out.scaleMax = scaleMax;
    out.width = std::max({w, textWidth(title, s) + 2 * margin, 160 * s});
    // Legend: margin, title, gap, bar, ticks, gap, labels, margin.
    const int titleY = h + margin / 2, barY = titleY + (kGlyphHeight + 4) * s, barH = 10 * s;
    const int tickH = 3 * s, labelY = barY + barH + tickH + 2 * s;
    out.height = labelY + kGlyphHeight * s + margin / 2;
    out.rgb.resize(static_cast<size_t>(out.width) * out.height * 3);
    auto put = [&](int x, int y, std::array<uint8_t, 3> c) {
        for (int k = 0; k < 3; ++k)
            out.rgb[(static_cast<size_t>(y) * out.width + x) * 3 + k] = c[k];
    };
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) put(x, y, kBackground);
    const int x0 = (out.width - w) / 2;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float e = relError.pixels[static_cast<size_t>(y) * w + x];
            put(x0 + x, y, e < 0 ? kUnselected : heatColour(e / scaleMax));
        }
    drawText(out.rgb, out.width, out.height, margin, titleY, title, s, kText);
    const int left = margin + barLeftRoom, right = out.width - margin - barRightRoom;
    for (int x = left; x <= right; ++x) {
        const auto c = heatColour(static_cast<double>(x - left) / (right - left));
        for (int y = barY; y < barY + barH; ++y) put(x, y, c);
    }
    for (int q = 0; q <= 4; ++q) {
        const int x = left + (right - left) * q / 4;
        for (int y = barY + barH; y < barY + barH + tickH; ++y)
            for (int dx = 0; dx < s; ++dx) put(std::min(x + dx, out.width - 1), y, kText);
        if (q % 2) continue;
        const std::string label = percent(scaleMax * q / 4) + (q == 4 ? "+" : "");
        const int lx = std::clamp(x - textWidth(label, s) / 2, 0, out.width - textWidth(label, s));
        drawText(out.rgb, out.width, out.height, lx, labelY, label, s, kText);
    }
    return out;
}

}  // namespace tsis
