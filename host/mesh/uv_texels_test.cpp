#include "mesh/uv_texels.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace tsis {
namespace {

// `n` square charts of two triangles each, at random places and sizes in UV
// (a few texels across at `res`) and random sizes in 3D: what an atlas of
// many small charts looks like.
Mesh squares(int n, int res, unsigned seed) {
    Mesh m;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> place(0.05f, 0.9f), side(2.0f, 7.0f), mm(0.5f, 2.0f);
    for (int i = 0; i < n; ++i) {
        const glm::vec2 o(place(rng), place(rng));
        const float s = side(rng) / float(res), a = mm(rng);
        const auto base = static_cast<uint32_t>(m.positions.size());
        const glm::vec2 corners[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        for (const glm::vec2& c : corners) {
            m.uvs.push_back(o + s * c);
            m.positions.emplace_back(a * c.x, 0.7f * a * c.y, float(i));
        }
        m.triangles.emplace_back(base, base + 1, base + 2);
        m.triangles.emplace_back(base, base + 2, base + 3);
    }
    return m;
}

// Per square chart (triangles 2i, 2i + 1): its surface area and the area
// its texels stand for under `ratios`.
void chartSums(const Mesh& m, int res, const std::vector<float>& ratios,
               std::vector<double>& surface, std::vector<double>& texels) {
    surface.assign(m.triangles.size() / 2, 0);
    texels.assign(surface.size(), 0);
    for (size_t t = 0; t < m.triangles.size(); ++t) surface[t / 2] += m.triangleArea(t);
    rasterUVTriangles(
        m, res, [&](size_t t, int, int) { texels[t / 2] += ratios[t] / (double(res) * res); });
}

TEST(UvTexels, EachChartsTexelsSumToItsSurfaceArea) {
    constexpr int kRes = 256;
    const Mesh m = squares(40, kRes, 3);
    const std::vector<double> ratios = areaRatios(m);
    const std::vector<float> plain(ratios.begin(), ratios.end());
    std::vector<double> surface, texels;
    // Alone, A3D/AUV misses or adds part of a texel along each border: on
    // charts a few texels across, tens of per cent.
    chartSums(m, kRes, plain, surface, texels);
    double worst = 0;
    for (size_t c = 0; c < surface.size(); ++c)
        worst = std::max(worst, std::abs(texels[c] / surface[c] - 1));
    EXPECT_GT(worst, 0.1);
    chartSums(m, kRes, texelAreaRatios(m, kRes), surface, texels);
    for (size_t c = 0; c < surface.size(); ++c) EXPECT_NEAR(texels[c] / surface[c], 1.0, 1e-6) << c;
}

TEST(UvTexels, AChartWithoutATexelCentreKeepsItsRatio) {
    Mesh m = squares(1, 64, 5);
    // A third of a texel across, between the centres of four texels.
    const glm::vec2 corners[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (size_t v = 0; v < 4; ++v) m.uvs[v] = (glm::vec2(10.6f) + 0.3f * corners[v]) / 64.0f;
    int texels = 0;
    rasterUVTriangles(m, 64, [&](size_t, int, int) { ++texels; });
    ASSERT_EQ(texels, 0);
    const std::vector<float> r = texelAreaRatios(m, 64);
    for (size_t t = 0; t < 2; ++t)
        EXPECT_FLOAT_EQ(r[t], float(m.triangleArea(t) / m.triangleUVArea(t)));
}

TEST(UvTexels, ChartsAreTheTrianglesSharingVertices) {
    const Mesh m = squares(3, 64, 9);
    UnionFind charts = uvCharts(m);
    EXPECT_EQ(charts.find(2), 0u);
    EXPECT_EQ(charts.find(3), 0u);
    EXPECT_EQ(charts.find(6), 4u);
    EXPECT_NE(charts.find(8), charts.find(0));
}

}  // namespace
}  // namespace tsis
