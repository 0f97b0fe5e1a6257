#include "mesh/uv_check.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <random>

#include "mesh/builtin.h"

namespace tsis {
namespace {

using ::testing::HasSubstr;

// An n×n grid of quads over [0,1]², two triangles each; UV = xy.
Mesh grid(int n) {
    Mesh m;
    m.name = "grid";
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) {
            m.positions.emplace_back(float(j) / n, float(i) / n, 0.0f);
            m.uvs.emplace_back(float(j) / n, float(i) / n);
        }
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const uint32_t a = i * (n + 1) + j, b = a + 1, c = a + n + 1, d = c + 1;
            m.triangles.emplace_back(a, b, d);
            m.triangles.emplace_back(a, d, c);
        }
    return m;
}

TEST(UVCheck, GridWithSharedEdgesAndVerticesIsOk) {
    const UVCheck c = checkUVs(grid(8));
    EXPECT_TRUE(c.ok) << c.problem;
    EXPECT_EQ(c.problem, "");
    EXPECT_EQ(c.overlapping, 0u);
}

TEST(UVCheck, MovingOneVertexMakesOverlaps) {
    Mesh m = grid(4);
    // Pull interior vertex (row 2, column 2) past its neighbour: the fan
    // around it folds over.
    m.uvs[2 * 5 + 2].x += 0.3f;
    const UVCheck c = checkUVs(m);
    EXPECT_FALSE(c.ok);
    EXPECT_GT(c.overlapping, 0u);
    EXPECT_EQ(c.outOfRange, 0u);
    EXPECT_THAT(c.problem, HasSubstr("UVs of 'grid': "));
    EXPECT_THAT(c.problem, HasSubstr("pairs of overlapping triangles (e.g. "));
    EXPECT_EQ(c.problem.find('\n'), std::string::npos);
}

TEST(UVCheck, TwoSeparateCopiesOverlapOnlyWhenStacked) {
    // Two triangles with their own vertices at the same UVs overlap fully;
    // side by side, touching along an edge, they do not.
    Mesh m;
    m.name = "two";
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
    m.triangles = {{0, 1, 2}, {3, 4, 5}};
    m.uvs = {{0, 0}, {0.5f, 0}, {0, 0.5f}, {0, 0}, {0.5f, 0}, {0, 0.5f}};
    UVCheck c = checkUVs(m);
    EXPECT_EQ(c.overlapping, 1u);
    EXPECT_THAT(c.problem, HasSubstr("1 pair of overlapping triangles (e.g. 0 and 1)"));
    m.uvs[3] = {0.5f, 0.5f};  // mirror across the hypotenuse: shares the edge only
    c = checkUVs(m);
    EXPECT_TRUE(c.ok) << c.problem;
    m.uvs[3] = {0.5f, 0.5f};
    m.uvs[4] = {0.5f, 1.0f};
    m.uvs[5] = {0.0f, 0.5f};  // (0,0.5)-(0.5,0.5)-(0.5,1): shares one vertex only
    c = checkUVs(m);
    EXPECT_TRUE(c.ok) << c.problem;
    m.uvs[3] = {0.2f, 0.2f};  // a corner poking into the first triangle
    c = checkUVs(m);
    EXPECT_EQ(c.overlapping, 1u);
}

TEST(UVCheck, OutOfRangeDegenerateAndMissing) {
    Mesh m = grid(2);
    m.uvs[0] = {-0.1f, 0.0f};
    m.uvs[8] = {1.0f, 1.0f + 1e-7f};  // within the epsilon
    UVCheck c = checkUVs(m);
    EXPECT_EQ(c.outOfRange, 1u);
    EXPECT_THAT(c.problem, HasSubstr("1 vertex outside [0,1] (e.g. vertex 0)"));
    m = grid(2);
    m.uvs[4] = m.uvs[0];  // centre onto a corner: triangles around it collapse or fold
    c = checkUVs(m);
    EXPECT_GT(c.degenerate, 0u);
    EXPECT_THAT(c.problem, HasSubstr("degenerate triangles"));
    m.uvs.clear();
    c = checkUVs(m);
    EXPECT_FALSE(c.ok);
    EXPECT_THAT(c.problem, HasSubstr("has none"));
}

// The grid-accelerated count equals a brute-force count on random layouts.
TEST(UVCheck, MatchesBruteForce) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> U(0.0f, 1.0f);
    for (int round = 0; round < 20; ++round) {
        Mesh m;
        m.name = "random";
        const int n = 60;
        for (int t = 0; t < n; ++t) {
            const float x = U(rng), y = U(rng), s = 0.02f + 0.15f * U(rng);
            for (int k = 0; k < 3; ++k) {
                m.uvs.emplace_back(std::min(1.0f, x + s * U(rng)), std::min(1.0f, y + s * U(rng)));
                m.positions.emplace_back(t, k, 0);
            }
            m.triangles.emplace_back(3 * t, 3 * t + 1, 3 * t + 2);
        }
        Mesh one = m;
        size_t brute = 0;
        for (int a = 0; a < n; ++a)
            for (int b = a + 1; b < n; ++b) {
                one.triangles = {m.triangles[a], m.triangles[b]};
                const UVCheck c = checkUVs(one);
                if (c.degenerate == 0) brute += c.overlapping;
            }
        size_t degenerate = checkUVs(m).degenerate;
        if (degenerate == 0) {
            EXPECT_EQ(checkUVs(m).overlapping, brute) << round;
        }
    }
}

TEST(UVCheck, FastOnAHundredThousandTriangles) {
    const Mesh m = grid(224);  // 100,352 triangles
    const auto start = std::chrono::steady_clock::now();
    const UVCheck c = checkUVs(m);
    const double s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_TRUE(c.ok) << c.problem;
    EXPECT_LT(s, 1.0);
}

}  // namespace
}  // namespace tsis
