#include "render/radial_importance.h"

#include <gtest/gtest.h>

#include <cmath>

#include "physics/dipole.h"
#include "physics/material.h"
#include "physics/split.h"

namespace tsis {
namespace {

RadialProfile rd(const Dipole& d) {
    return [d](double r) { return d.Rd(r); };
}

// Far enough out that the missing tail is negligible, the integral is the
// closed-form total diffuse reflectance (docs/design.md §2).
TEST(RadialImportance, MassMatchesClosedForm) {
    for (const char* name : {"skin1", "marble", "cream", "skimmilk"}) {
        const Dipole d(presetMaterial(name));
        const double rMax = 40.0 / std::min({d.ch[0].sigmaTr, d.ch[1].sigmaTr, d.ch[2].sigmaTr});
        const RadialImportance imp(rd(d), rMax);
        const glm::dvec3 expected = d.totalReflectance();
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(imp.mass()[c] / expected[c], 1.0, 1e-5) << name << " channel " << c;
    }
}

TEST(RadialImportance, InverseInvertsCdf) {
    const RadialImportance imp(rd(Dipole(presetMaterial("skin2"))), 20.0);
    double prev = -1.0;
    for (int k = 0; k <= 100; ++k) {
        const double u = k / 100.0;
        const double r = imp.inverse(u);
        EXPECT_GE(r, prev);
        prev = r;
        EXPECT_NEAR(imp.cdf(r), u, 1e-9) << "u = " << u;
    }
    EXPECT_EQ(imp.inverse(0.0), 0.0);
    EXPECT_EQ(imp.inverse(1.0), 20.0);
    EXPECT_EQ(imp.cdf(25.0), 1.0);
}

// Each channel counts equally: the mixture's median lies between the
// channels' own medians.
TEST(RadialImportance, MixtureWeighsChannelsEqually) {
    const Dipole d(presetMaterial("skin1"));  // red reaches much farther than blue
    const RadialImportance imp(rd(d), 30.0);
    double medians[3];
    for (int c = 0; c < 3; ++c) {
        const RadialImportance one(
            [&d, c](double r) {
                glm::dvec3 v(0.0);
                v[c] = d.ch[static_cast<size_t>(c)].Rd(r);
                return v;
            },
            30.0);
        medians[c] = one.inverse(0.5);
    }
    const double m = imp.inverse(0.5);
    EXPECT_LT(medians[2], m);
    EXPECT_LT(m, medians[0]);
    // Per channel, the mixture cdf is the channel's own cdf averaged.
    const double r = medians[1];
    double mix = 0.0;
    for (int c = 0; c < 3; ++c) mix += imp.mass(r)[c] / imp.mass()[c] / 3.0;
    EXPECT_NEAR(imp.cdf(r), mix, 1e-9);
}

}  // namespace
}  // namespace tsis
