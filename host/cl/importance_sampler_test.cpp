#include "cl/importance_sampler.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "support/cl_fixture.h"

namespace tsis {
namespace {

using test::ClTest;

double luma(const cl_float4& f) {
    return std::max(0.0, TSIS_LUMINANCE(double(f.s[0]), double(f.s[1]), double(f.s[2])));
}

// Random flux; about `zeroFraction` of the texels black.
std::vector<cl_float4> randomFlux(int res, double zeroFraction, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<cl_float4> flux(size_t(res) * res);
    for (cl_float4& f : flux) {
        const bool zero = u(rng) < zeroFraction;
        // Spread over several orders of magnitude, like lit and grazing texels.
        const float scale = zero ? 0.0f : std::pow(10.0f, -3.0f * u(rng));
        f = {{scale * u(rng), scale * u(rng), scale * u(rng), 0.0f}};
    }
    return flux;
}

std::vector<cl_float4> positionsFor(int res) {
    std::vector<cl_float4> p(size_t(res) * res);
    for (size_t i = 0; i < p.size(); ++i)
        p[i] = {{float(i % res), float(i / res), 0.5f * float(i), 1.0f}};
    return p;
}

class ImportanceSamplerTest : public ClTest {
  protected:
    ImportanceSampler sampler{rt};

    std::vector<TsisSample> drawSamples(const std::vector<cl_float4>& flux, int res, int n,
                                        uint32_t seed) {
        return drawOffset(flux, res, n, ImportanceSampler::seedOffset(seed));
    }

    std::vector<TsisSample> drawOffset(const std::vector<cl_float4>& flux, int res, int n,
                                       float xi) {
        cl::Buffer f = upload(flux);
        cl::Buffer p = upload(positionsFor(res));
        cl::Buffer s = buffer(size_t(n) * sizeof(TsisSample));
        sampler.buildPyramid(f, res);
        sampler.drawWithOffset(f, p, res, n, xi, s);
        return download<TsisSample>(s, n);
    }
};

// Every level against sums in double. A texel of level k adds 4^k non-negative
// floats in k rounds of 3 additions, so its relative error is below about
// (3k + 2)·2⁻²⁴ (the +2: the float luminance); the bound checked is 4e-6
// (k ≤ 8 here: 26·6e-8 = 1.6e-6).
TEST_F(ImportanceSamplerTest, PyramidMatchesDoubleSums) {
    for (int res : {1, 2, 16, 256}) {
        SCOPED_TRACE("res " + std::to_string(res));
        const std::vector<cl_float4> flux = randomFlux(res, 0.2, 11 + res);
        cl::Buffer f = upload(flux);
        sampler.buildPyramid(f, res);
        const size_t size = ImportanceSampler::pyramidSize(res);
        ASSERT_EQ(size, (4 * size_t(res) * res - 1) / 3);
        const std::vector<float> pyr = download<float>(sampler.pyramid(), size);

        std::vector<double> level(flux.size());
        for (size_t i = 0; i < flux.size(); ++i) level[i] = luma(flux[i]);
        for (int k = 0, w = res; w >= 1; ++k, w /= 2) {
            const size_t off = ImportanceSampler::levelOffset(res, k);
            for (int i = 0; i < w * w; ++i) {
                ASSERT_NEAR(pyr[off + i], level[i], 4e-6 * level[i])
                    << "level " << k << " texel " << i;
            }
            if (w == 1) break;
            std::vector<double> up(size_t(w / 2) * (w / 2));
            for (int y = 0; y < w / 2; ++y)
                for (int x = 0; x < w / 2; ++x)
                    up[y * (w / 2) + x] = level[2 * y * w + 2 * x] + level[2 * y * w + 2 * x + 1] +
                                          level[(2 * y + 1) * w + 2 * x] +
                                          level[(2 * y + 1) * w + 2 * x + 1];
            level = up;
        }
        EXPECT_NEAR(sampler.totalLuminance(), level[0], 4e-6 * level[0]);
        EXPECT_GT(sampler.lastPyramidMs(), 0.0);
    }
}

// 2x2 by hand: texel (x, y) at index y*2 + x, parent = 1 + 2 + 3 + 4.
TEST_F(ImportanceSamplerTest, PyramidByHand) {
    const std::vector<cl_float4> flux = {
        {{1, 1, 1, 0}}, {{0, 2.0f / TSIS_LUMA_G, 0, 0}}, {{3, 3, 3, 0}}, {{-5, -5, -5, 0}}};
    cl::Buffer f = upload(flux);
    sampler.buildPyramid(f, 2);
    const std::vector<float> pyr = download<float>(sampler.pyramid(), 5);
    EXPECT_FLOAT_EQ(pyr[0], 1.0f);
    EXPECT_FLOAT_EQ(pyr[1], 2.0f);
    EXPECT_FLOAT_EQ(pyr[2], 3.0f);
    EXPECT_EQ(pyr[3], 0.0f);  // negative luminance counts as none
    EXPECT_FLOAT_EQ(pyr[4], 6.0f);
    EXPECT_FLOAT_EQ(float(sampler.totalLuminance()), 6.0f);
}

// Y = (1, 0, 3, 0) over a 2x2 atlas and n = 4: u = (i + ξ)/4 puts exactly one
// sample in [0, 1/4) (texel 0) and three in [1/4, 1) (texel 2), whatever ξ.
// Weights Φ·ΣY/(n·Y) = Φ·4/(4·Y). (The float Y are not exactly 1 and 3, so ξ
// must stay clear of 0 for sample 1 to be decided; the seeds below do.)
TEST_F(ImportanceSamplerTest, DrawByHand) {
    const std::vector<cl_float4> flux = {
        {{1, 1, 1, 0}}, {{0, 0, 0, 0}}, {{0, 3.0f / TSIS_LUMA_G, 0, 0}}, {{0, 0, 0, 0}}};
    for (uint32_t seed : {0u, 1u, 99u}) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        ASSERT_GT(ImportanceSampler::seedOffset(seed), 1e-3f);
        const std::vector<TsisSample> s = drawSamples(flux, 2, 4, seed);
        EXPECT_EQ(s[0].texel, 0.0f);
        for (int i = 1; i < 4; ++i) EXPECT_EQ(s[i].texel, 2.0f) << i;
        EXPECT_NEAR(s[0].wr, 1.0, 1e-6);
        EXPECT_NEAR(s[0].wg, 1.0, 1e-6);
        EXPECT_NEAR(s[1].wg, 1.0 / TSIS_LUMA_G, 1e-6);
        EXPECT_EQ(s[1].wr, 0.0f);
        // Positions of texel 2 = (x 0, y 1).
        EXPECT_EQ(s[3].px, 0.0f);
        EXPECT_EQ(s[3].py, 1.0f);
        EXPECT_EQ(s[3].pz, 1.0f);
    }
}

// u = 0 lands on the first child with mass, not on the black ones before it:
// Y = (0, 1, 0, 1), ξ = 0, n = 2 gives u = 0 and 1/2: texels 1 and 3.
TEST_F(ImportanceSamplerTest, NeverPicksBlackChild) {
    const std::vector<cl_float4> flux = {
        {{0, 0, 0, 0}}, {{1, 1, 1, 0}}, {{0, 0, 0, 0}}, {{1, 1, 1, 0}}};
    const std::vector<TsisSample> s = drawOffset(flux, 2, 2, 0.0f);
    EXPECT_EQ(s[0].texel, 1.0f);
    EXPECT_EQ(s[1].texel, 3.0f);
}

// u just below 1 must reach the last lit texel of a 2x2 atlas whose texel 3
// is black, also where float round-off leaves the remaining mass at or above
// what texels 0–2 hold (the fallback in tsis_draw). The host replays the
// kernel's float walk on the device's pyramid to count how often that happens:
// the test only means something if it does (about 4% of random atlases).
TEST_F(ImportanceSamplerTest, TopOfCdfLandsOnLastLitTexel) {
    const float u = 0x1.fffffep-1f;
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> uni(0.0f, 1.0f);
    int roundOffCases = 0;
    for (int trial = 0; trial < 400; ++trial) {
        SCOPED_TRACE("trial " + std::to_string(trial));
        std::vector<cl_float4> flux(4);
        for (int i = 0; i < 3; ++i) {
            const float v = uni(rng) * std::pow(10.0f, -3.0f * uni(rng));
            flux[i] = {{v, v, v, 0.0f}};
        }
        flux[3] = {{0, 0, 0, 0}};
        if (trial % 3 == 0) flux[2] = {{0, 0, 0, 0}};  // two trailing black texels
        const std::vector<TsisSample> s = drawOffset(flux, 2, 1, u);
        const std::vector<float> pyr = download<float>(sampler.pyramid(), 5);
        float mass = u * pyr[4];
        for (int c = 0; c < 4; ++c) mass -= pyr[c];
        roundOffCases += mass >= 0.0f;
        const int last = luma(flux[2]) > 0 ? 2 : 1;
        ASSERT_EQ(s[0].texel, float(last));
    }
    EXPECT_GT(roundOffCases, 0);
}

TEST_F(ImportanceSamplerTest, SingleTexelAndDarkAtlas) {
    const std::vector<TsisSample> one = drawSamples({{{2, 4, 8, 0}}}, 1, 8, 3);
    for (const TsisSample& s : one) {
        EXPECT_EQ(s.texel, 0.0f);
        EXPECT_FLOAT_EQ(s.wr, 2.0f / 8);
        EXPECT_FLOAT_EQ(s.wb, 8.0f / 8);
    }
    const std::vector<TsisSample> dark = drawSamples(std::vector<cl_float4>(64), 8, 100, 3);
    EXPECT_EQ(sampler.totalLuminance(), 0.0);
    for (const TsisSample& s : dark) {
        EXPECT_EQ(s.wr, 0.0f);
        EXPECT_EQ(s.wg, 0.0f);
        EXPECT_EQ(s.wb, 0.0f);
    }
}

// Counts per texel against p_i = Y_i/ΣY: Pearson's chi-square below the 0.1%
// critical value (Wilson–Hilferty), no sample on a black texel, and, since
// u_i is a shifted grid, every count within 2 of n·p_i (stratification: a
// texel's CDF interval of length p_i holds ⌊n p_i⌋ or ⌈n p_i⌉ grid points; 1
// more of slack for float round-off in the CDF).
TEST_F(ImportanceSamplerTest, CountsFollowLuminance) {
    const int res = 16;
    const int n = 200000;
    const std::vector<cl_float4> flux = randomFlux(res, 0.25, 5);
    const std::vector<TsisSample> s = drawSamples(flux, res, n, 1234);

    double total = 0.0;
    for (const cl_float4& f : flux) total += luma(f);
    std::vector<int> count(flux.size(), 0);
    for (const TsisSample& x : s) {
        const int t = static_cast<int>(x.texel);
        ASSERT_GE(t, 0);
        ASSERT_LT(t, res * res);
        ++count[t];
    }
    double chi2 = 0.0;
    int cells = 0;
    for (size_t i = 0; i < flux.size(); ++i) {
        const double expected = n * luma(flux[i]) / total;
        if (expected == 0.0) {
            EXPECT_EQ(count[i], 0) << "sample on black texel " << i;
            continue;
        }
        ++cells;
        chi2 += (count[i] - expected) * (count[i] - expected) / expected;
        EXPECT_LE(std::abs(count[i] - expected), 2.0) << "texel " << i;
    }
    ASSERT_GT(cells, 100);
    const double df = cells - 1;
    const double z = 3.09;  // one-sided 0.1%
    const double critical = df * std::pow(1 - 2 / (9 * df) + z * std::sqrt(2 / (9 * df)), 3);
    EXPECT_LT(chi2, critical) << "chi2 " << chi2 << " with " << df << " degrees of freedom";
    EXPECT_GT(sampler.lastDrawMs(), 0.0);
}

// Weights Φ_i·ΣY/(n·Y_i) and positions of the chosen texels: relative 1e-5
// (float ΣY over 256 texels and float Y_i against double).
TEST_F(ImportanceSamplerTest, WeightsAndPositions) {
    const int res = 16;
    const int n = 5000;
    const std::vector<cl_float4> flux = randomFlux(res, 0.25, 9);
    const std::vector<cl_float4> pos = positionsFor(res);
    const std::vector<TsisSample> s = drawSamples(flux, res, n, 77);
    double total = 0.0;
    for (const cl_float4& f : flux) total += luma(f);
    for (int i = 0; i < n; ++i) {
        const int t = static_cast<int>(s[i].texel);
        const double scale = total / (n * luma(flux[t]));
        const float w[3] = {s[i].wr, s[i].wg, s[i].wb};
        for (int c = 0; c < 3; ++c) {
            const double expected = flux[t].s[c] * scale;
            ASSERT_NEAR(w[c], expected, 1e-5 * expected) << "sample " << i << " channel " << c;
        }
        ASSERT_EQ(s[i].px, pos[t].s[0]);
        ASSERT_EQ(s[i].py, pos[t].s[1]);
        ASSERT_EQ(s[i].pz, pos[t].s[2]);
    }
}

TEST_F(ImportanceSamplerTest, SeedDecidesSamples) {
    const std::vector<cl_float4> flux = randomFlux(16, 0.25, 21);
    const std::vector<TsisSample> a = drawSamples(flux, 16, 900, 42);
    const std::vector<TsisSample> b = drawSamples(flux, 16, 900, 42);
    const std::vector<TsisSample> c = drawSamples(flux, 16, 900, 43);
    EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(TsisSample)), 0);
    int differ = 0;
    for (size_t i = 0; i < a.size(); ++i) differ += a[i].texel != c[i].texel;
    EXPECT_GT(differ, 0);
    EXPECT_NE(ImportanceSampler::seedOffset(42), ImportanceSampler::seedOffset(43));
    for (uint32_t seed : {0u, 1u, 0xffffffffu}) {
        EXPECT_GE(ImportanceSampler::seedOffset(seed), 0.0f);
        EXPECT_LT(ImportanceSampler::seedOffset(seed), 1.0f);
    }
}

}  // namespace
}  // namespace tsis
