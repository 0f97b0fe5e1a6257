// kernels/ltsm.cl against a host double version of its sum: per point xo and
// ring sample s, B(xo) += (Φ_s / τ²)·A'_s·f(|xo − x_s|), Φ_s and x_s bilinear
// in the light's maps around xo's projection (kernels/ltsm.cl).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "ltsm_shared.h"
#include "support/analytic_table.h"
#include "support/cl_fixture.h"
#include "support/kernel_reference.h"

namespace tsis {
namespace {

using test::ClTest;

constexpr int kRes = 8;

// A centre sample and two rings of three, offsets up to 1.5 texels of the
// orthographic map, per-channel areas unlike each other.
std::vector<TsisRingSample> pattern() {
    std::vector<TsisRingSample> p = {{0, 0, 0, 0, 0.2f, 0.3f, 0.4f, 0}};
    for (int ring = 1; ring <= 2; ++ring)
        for (int k = 0; k < 3; ++k) {
            const float a = 2.0943951f * (float(k) + 0.5f * float(ring - 1));
            const float r = 0.55f * float(ring);
            p.push_back(
                {r * std::cos(a), r * std::sin(a), r, 0, 0.5f * ring, 0.7f, 0.9f / ring, 0});
        }
    return p;
}

// Points over the map: inside, near its edges and one off it.
std::vector<cl_float4> points(uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-3.4f, 3.4f);
    std::vector<cl_float4> p;
    p.reserve(41);
    // One medium throughout (tag 1, as the maps' covered texels).
    for (int i = 0; i < 40; ++i) p.push_back({{u(rng), u(rng), 0.02f, 1.0f}});
    p.push_back({{9.0f, 9.0f, 0.0f, 1.0f}});
    return p;
}

// The kernel's sum in double (kernels/ltsm.cl), added to `base`.
std::vector<glm::dvec3> hostLtsm(const std::vector<cl_float4>& pts, const TsisLightMapInfo& l,
                                 const test::LightMaps& maps,
                                 const std::vector<TsisRingSample>& pat, const ProfileTable& t,
                                 std::vector<glm::dvec3>* magnitude) {
    std::vector<glm::dvec3> b(pts.size(), glm::dvec3(0.0));
    magnitude->assign(pts.size(), glm::dvec3(0.0));
    for (size_t j = 0; j < pts.size(); ++j) {
        const glm::dvec3 xo = test::xyz(pts[j]);
        const glm::dvec3 o = test::project(l, xo);
        const double invTau = 1.0 / (double(l.tau_per_w) * o.z);
        for (const TsisRingSample& s : pat) {
            const test::LitPoint lit = test::bilinear(l, maps.flux, maps.position, 0,
                                                      o.x + s.dx * invTau, o.y + s.dy * invTau);
            if (!(lit.point.w > 0.0)) continue;
            const double r = glm::length(xo - glm::dvec3(lit.point) / lit.point.w);
            const double area[3] = {s.ar, s.ag, s.ab};
            for (int c = 0; c < 3; ++c) {
                const double term = lit.flux[c] * area[c] * test::lookup(t, r, c) * invTau * invTau;
                b[j][c] += term;
                (*magnitude)[j][c] += std::abs(term);
            }
        }
    }
    return b;
}

class LtsmKernelTest : public ClTest, public ::testing::WithParamInterface<bool> {
  protected:
    cl::Kernel kernel = rt.kernel("ltsm.cl", "tsis_ltsm");
};

// Every output value against the host sum, for a perspective (point light)
// and an orthographic (directional) map, written and then accumulated onto.
// Tolerance per value: 1e-5 of Σ|terms| (float sums of ≤ 7 products; the
// interpolation point moves by float rounding, ~1e-6 mm, where |f'| ≤ 2.5).
TEST_P(LtsmKernelTest, MatchesHostDoubleSum) {
    const bool perspective = GetParam();
    const TsisLightMapInfo l =
        test::lightMap(glm::vec3(0.0f, 0.0f, perspective ? 8.0f : 10.0f), perspective, kRes, 4.0f);
    // The maps' texel size as the orthographic view has it, for both views.
    const test::LightMaps maps =
        test::planeLightMaps(test::lightMap(glm::vec3(0, 0, 10), false, kRes, 4.0f), 1, 7, 0.25);
    const std::vector<TsisRingSample> pat = pattern();
    const ProfileTable t = test::analyticTable(6.0);
    const std::vector<cl_float4> pts = points(11);

    // No discrete choice in the sum (the bilinear reads are continuous), so
    // float and double part only by rounding.
    std::vector<glm::dvec3> mag;
    const std::vector<glm::dvec3> want = hostLtsm(pts, l, maps, pat, t, &mag);

    cl::Buffer p = upload(pts), flux = upload(maps.flux), pos = upload(maps.position);
    cl::Buffer patBuf = upload(pat), table = upload(t.rgba);
    const std::vector<cl_float4> base(pts.size(), {{0.5f, -1.0f, 2.0f, 0.0f}});
    cl::Buffer out = upload(base);
    for (int accumulate : {0, 1}) {
        run(kernel, pts.size(), p, int(pts.size()), l, flux, pos, patBuf, int(pat.size()), table,
            t.info, accumulate, out);
        const std::vector<cl_float4> got = download<cl_float4>(out, pts.size());
        // After the first run out holds B; the second adds B again.
        const double times = accumulate ? 2.0 : 1.0;
        for (size_t j = 0; j < pts.size(); ++j) {
            for (int c = 0; c < 3; ++c)
                ASSERT_NEAR(got[j].s[c], times * want[j][c], 1e-5 * times * mag[j][c] + 1e-12)
                    << "point " << j << " channel " << c << " accumulate " << accumulate;
            ASSERT_EQ(got[j].s[3], 0.0f);
        }
    }
    // The test sees light: most points get some, the one off the map none.
    int lit = 0;
    for (const glm::dvec3& b : want) lit += b.x > 0.0;
    EXPECT_GT(lit, 30);
    EXPECT_EQ(want.back(), glm::dvec3(0.0));
}

// By hand: one centre sample of area (1, 2, 3) mm², flux (4, 5, 6) in the one
// texel xo projects to the centre of, at distance 0 from xo; f = (1, 1, 1) at
// r = 0 (a flat table): B = Φ·A'·f / τ² with τ = the texel size, 0.5 mm.
TEST_P(LtsmKernelTest, OneTexelByHand) {
    const TsisLightMapInfo l = test::lightMap(glm::vec3(0, 0, 10), false, 4, 1.0f);  // τ = 0.5 mm
    std::vector<cl_float4> flux(16, {{0, 0, 0, 0}}), pos(16, {{0, 0, 0, 0}});
    // Texel (2, 2) has its centre at (0.25, 0.25); xo there reads it with weight 1.
    flux[10] = {{4, 5, 6, 1}};
    pos[10] = {{0.25f, 0.25f, 0, 1}};
    ProfileTable t;
    t.info = {1.0f, float(TSIS_TABLE_SIZE - 1), TSIS_TABLE_SIZE, 0};
    t.rgba.assign(4 * TSIS_TABLE_SIZE, 1.0f);
    const std::vector<TsisRingSample> pat = {{0, 0, 0, 0, 1, 2, 3, 0}};
    const std::vector<cl_float4> xo = {{{0.25f, 0.25f, 0.0f, 1.0f}}};
    cl::Buffer out = buffer(sizeof(cl_float4));
    run(kernel, 1, upload(xo), 1, l, upload(flux), upload(pos), upload(pat), 1, upload(t.rgba),
        t.info, 0, out);
    const cl_float4 b = download<cl_float4>(out, 1)[0];
    EXPECT_NEAR(b.s[0], 4 * 1 / 0.25, 1e-4);
    EXPECT_NEAR(b.s[1], 5 * 2 / 0.25, 1e-4);
    EXPECT_NEAR(b.s[2], 6 * 3 / 0.25, 1e-4);
}

INSTANTIATE_TEST_SUITE_P(Views, LtsmKernelTest, ::testing::Bool(), [](const auto& info) {
    return std::string(info.param ? "perspective" : "orthographic");
});

}  // namespace
}  // namespace tsis
