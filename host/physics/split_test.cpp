#include "physics/split.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

namespace tsis {
namespace {

double importance(const DipoleChannel& d, double r) {
    return d.Rd(r) * 2.0 * std::numbers::pi * r;
}

TEST(Split, WeightsArePartitionOfUnityMonotoneContinuous) {
    for (double K : {0.5, 1.5, 10.0}) {
        for (double Rp : {0.3, 2.4141, 8.0}) {
            double prev = localWeight(0.0, Rp, K);
            for (int k = 0; k <= 4000; ++k) {
                const double r = 4.0 * Rp * k / 4000;
                const double wl = localWeight(r, Rp, K);
                EXPECT_DOUBLE_EQ(wl + globalWeight(r, Rp, K), 1.0);
                EXPECT_GE(wl, 0.0) << "r " << r << " Rp " << Rp << " K " << K;
                EXPECT_LE(wl, 1.0) << "r " << r << " Rp " << Rp << " K " << K;
                EXPECT_LE(wl, prev) << "r " << r << " Rp " << Rp << " K " << K;
                prev = wl;
            }
            EXPECT_DOUBLE_EQ(localWeight(Rp, Rp, K), 0.5);
            EXPECT_NEAR(localWeight(std::nextafter(Rp, 1e9), Rp, K), 0.5, 1e-12);
            EXPECT_NEAR(localWeight(std::nextafter(Rp, 0.0), Rp, K), 0.5, 1e-12);
        }
    }
    // Fig. 3.4: Rp = 2.4141, K = 1.5 ⇒ Wl(0) = 1 − ½e^(−3.62) ≈ 0.987, and Wl → 0 far out.
    EXPECT_NEAR(localWeight(0.0, 2.4141, 1.5), 1.0 - 0.5 * std::exp(-2.4141 * 1.5), 1e-15);
    EXPECT_GT(localWeight(0.0, 2.4141, 1.5), 0.98);
    EXPECT_LT(localWeight(20.0, 2.4141, 1.5), 1e-10);
    const glm::dvec3 w = localWeight(1.0, glm::dvec3(0.5, 1.0, 2.0), 1.5);
    EXPECT_EQ(w, glm::dvec3(localWeight(1.0, 0.5, 1.5), 0.5, localWeight(1.0, 2.0, 1.5)));
    EXPECT_EQ(globalWeight(1.0, glm::dvec3(0.5, 1.0, 2.0), 1.5), 1.0 - w);
}

// Rp is a crossing of the bound, and the importance stays below it beyond Rp.
TEST(Split, ImportanceRadiusIsTheLargestCrossing) {
    for (const Material& m : presetMaterials()) {
        const Dipole d(m);
        for (int c = 0; c < 3; ++c) {
            const DipoleChannel& ch = d.ch[c];
            const double rp = importanceRadius(ch, 0.1);
            double peak = 0.0;
            for (int k = 1; k <= 100000; ++k) peak = std::max(peak, importance(ch, k * 1e-4 * rp));
            if (peak < 0.1) continue;  // see NeverReachingTheBound
            EXPECT_NEAR(importance(ch, rp), 0.1, 1e-9) << m.name << " " << c;
            for (int k = 1; k <= 10000; ++k) {
                const double r = rp * (1.0 + k * 1e-2);  // out to 100·Rp
                ASSERT_LT(importance(ch, r), 0.1) << m.name << " " << c << " r " << r;
            }
        }
    }
}

// A dark channel whose importance peaks below the bound: Rp is where it peaks.
TEST(Split, NeverReachingTheBoundGivesThePeak) {
    const DipoleChannel ch = Dipole(presetMaterial("ketchup")).ch[2];
    const double rp = importanceRadius(ch, 0.1);
    const double peak = importance(ch, rp);
    ASSERT_LT(peak, 0.1);
    for (double f : {0.5, 0.9, 0.99, 1.01, 1.1, 2.0}) EXPECT_LE(importance(ch, f * rp), peak) << f;
    // And a bound just under the peak gives a crossing just past it.
    EXPECT_GT(importanceRadius(ch, 0.99 * peak), rp);
}

// The thesis' Fig. 3.4 gives Rp = 2.4141 for skimmilk red. With the table's
// σa = 0.0014 we get 2.4161; with the caption's σa = 0.0024 it would be 2.3747,
// so the caption's σa is the misprint (docs/design.md §3).
TEST(Split, SkimmilkRedReproducesThesisRp) {
    const double rp = importanceRadius(Dipole(presetMaterial("skimmilk")).ch[0]);
    std::printf("skimmilk red Rp = %.4f mm (thesis Fig. 3.4: 2.4141)\n", rp);
    EXPECT_NEAR(rp, 2.4141, 0.005);
    EXPECT_NEAR(importanceRadius(DipoleChannel(0.70, 0.0024, 1.3)), 2.3747, 0.001);
}

}  // namespace
}  // namespace tsis
