#include "render/radiosity_atlas.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "gl/gl_context.h"
#include "gl/passes.h"
#include "support/cl_fixture.h"

namespace tsis {
namespace {

// Bit j when texel j of the 2×2 around a point's coordinates (x0 y0, x1 y0,
// x0 y1, x1 y1) holds its surface: a position of its medium within maxMm.
uint8_t hostMask(const std::vector<float>& atlas, int res, glm::dvec2 uv, glm::dvec4 p,
                 double maxMm) {
    const glm::dvec2 f0 = glm::floor(uv * double(res) - 0.5);
    uint8_t mask = 0;
    for (int j = 0; j < 4; ++j) {
        const int x = int(f0.x) + (j & 1), y = int(f0.y) + (j >> 1);
        if (x < 0 || y < 0 || x >= res || y >= res) continue;
        const float* q = &atlas[(size_t(y) * res + x) * 4];
        const glm::dvec3 d = glm::dvec3(q[0], q[1], q[2]) - glm::dvec3(p);
        if (double(q[3]) == p.w && glm::dot(d, d) < maxMm * maxMm) mask |= uint8_t(1u << j);
    }
    return mask;
}

// B at a point from an atlas image, in double: bilinear over the 2×2
// texels around its coordinates that `mask` names, renormalised.
glm::dvec3 hostLookup(const std::vector<float>& b, int res, glm::dvec2 uv, uint8_t mask) {
    const glm::dvec2 f = uv * double(res) - 0.5;
    const glm::dvec2 f0 = glm::floor(f), t = f - f0;
    glm::dvec3 sum(0);
    double weights = 0;
    for (int j = 0; j < 4; ++j) {
        if (!((mask >> j) & 1)) continue;
        const size_t k = size_t(int(f0.y) + (j >> 1)) * res + size_t(int(f0.x) + (j & 1));
        const double w = (j & 1 ? t.x : 1 - t.x) * (j >> 1 ? t.y : 1 - t.y);
        sum += w * glm::dvec3(b[k * 4], b[k * 4 + 1], b[k * 4 + 2]);
        weights += w;
    }
    return sum / weights;
}

class RadiosityAtlasTest : public test::ClTest {};

// An 8² atlas: a chart in columns 0–3 (a plane, 0.1 mm a texel, B linear
// in the texel), an empty gutter column 4, another chart in columns 5–7
// far away in space. Points inside, at the gutter (renormalised), with
// only the gutter and the other chart around, of another medium (both
// with no texel of their surface) and on the atlas' top row.
struct LookupCase {
    static constexpr int kRes = 8;
    static constexpr float kMaxMm = 0.3f;
    std::vector<float> xyz, b, uvs, points;
    std::vector<uint8_t> mask;
    size_t count() const { return mask.size(); }
    glm::dvec3 want(size_t i) const {
        return hostLookup(b, kRes, glm::dvec2(uvs[i * 2], uvs[i * 2 + 1]), mask[i]);
    }

    LookupCase() : xyz(kRes * kRes * 4, 0.0f), b(kRes * kRes * 4, 0.0f) {
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
        const std::vector<glm::dvec2> at = {
            {2.3, 3.6}, {3.4, 1.2}, {4.5, 5.5}, {1.0, 1.0}, {0.2, 7.9}};
        for (size_t i = 0; i < at.size(); ++i) {
            const glm::dvec2 uv = (at[i] + 0.5) / double(kRes);
            uvs.insert(uvs.end(), {float(uv.x), float(uv.y)});
            const float x = std::min(float(at[i].x), 3.4f);  // on the left chart
            points.insert(points.end(),
                          {0.1f * x, 0.1f * float(at[i].y), 0.0f, i == 3 ? 2.0f : 1.0f});
            mask.push_back(hostMask(
                xyz, kRes, uv,
                glm::dvec4(points[i * 4], points[i * 4 + 1], points[i * 4 + 2], points[i * 4 + 3]),
                kMaxMm));
        }
    }
};

TEST_F(RadiosityAtlasTest, LookupIsTheHostsBilinearOverTheTexelsOfThePointsSurface) {
    const LookupCase c;
    const std::vector<uint8_t>& mask = c.mask;
    EXPECT_EQ(mask[0], 0xf);  // inside
    EXPECT_EQ(mask[1], 0x5);  // at the gutter: column 3's two
    EXPECT_EQ(mask[2], 0);    // only the gutter and the other chart around
    EXPECT_EQ(mask[3], 0);    // another medium
    EXPECT_EQ(mask[4], 0x3);  // the top row: the two below it
    cl::Kernel lookup = rt.kernel("radiosity_atlas.cl", "tsis_radiosity_atlas_lookup");
    const size_t n = c.count();
    const std::vector<float> untouched(n * 4, -7.0f);
    cl::Buffer out = upload(untouched), none = buffer(n);
    run(lookup, n, upload(c.uvs), upload(c.points), int(n), upload(c.xyz), upload(c.b),
        LookupCase::kRes, LookupCase::kMaxMm * LookupCase::kMaxMm, out, none);
    const std::vector<float> got = download<float>(out, n * 4);
    const std::vector<uint8_t> left = download<uint8_t>(none, n);
    for (size_t i = 0; i < n; ++i) {
        EXPECT_EQ(left[i], mask[i] == 0 ? 1 : 0) << i;
        if (mask[i] == 0) {
            // Left for the gather.
            for (int k = 0; k < 4; ++k) EXPECT_EQ(got[i * 4 + k], -7.0f) << i;
            continue;
        }
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(got[i * 4 + k], c.want(i)[k], 1e-4) << i << " " << k;
        EXPECT_EQ(got[i * 4 + 3], 0.0f);
    }
    // Linear B inside the chart: exact. At the gutter: column 3's, linear in y.
    EXPECT_NEAR(got[0], 2.3 + 2 * 3.6, 1e-4);
    EXPECT_NEAR(got[4], 3 + 2 * 1.2, 1e-4);
}

// The same rule on the GL side (gl/passes.h RadiosityLookupPass), the
// points as the middle row of a 5×3 G-buffer whose other rows show nothing:
// the host's B where the point has texels of its surface; the two without
// counted, the one beside a found pixel of its medium given that pixel's B,
// the other (no neighbour of its medium) left 0.
TEST(RadiosityLookupPass, IsTheHostsBilinearAndFillsThePixelsWithNoTexel) {
    const LookupCase c;
    GlContext gl;
    const int w = int(c.count()), h = 3;
    RenderTarget gbuffer(w, h, {GL_RGBA32F, GL_RG32F}, true);
    const size_t pixels = size_t(w) * size_t(h);
    std::vector<float> position(pixels * 4, 0.0f), uv(pixels * 2, 0.0f), depth(pixels, 1.0f);
    for (int i = 0; i < w; ++i) {
        const size_t px = size_t(w) + size_t(i);  // row 1
        std::copy_n(&c.points[size_t(i) * 4], 4, &position[px * 4]);
        std::copy_n(&c.uvs[size_t(i) * 2], 2, &uv[px * 2]);
        depth[px] = 0.5f;
    }
    auto fill = [&](GLuint texture, GLenum format, const float* data) {
        glBindTexture(GL_TEXTURE_2D, texture);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, w, h, format, GL_FLOAT, data);
    };
    fill(gbuffer.color(0), GL_RGBA, position.data());
    fill(gbuffer.color(1), GL_RG, uv.data());
    fill(gbuffer.depth(), GL_DEPTH_COMPONENT, depth.data());
    RadiosityLookupPass pass;
    pass.setAtlas(c.xyz.data(), 1, c.b.data(), 1, LookupCase::kRes);
    const RadiosityLookupPass::Counts n = pass.run(gbuffer, 1, LookupCase::kMaxMm);
    EXPECT_EQ(n.covered, w);
    EXPECT_EQ(n.offAtlas, 2);
    RenderTarget out(w, h, {GL_RGBA32F}, false);
    glCopyImageSubData(pass.texture(), GL_TEXTURE_2D, 0, 0, 0, 0, out.color(0), GL_TEXTURE_2D, 0, 0,
                       0, 0, w, h, 1);
    const std::vector<float> got = out.readRGBA(0);
    auto at = [&](int i, int k) { return got[(size_t(w) + size_t(i)) * 4 + size_t(k)]; };
    for (int i : {0, 1, 4}) {
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(at(i, k), c.want(size_t(i))[k], 1e-4) << i;
        EXPECT_EQ(at(i, 3), 1.0f) << i;
    }
    // Point 2 beside point 1 (found, its medium) and point 3 (another medium).
    for (int k = 0; k < 3; ++k) EXPECT_EQ(at(2, k), at(1, k));
    EXPECT_EQ(at(2, 3), 0.5f);
    // Point 3 (medium 2): no neighbour of its medium.
    for (int k = 0; k < 3; ++k) EXPECT_EQ(at(3, k), 0.0f);
    EXPECT_EQ(at(3, 3), 0.5f);
}

// The ring: the texels beside a chart continue its surface straight on
// (a plane: exactly), a texel beside two charts far apart in space takes
// the first one's continuation alone, and a texel beside nothing stays
// uncovered.
TEST(RadiosityAtlasRing, ContinuesEachChartsSurfaceStraightOn) {
    constexpr int kRes = 12;
    std::vector<float> atlas(kRes * kRes * 4, 0.0f);
    auto set = [&](int x, int y, glm::vec3 p) {
        float* q = &atlas[size_t(y * kRes + x) * 4];
        q[0] = p.x;
        q[1] = p.y;
        q[2] = p.z;
        q[3] = 1.0f;
    };
    // A tilted plane in columns 2–5, rows 2–9; another in columns 7–9 far away.
    auto plane = [](int x, int y) { return glm::vec3(0.1f * x, 0.1f * y, 0.05f * x + 0.02f * y); };
    for (int y = 2; y <= 9; ++y) {
        for (int x = 2; x <= 5; ++x) set(x, y, plane(x, y));
        for (int x = 7; x <= 9; ++x) set(x, y, glm::vec3(40.0f + 0.1f * x, 0.1f * y, 9.0f));
    }
    const std::vector<float> ring = RadiosityAtlas::withRing(atlas, kRes, 0.3f);
    auto p = [&](int x, int y) {
        const float* q = &ring[size_t(y * kRes + x) * 4];
        return glm::vec4(q[0], q[1], q[2], q[3]);
    };
    for (const glm::ivec2 t :
         {glm::ivec2(1, 5), glm::ivec2(1, 1), glm::ivec2(3, 10), glm::ivec2(1, 10)}) {
        const glm::vec4 q = p(t.x, t.y);
        EXPECT_EQ(q.w, 1.0f) << t.x << "," << t.y;
        const glm::vec3 want = plane(t.x, t.y);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(q[c], want[c], 1e-5) << t.x << "," << t.y;
    }
    // Column 6: between the two; the first direction found is +x (the far
    // chart), whose continuation the near chart's does not agree with.
    const glm::vec4 between = p(6, 5);
    EXPECT_EQ(between.w, 1.0f);
    EXPECT_NEAR(between.x, 40.0f + 0.6f, 1e-4);
    // Covered texels are kept, a texel two away from every chart stays empty.
    EXPECT_EQ(p(3, 3), glm::vec4(plane(3, 3), 1.0f));
    EXPECT_EQ(p(0, 0).w, 0.0f);
    EXPECT_EQ(p(11, 11).w, 0.0f);
}

}  // namespace
}  // namespace tsis
