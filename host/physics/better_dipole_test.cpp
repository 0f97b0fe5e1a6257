#include "physics/better_dipole.h"

#include <gtest/gtest.h>

#include <cmath>

#include "physics/material.h"
#include "support/plane_integral.h"

namespace tsis {
namespace {

TEST(BetterDipole, NumericIntegralEqualsClosedForm) {
    for (const Material& m : presetMaterials())
        for (int c = 0; c < 3; ++c) {
            if (m.sigmaA[c] == 0.0) continue;  // spectralon: below
            const BetterDipoleChannel d(m.sigmaSPrime[c], m.sigmaA[c], m.eta);
            const double numeric = test::planeIntegral([&](double r) { return d.Rd(r); },
                                                       1e-9 * d.zr, 2 * d.zb + 60.0 / d.sigmaTr);
            EXPECT_NEAR(numeric / d.totalReflectance(), 1.0, 1e-4) << m.name << " " << c;
        }
}

// Without absorption every photon leaves: Cφ·2A + CE = 1 exactly.
TEST(BetterDipole, NoAbsorptionReflectsAll) {
    for (double eta : {1.0, 1.3, 1.5})
        EXPECT_NEAR(BetterDipoleChannel(2.0, 0.0, eta).totalReflectance(), 1.0, 1e-12) << eta;
}

// Against the classical dipole: close in total (within the 20% the boundary
// and the fluence term move it), and the same exponential tail σtr only
// when σa ≪ σs′ (Grosjean's D → 1/(3σt′)).
TEST(BetterDipole, NearTheClassicalDipole) {
    const BetterDipoleChannel d(2.0, 0.002, 1.3);
    EXPECT_NEAR(d.D * 3.0 * d.sigmaTPrime, 1.0, 2e-3);
    EXPECT_GT(d.totalReflectance(), 0.8);
    EXPECT_LT(d.totalReflectance(), 1.0);
}

}  // namespace
}  // namespace tsis
