#include "physics/dipole.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "support/plane_integral.h"

namespace tsis {
namespace {

// ∫0^∞ Rd(r) 2πr dr from 1e-9·zr (the integrand vanishes like r² there) to
// 60 decay lengths out. Needs σa > 0 (a 1/r² importance tail is not integrable here).
double integrateRd(const DipoleChannel& d) {
    return test::planeIntegral([&](double r) { return d.Rd(r); }, 1e-9 * d.zr,
                               d.zv + 60.0 / d.sigmaTr);
}

TEST(Dipole, NumericIntegralEqualsClosedForm) {
    double worst = 0.0;
    for (const Material& m : presetMaterials()) {
        const Dipole d(m);
        for (int c = 0; c < 3; ++c) {
            if (d.ch[c].sigmaA == 0.0) continue;  // spectralon: see below
            const double closed = d.ch[c].totalReflectance();
            const double rel = std::abs(integrateRd(d.ch[c]) / closed - 1.0);
            worst = std::max(worst, rel);
            EXPECT_LT(rel, 1e-4) << m.name << " channel " << c;
        }
    }
    std::printf("max relative |numeric ∫Rd 2πr dr / closed form − 1| = %.2e\n", worst);
}

TEST(Dipole, NonAbsorbingReflectsEverything) {
    const Dipole d(presetMaterial("spectralon"));
    for (int c = 0; c < 3; ++c) EXPECT_DOUBLE_EQ(d.ch[c].totalReflectance(), 1.0);
}

// Jensen et al. 2001's diffuse-reflectance column for marble (with η = 1.5).
TEST(Dipole, MarbleMatchesJensensTable) {
    const glm::dvec3 R = Dipole(presetMaterial("marble")).totalReflectance();
    EXPECT_NEAR(R.x, 0.830, 0.005);
    EXPECT_NEAR(R.y, 0.791, 0.005);
    EXPECT_NEAR(R.z, 0.753, 0.005);
}

TEST(Dipole, DerivedQuantities) {
    const DipoleChannel d(0.70, 0.0014, 1.3);  // skimmilk red
    EXPECT_DOUBLE_EQ(d.sigmaTPrime, 0.7014);
    EXPECT_DOUBLE_EQ(d.zr, 1.0 / 0.7014);
    EXPECT_DOUBLE_EQ(d.meanFreePath(), d.zr);
    EXPECT_DOUBLE_EQ(d.alphaPrime, 0.70 / 0.7014);
    EXPECT_DOUBLE_EQ(d.sigmaTr, std::sqrt(3.0 * 0.0014 * 0.7014));
    EXPECT_NEAR(d.Fdr, 0.444763, 1e-6);  // −1.44/1.69 + 0.71/1.3 + 0.668 + 0.0636·1.3
    EXPECT_DOUBLE_EQ(d.A, (1 + d.Fdr) / (1 - d.Fdr));
    EXPECT_DOUBLE_EQ(d.zv, d.zr * (1 + 4 * d.A / 3));
    // Rd at r = 0 by hand: sr = zr, sv = zv.
    auto src = [&](double z) {
        return z * (1 + d.sigmaTr * z) * std::exp(-d.sigmaTr * z) / (z * z * z);
    };
    EXPECT_DOUBLE_EQ(d.Rd(0.0), d.alphaPrime / (4 * std::numbers::pi) * (src(d.zr) + src(d.zv)));
}

TEST(Dipole, RgbMatchesChannels) {
    const Material& m = presetMaterial("skin2");
    const Dipole d(m);
    for (int c = 0; c < 3; ++c) {
        const DipoleChannel ch(m.sigmaSPrime[c], m.sigmaA[c], m.eta);
        EXPECT_EQ(d.Rd(1.7)[c], ch.Rd(1.7));
        EXPECT_EQ(d.totalReflectance()[c], ch.totalReflectance());
        EXPECT_EQ(d.sigmaTr()[c], ch.sigmaTr);
        EXPECT_EQ(d.meanFreePath()[c], 1.0 / (m.sigmaSPrime[c] + m.sigmaA[c]));
    }
}

}  // namespace
}  // namespace tsis
