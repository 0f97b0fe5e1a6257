#include "cl/gather.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <random>

#include "physics/profile_table.h"
#include "support/analytic_table.h"
#include "support/cl_fixture.h"

namespace tsis {
namespace {

using test::analyticTable;
using test::ClTest;
using test::lookup;

// Points and samples of two media (tags 1 and 2, mesh/media.h): a sample
// lights only the points of its own.
std::vector<cl_float4> randomPoints(int count, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-2.0f, 2.0f);
    std::vector<cl_float4> p(count);
    for (cl_float4& x : p) x = {{u(rng), u(rng), u(rng), rng() % 4 == 0 ? 2.0f : 1.0f}};
    return p;
}

std::vector<TsisSample> randomSamples(int n, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-2.0f, 2.0f);
    std::uniform_real_distribution<float> w(0.0f, 1.0f);
    std::vector<TsisSample> s(n);
    for (TsisSample& x : s)
        x = {u(rng), u(rng), u(rng), 0.0f, w(rng), w(rng), w(rng), rng() % 4 == 0 ? 2.0f : 1.0f};
    return s;
}

class GatherTest : public ClTest, public ::testing::WithParamInterface<int> {
  protected:
    // A negative parameter: that width with the interleaved table rows.
    Gatherer gatherer{rt, std::abs(GetParam()), GetParam() < 0};

    std::vector<cl_float4> gather(const std::vector<cl_float4>& points,
                                  const std::vector<TsisSample>& samples, const ProfileTable& t) {
        cl::Buffer p = upload(points);
        cl::Buffer s = upload(samples);
        cl::Buffer table = upload(t.rgba);
        cl::Buffer out = buffer(points.size() * sizeof(cl_float4));
        // Poison, so a point the kernel skips shows.
        rt.queue().enqueueFillBuffer(out, std::nanf(""), 0, points.size() * sizeof(cl_float4));
        gatherer.run(p, int(points.size()), s, int(samples.size()), table, t.info, out);
        EXPECT_EQ(gatherer.lastEvaluations(), (long long)points.size() * samples.size());
        return download<cl_float4>(out, points.size());
    }

    // Against Σ w·f in double. Tolerance: 1e-4 of Σ|w·f| (float accumulation
    // over n ≤ 1000 terms, worst case n·2⁻²⁴ = 6e-5) plus 1e-6·Σ|w| for the
    // float distance moving the interpolation point (δr ≈ 1e-6, |f'| ≤ 2).
    void expectMatchesHost(const std::vector<cl_float4>& points,
                           const std::vector<TsisSample>& samples, const ProfileTable& t) {
        const std::vector<cl_float4> got = gather(points, samples, t);
        for (size_t j = 0; j < points.size(); ++j) {
            for (int c = 0; c < 3; ++c) {
                double sum = 0.0, mag = 0.0, wsum = 0.0;
                for (const TsisSample& s : samples) {
                    if (s.medium != points[j].s[3]) continue;
                    const double dx = double(points[j].s[0]) - s.px;
                    const double dy = double(points[j].s[1]) - s.py;
                    const double dz = double(points[j].s[2]) - s.pz;
                    const double w = c == 0 ? s.wr : c == 1 ? s.wg : s.wb;
                    const double f = lookup(t, std::sqrt(dx * dx + dy * dy + dz * dz), c);
                    sum += w * f;
                    mag += std::abs(w * f);
                    wsum += std::abs(w);
                }
                ASSERT_NEAR(got[j].s[c], sum, 1e-4 * mag + 1e-6 * wsum)
                    << "point " << j << " channel " << c;
            }
            ASSERT_EQ(got[j].s[3], 0.0f) << "point " << j;
        }
    }
};

// f = (r, 2r, r/2) with inv_step 1: one sample at the origin weighted (1, 2, 3)
// seen from (3, 4, 0), r = 5 exactly: B = (5, 20, 7.5); beyond r_max: 0.
TEST_P(GatherTest, ByHand) {
    ProfileTable t;
    t.info = {float(TSIS_TABLE_SIZE - 1), 1.0f, TSIS_TABLE_SIZE, 0};
    t.rgba.resize(4 * TSIS_TABLE_SIZE);
    for (int k = 0; k < TSIS_TABLE_SIZE; ++k) {
        t.rgba[4 * k] = float(k);
        t.rgba[4 * k + 1] = 2.0f * k;
        t.rgba[4 * k + 2] = 0.5f * k;
    }
    const std::vector<TsisSample> s = {{0, 0, 0, 0, 1, 2, 3, 1}};
    const std::vector<cl_float4> p = {
        {{3, 4, 0, 1}}, {{8191, 0, 0, 1}}, {{0, 0, 0.5f, 1}}, {{3, 4, 0, 2}}};
    const std::vector<cl_float4> b = gather(p, s, t);
    EXPECT_EQ(b[3].s[0], 0.0f);  // another medium: no light crosses
    EXPECT_EQ(b[0].s[0], 5.0f);
    EXPECT_EQ(b[0].s[1], 20.0f);
    EXPECT_EQ(b[0].s[2], 7.5f);
    EXPECT_EQ(b[1].s[0], 0.0f);  // r = r_max: outside
    EXPECT_EQ(b[2].s[0], 0.5f);  // between entries 0 and 1
    EXPECT_EQ(b[2].s[2], 0.75f);
}

TEST_P(GatherTest, MatchesHostLoop) {
    const ProfileTable t = analyticTable(5.0);
    // 1013: not a multiple of 8 or 16, and a few points beyond r_max of some samples.
    expectMatchesHost(randomPoints(1013, 1), randomSamples(900, 2), t);
}

TEST_P(GatherTest, OnePointOneSample) {
    const ProfileTable t = analyticTable(5.0);
    expectMatchesHost(randomPoints(1, 3), randomSamples(900, 4), t);
    expectMatchesHost(randomPoints(37, 5), randomSamples(1, 6), t);
    expectMatchesHost(randomPoints(1, 7), randomSamples(1, 8), t);
}

TEST_P(GatherTest, NoSamplesGivesZero) {
    const std::vector<cl_float4> b = gather(randomPoints(20, 9), {}, analyticTable(5.0));
    for (const cl_float4& x : b)
        for (int c = 0; c < 4; ++c) EXPECT_EQ(x.s[c], 0.0f);
}

TEST_P(GatherTest, NoPointsIsANoOp) {
    const ProfileTable t = analyticTable(5.0);
    cl::Buffer p = buffer(16);
    cl::Buffer s = upload(randomSamples(4, 10));
    cl::Buffer table = upload(t.rgba);
    cl::Buffer out = buffer(16);
    gatherer.run(p, 0, s, 4, table, t.info, out);
    EXPECT_EQ(gatherer.lastEvaluations(), 0);
    EXPECT_EQ(gatherer.lastMs(), 0.0);
}

INSTANTIATE_TEST_SUITE_P(Widths, GatherTest, ::testing::Values(1, 8, 16, -8, -16),
                         [](const auto& info) {
                             // Appended, not "w" + …: GCC 12 warns falsely (-Wrestrict) on that.
                             std::string name = "w";
                             name += std::to_string(std::abs(info.param));
                             if (info.param < 0) name += "interleaved";
                             return name;
                         });

}  // namespace
}  // namespace tsis
