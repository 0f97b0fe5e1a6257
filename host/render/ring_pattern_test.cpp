#include "render/ring_pattern.h"

#include <gtest/gtest.h>

#include <cmath>

#include "physics/dipole.h"
#include "physics/material.h"
#include "render/profiles.h"

namespace tsis {
namespace {

struct Fixture {
    KeyedProfile profile;
    ProfileTable table;
    RadialImportance importance;
    Fixture(const char* material, RdPart part, double rMax)
        : profile(radialProfile(presetMaterial(material), RenderOptions{}, part)),
          table(ProfileTable::build(profile.f, rMax)),
          importance(profile.f, rMax) {}
};

TEST(RingPattern, LayoutIsCentrePlusRings) {
    Fixture f("skimmilk", RdPart::Local, 12.0);
    const RingPattern p = RingPattern::build(f.importance, f.table, 4, 4);
    ASSERT_EQ(p.samples.size(), 17u);
    ASSERT_EQ(p.edges.size(), 5u);
    EXPECT_EQ(p.samples[0].r, 0.0f);
    EXPECT_DOUBLE_EQ(p.edges.back(), 12.0);
    for (size_t k = 1; k < p.edges.size(); ++k) EXPECT_GT(p.edges[k], p.edges[k - 1]);
    for (int k = 1; k <= 4; ++k)
        for (int m = 0; m < 4; ++m) {
            const TsisRingSample& s = p.samples[static_cast<size_t>(1 + (k - 1) * 4 + m)];
            // Inside its ring, on the circle of its radius.
            EXPECT_GT(s.r, p.edges[static_cast<size_t>(k - 1)]);
            EXPECT_LT(s.r, p.edges[static_cast<size_t>(k)]);
            EXPECT_NEAR(std::hypot(s.dx, s.dy), s.r, 1e-5 * s.r);
        }
    // Each ring holds C/(LC+1) of the importance, the centre 1/(LC+1).
    double inner = 0.0;
    for (size_t k = 0; k < p.edges.size(); ++k) {
        const double share = f.importance.cdf(p.edges[k]) - f.importance.cdf(inner);
        EXPECT_NEAR(share, (k == 0 ? 1.0 : 4.0) / 17.0, 1e-9) << "ring " << k;
        inner = p.edges[k];
    }
}

// On a flat, uniformly lit plane the filter is exact: Σ A'·f(r_s) = ∫ f dA.
TEST(RingPattern, ExactOnAPlane) {
    for (RdPart part : {RdPart::Full, RdPart::Local}) {
        Fixture f("skin2", part, 25.0);
        for (int rings : {0, 1, 4, 8})
            for (int per : {1, 4, 6}) {
                const RingPattern p = RingPattern::build(f.importance, f.table, rings, per);
                const glm::dvec3 got = p.planeIntegral(f.table);
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(got[c] / f.importance.mass()[c], 1.0, 1e-5)
                        << rings << "×" << per << " channel " << c;
            }
    }
}

// The odd rings are turned by half a sector.
TEST(RingPattern, OddRingsAreStaggered) {
    Fixture f("marble", RdPart::Full, 20.0);
    const RingPattern p = RingPattern::build(f.importance, f.table, 2, 4);
    const TsisRingSample& first = p.samples[1];   // ring 1, angle π/4
    const TsisRingSample& second = p.samples[5];  // ring 2, angle 0
    EXPECT_NEAR(std::atan2(first.dy, first.dx), M_PI / 4, 1e-5);
    EXPECT_NEAR(std::atan2(second.dy, second.dx), 0.0, 1e-5);
}

}  // namespace
}  // namespace tsis
