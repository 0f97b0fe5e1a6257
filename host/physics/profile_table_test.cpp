#include "physics/profile_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "physics/dipole.h"

namespace tsis {
namespace {

ProfileTable rdTable(const Dipole& d, double rMax) {
    return ProfileTable::build([&](double r) { return d.Rd(r); }, rMax);
}

TEST(ProfileTable, LayoutMatchesSharedHeader) {
    const Dipole d(presetMaterial("marble"));
    const ProfileTable t = rdTable(d, 10.0);
    EXPECT_EQ(t.info.size, static_cast<tsis_uint>(TSIS_TABLE_SIZE));
    EXPECT_EQ(t.info.r_max, 10.0f);
    EXPECT_EQ(t.info.inv_step, static_cast<float>((TSIS_TABLE_SIZE - 1) / 10.0));
    ASSERT_EQ(t.rgba.size(), 4u * TSIS_TABLE_SIZE);
    for (int k : {0, 1, 4095, TSIS_TABLE_SIZE - 1}) {
        const glm::dvec3 v = d.Rd(k * 10.0 / (TSIS_TABLE_SIZE - 1));
        for (int c = 0; c < 3; ++c) EXPECT_EQ(t.rgba[4 * k + c], static_cast<float>(v[c]));
        EXPECT_EQ(t.rgba[4 * k + 3], 0.0f);
    }
}

TEST(ProfileTable, ZeroAtAndBeyondRMaxAndForNaN) {
    const ProfileTable t = rdTable(Dipole(presetMaterial("skin1")), 10.0);
    EXPECT_EQ(t.lookup(10.0f), glm::vec3(0.0f));
    EXPECT_EQ(t.lookup(1e6f), glm::vec3(0.0f));
    EXPECT_EQ(t.lookup(std::numeric_limits<float>::infinity()), glm::vec3(0.0f));
    EXPECT_EQ(t.lookup(std::numeric_limits<float>::quiet_NaN()), glm::vec3(0.0f));
    EXPECT_EQ(t.lookup(0.0f), glm::vec3(t.rgba[0], t.rgba[1], t.rgba[2]));
    EXPECT_GT(t.lookup(9.99f).x, 0.0f);
}

// Accuracy of the table against the exact Rd: max relative error over a dense
// grid on [0, 0.999·rMax] (200001 points, incommensurate with the table), where
// Rd > 1e-30. TSIS_TABLE_SIZE = 8192 entries: step 1.22 µm at 10 mm, 8.55 µm at
// 70 mm. Measured maxima (GCC 12, x86-64):
//   rMax 10 mm: cream 2.9e-5, ketchup 4.1e-6, skin1 2.2e-6, marble 5.0e-6, apple 3.1e-6
//   rMax 70 mm: cream 1.4e-3, ketchup 1.2e-4, skin1 7.5e-5, marble 2.4e-4, apple 1.5e-4
// The worst is the flat-topped peak at r = 0 (curvature scale zr; cream red has
// the smallest, 0.135 mm), mid-way through the first interval: linear
// interpolation error ~ h²|Rd''|/8. Elsewhere float rounding of r dominates.
TEST(ProfileTable, RelativeErrorAgainstExactRd) {
    for (double rMax : {10.0, 70.0}) {
        for (const char* name : {"cream", "ketchup", "skin1", "marble", "apple"}) {
            const Dipole d(presetMaterial(name));
            const ProfileTable t = rdTable(d, rMax);
            const int n = 200001;
            double worst = 0.0, worstR = 0.0;
            for (int j = 0; j < n; ++j) {
                const double r = 0.999 * rMax * j / (n - 1);
                const glm::dvec3 exact = d.Rd(r);
                const glm::vec3 got = t.lookup(static_cast<float>(r));
                for (int c = 0; c < 3; ++c) {
                    if (!(exact[c] > 1e-30)) continue;
                    const double rel = std::abs(got[c] - exact[c]) / exact[c];
                    if (rel > worst) {
                        worst = rel;
                        worstR = r;
                    }
                }
            }
            std::printf("table %-8s rMax %4.0f mm: max rel error %.2e at r = %.4f mm\n", name, rMax,
                        worst, worstR);
            EXPECT_LT(worst, rMax <= 10.0 ? 5e-5 : 2e-3) << name << " rMax " << rMax;
        }
    }
}

}  // namespace
}  // namespace tsis
