#include "render/radiosity_atlas.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "support/cl_fixture.h"

namespace tsis {
namespace {

// B at a point from an atlas image, in double: bilinear over the 2×2 texels
// around its coordinates that count (covered, its medium, within maxMm),
// renormalised; else the nearest that counts of the 4×4 around; else 0.
glm::dvec3 hostLookup(const std::vector<float>& xyz, const std::vector<float>& b, int res,
                      glm::dvec2 uv, glm::dvec4 p, double maxMm) {
    const glm::dvec2 f = uv * double(res) - 0.5;
    const glm::dvec2 f0 = glm::floor(f), t = f - f0;
    glm::dvec3 sum(0), nearest(0);
    double weights = 0, best = INFINITY;
    for (int pass = 0; pass < 2 && weights == 0; ++pass)
        for (int dy = pass ? -1 : 0; dy <= (pass ? 2 : 1); ++dy)
            for (int dx = pass ? -1 : 0; dx <= (pass ? 2 : 1); ++dx) {
                const int x = int(f0.x) + dx, y = int(f0.y) + dy;
                if (x < 0 || y < 0 || x >= res || y >= res) continue;
                const size_t k = size_t(y) * res + x;
                const glm::dvec3 q(xyz[k * 4], xyz[k * 4 + 1], xyz[k * 4 + 2]);
                const double d2 = glm::dot(q - glm::dvec3(p), q - glm::dvec3(p));
                if (double(xyz[k * 4 + 3]) != p.w || !(d2 < maxMm * maxMm)) continue;
                const glm::dvec3 v(b[k * 4], b[k * 4 + 1], b[k * 4 + 2]);
                if (pass == 0) {
                    const double w = (dx ? t.x : 1 - t.x) * (dy ? t.y : 1 - t.y);
                    if (w > 0) {
                        sum += w * v;
                        weights += w;
                    }
                } else if (d2 < best) {
                    best = d2;
                    nearest = v;
                }
            }
    return weights > 0 ? sum / weights : nearest;
}

class RadiosityAtlasTest : public test::ClTest {};

// An 8² atlas: a chart in columns 0–3 (a plane, 0.1 mm a texel, B linear
// in the texel), an empty gutter column 4, another chart in columns 5–7
// far away in space. Points inside, at the gutter (renormalised), with
// only the other chart and the gutter around (the nearest texel of their
// own chart), and of another medium (nothing: 0).
TEST_F(RadiosityAtlasTest, LookupIsTheHostsBilinearOverTheTexelsOfThePointsSurface) {
    constexpr int kRes = 8;
    std::vector<float> xyz(kRes * kRes * 4, 0.0f), b(kRes * kRes * 4, 0.0f);
    for (int y = 0; y < kRes; ++y)
        for (int x = 0; x < kRes; ++x) {
            if (x == 4) continue;
            float* q = &xyz[size_t(y * kRes + x) * 4];
            float* v = &b[size_t(y * kRes + x) * 4];
            const bool left = x < 4;
            q[0] = 0.1f * float(x);
            q[1] = 0.1f * float(y);
            q[2] = left ? 0.0f : 50.0f;
            q[3] = 1.0f;
            v[0] = left ? float(x + 2 * y) : 100.0f;
            v[1] = left ? float(3 * x - y) : 200.0f;
            v[2] = 1.0f;
        }
    // uv in texel units (+ ½: the centre), and the surface point there.
    const std::vector<glm::dvec2> at = {{2.3, 3.6}, {3.4, 1.2}, {4.5, 5.5}, {1.0, 1.0}, {0.2, 7.9}};
    std::vector<float> uvs, points;
    for (size_t i = 0; i < at.size(); ++i) {
        const glm::dvec2 uv = (at[i] + 0.5) / double(kRes);
        uvs.insert(uvs.end(), {float(uv.x), float(uv.y)});
        const float x = std::min(float(at[i].x), 3.4f);  // on the left chart
        points.insert(points.end(), {0.1f * x, 0.1f * float(at[i].y), 0.0f, i == 3 ? 2.0f : 1.0f});
    }
    const float maxMm = 0.3f;
    cl::Kernel lookup = rt.kernel("radiosity_atlas.cl", "tsis_radiosity_atlas_lookup");
    cl::Buffer out = buffer(at.size() * 16);
    run(lookup, at.size(), upload(uvs), upload(points), int(at.size()), upload(xyz), upload(b),
        kRes, maxMm * maxMm, out);
    const std::vector<float> got = download<float>(out, at.size() * 4);
    for (size_t i = 0; i < at.size(); ++i) {
        const glm::dvec4 p(points[i * 4], points[i * 4 + 1], points[i * 4 + 2], points[i * 4 + 3]);
        const glm::dvec3 want =
            hostLookup(xyz, b, kRes, glm::dvec2(uvs[i * 2], uvs[i * 2 + 1]), p, maxMm);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[i * 4 + c], want[c], 1e-4) << i << " " << c;
        EXPECT_EQ(got[i * 4 + 3], 0.0f);
    }
    // Linear B inside the chart: exact. At the gutter: column 3's, linear in y.
    EXPECT_NEAR(got[0], 2.3 + 2 * 3.6, 1e-4);
    EXPECT_NEAR(got[4], 3 + 2 * 1.2, 1e-4);
    // Beside the gutter and the other chart: the nearest texel of its own
    // (column 3), never the other chart's 100.
    EXPECT_LT(got[8], 50.0f);
    EXPECT_GT(got[8], 0.0f);
    EXPECT_EQ(got[12], 0.0f);  // another medium
}

}  // namespace
}  // namespace tsis
