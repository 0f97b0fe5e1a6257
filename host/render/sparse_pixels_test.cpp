#include "render/sparse_pixels.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "support/cl_fixture.h"

namespace tsis {
namespace {

// A width×height image of a plane z = depth(x, y), every pixel covered,
// 0.1 mm per pixel.
struct Image {
    int width, height;
    std::vector<int> pixels;
    std::vector<float> positions;
    Image(int w, int h, float (*depth)(int x, int y)) : width(w), height(h) {
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                pixels.push_back(y * w + x);
                positions.insert(positions.end(), {0.1f * x, 0.1f * y, depth(x, y), 1.0f});
            }
    }
};

TEST(SparsePixels, StrideOneEvaluatesEveryPoint) {
    const Image img(9, 6, [](int, int) { return 0.0f; });
    const SparsePixels plan = planSparsePixels(img.pixels, img.positions, 9, 6, 1, 1.0f);
    EXPECT_TRUE(plan.interpolate.empty());
    std::vector<int> sorted = plan.evaluate;
    std::sort(sorted.begin(), sorted.end());
    for (int k = 0; k < 54; ++k) EXPECT_EQ(sorted[size_t(k)], k);
}

// On a flat plane a field linear in x and y is reproduced exactly between the
// grid points; every point is evaluated or interpolated, once.
TEST(SparsePixels, LinearFieldIsExactOnAPlane) {
    const int w = 17, h = 13, stride = 4;
    const Image img(w, h, [](int, int) { return 0.0f; });
    const SparsePixels plan = planSparsePixels(img.pixels, img.positions, w, h, stride, 2.0f);
    EXPECT_EQ(plan.evaluate.size() + plan.interpolate.size(), size_t(w * h));
    // Only the grid itself is evaluated where the cell is complete: 5×4 grid
    // points plus the pixels past the last full cell (x = 17 is outside).
    EXPECT_LT(plan.evaluate.size(), size_t(w * h) / 4);
    std::vector<float> rgba(size_t(w * h) * 4, -1.0f);
    auto field = [&](int k) {
        const int row = k / w, column = k % w;
        return 3.0f + 0.5f * float(column) - 0.25f * float(row);
    };
    for (int k : plan.evaluate)
        for (int c = 0; c < 4; ++c) rgba[size_t(k) * 4 + c] = field(k) * float(c + 1);
    interpolateSparsePixels(plan, rgba);
    for (int k = 0; k < w * h; ++k)
        for (int c = 0; c < 4; ++c)
            EXPECT_NEAR(rgba[size_t(k) * 4 + c], field(k) * float(c + 1), 1e-4f) << k << " " << c;
}

// A depth jump (another surface 5 mm behind) and a missing corner: no pixel
// is interpolated across them. The cells of 4 at x0 = 4 span the jump (x =
// 6), at x0 = 8 have the hole as a corner, at x0 = 12 reach past the image;
// their pixels try cells of 2, whose corners lie on one side (x = 6, 7, 8
// behind the jump pass), and are evaluated where those fail too.
TEST(SparsePixels, DepthJumpsAndHolesAreNotInterpolatedAcross) {
    const int w = 16, h = 8, stride = 4;
    Image img(w, h, [](int x, int) { return x >= 6 ? 5.0f : 0.0f; });
    // A hole at grid point (12, 4).
    const int hole = 4 * w + 12;
    img.pixels.erase(img.pixels.begin() + hole);
    img.positions.erase(img.positions.begin() + hole * 4, img.positions.begin() + hole * 4 + 4);
    const SparsePixels plan = planSparsePixels(img.pixels, img.positions, w, h, stride, 1.0f);
    ASSERT_EQ(plan.levelEnds.size(), 2u);
    EXPECT_EQ(plan.levelEnds.back(), int(plan.interpolate.size()));
    auto x = [&](int k) { return img.pixels[size_t(k)] % w; };
    std::vector<bool> ready(img.pixels.size(), false);
    for (int k : plan.evaluate) ready[size_t(k)] = true;
    bool halfCells = false;
    for (size_t i = 0; i < plan.interpolate.size(); ++i) {
        const TsisInterpolatedPixel& p = plan.interpolate[i];
        const bool coarse = int(i) < plan.levelEnds[0];
        halfCells = halfCells || (!coarse && x(p.point) > 6 && x(p.point) < 8);
        // Not from a cell of 4 across the jump (those at x0 = 8 lack only the
        // hole: the triangle of their other corners).
        EXPECT_TRUE(!coarse || x(p.point) < 4 || x(p.point) >= 8)
            << "pixel " << img.pixels[size_t(p.point)];
        for (int c : p.corners) {
            EXPECT_TRUE(ready[size_t(c)]) << "corner " << c << " not yet made";
            EXPECT_EQ(x(c) >= 6, x(p.point) >= 6) << "across the jump";
        }
        ready[size_t(p.point)] = true;
    }
    EXPECT_TRUE(halfCells);
    EXPECT_EQ(plan.evaluate.size() + plan.interpolate.size(), img.pixels.size());
}

// A silhouette through a cell (its corner (8, 8) off the surface): the
// pixels in the triangle of the other three corners are interpolated from
// them (the missing one's weight 0), exactly for a linear field; the others
// try the cells of 2.
TEST(SparsePixels, ACellMissingACornerUsesTheTriangleOfTheOtherThree) {
    const int w = 9, h = 9, stride = 4;
    Image img(w, h, [](int, int) { return 0.0f; });
    const int corner = 8 * w + 8;
    img.pixels.erase(img.pixels.begin() + corner);
    img.positions.erase(img.positions.begin() + corner * 4, img.positions.begin() + corner * 4 + 4);
    const SparsePixels plan = planSparsePixels(img.pixels, img.positions, w, h, stride, 2.0f);
    auto field = [&](int k) {
        const int pixel = img.pixels[size_t(k)];
        const int x = pixel % w, y = pixel / w;
        return 1.0f + 0.5f * float(x) + 0.25f * float(y);
    };
    std::vector<float> rgba(img.pixels.size() * 4, -1.0f);
    for (int k : plan.evaluate)
        for (int c = 0; c < 4; ++c) rgba[size_t(k) * 4 + c] = field(k);
    interpolateSparsePixels(plan, rgba);
    int triangles = 0;
    for (size_t i = 0; i < plan.interpolate.size(); ++i) {
        const TsisInterpolatedPixel& p = plan.interpolate[i];
        const int x = img.pixels[size_t(p.point)] % w, y = img.pixels[size_t(p.point)] / w;
        if (x > 4 && y > 4 && int(i) < plan.levelEnds[0]) {
            ++triangles;
            EXPECT_LE(x + y, 12) << "outside the triangle";
            EXPECT_EQ(p.weights[3], 0.0f);
        }
    }
    EXPECT_GT(triangles, 0);
    for (size_t k = 0; k < img.pixels.size(); ++k)
        EXPECT_NEAR(rgba[k * 4], field(int(k)), 1e-4f) << "pixel " << img.pixels[k];
}

// The device's interpolation gives the host reference's values bit for bit
// (the same sums in the same order, no contraction), in place, leaving the
// evaluated points as they were.
class SparseInterpolationTest : public test::ClTest {};

TEST_F(SparseInterpolationTest, DeviceEqualsHost) {
    const int w = 37, h = 29, stride = 4;
    // Curved, with a step at x = 18 the cells of 4 at x0 = 16 span.
    const Image img(w, h, [](int x, int y) {
        return 0.01f * float(x * x) + 0.02f * float(y) + (x >= 18 ? 5.0f : 0.0f);
    });
    const SparsePixels plan = planSparsePixels(img.pixels, img.positions, w, h, stride, 3.0f);
    ASSERT_GT(plan.interpolate.size(), size_t(w * h) / 2);
    // The cells of 2 beside the step read the level of 4's pixels.
    ASSERT_EQ(plan.levelEnds.size(), 2u);
    ASSERT_GT(plan.levelEnds[1], plan.levelEnds[0]);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 10.0f);
    std::vector<float> host(size_t(w * h) * 4, -1.0f);
    for (int k : plan.evaluate)
        for (int c = 0; c < 4; ++c) host[size_t(k) * 4 + c] = u(rng);
    cl::Buffer device = upload(host);
    interpolateSparsePixels(plan, host);
    SparseInterpolation interpolation(rt);
    interpolation.run(plan, device);
    EXPECT_GE(interpolation.lastMs(), 0.0);
    const std::vector<float> got = download<float>(device, host.size());
    for (size_t i = 0; i < host.size(); ++i) ASSERT_EQ(got[i], host[i]) << "float " << i;
}

}  // namespace
}  // namespace tsis
