#include "physics/fresnel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "physics/dipole.h"

namespace tsis {
namespace {

TEST(Fresnel, NormalIncidence) {
    for (double eta : {1.3, 1.5, 2.4}) {
        const double r0 = (eta - 1) / (eta + 1);
        EXPECT_NEAR(fresnelReflectance(eta, 1.0), r0 * r0, 1e-15) << eta;
    }
}

TEST(Fresnel, GrazingAndClamping) {
    EXPECT_DOUBLE_EQ(fresnelReflectance(1.3, 0.0), 1.0);
    EXPECT_GT(fresnelReflectance(1.3, 1e-4), 0.999);
    EXPECT_DOUBLE_EQ(fresnelReflectance(1.3, -0.5), 1.0);
    EXPECT_DOUBLE_EQ(fresnelReflectance(1.3, 1.5), fresnelReflectance(1.3, 1.0));
    EXPECT_DOUBLE_EQ(fresnelTransmittance(1.3, 0.3), 1.0 - fresnelReflectance(1.3, 0.3));
}

TEST(Fresnel, MonotoneInCosine) {
    for (double eta : {1.3, 1.5}) {
        double prev = fresnelReflectance(eta, 0.0);
        for (int k = 1; k <= 1000; ++k) {
            const double f = fresnelReflectance(eta, k / 1000.0);
            EXPECT_LE(f, prev) << "eta " << eta << " cos " << k / 1000.0;
            prev = f;
        }
    }
}

// Independent form: Fresnel's sine and tangent laws in the angles themselves.
TEST(Fresnel, MatchesSineTangentLaws) {
    for (double eta : {1.3, 1.5}) {
        for (double deg : {10.0, 30.0, 45.0, 60.0, 80.0, 89.0}) {
            const double ti = deg * std::numbers::pi / 180.0;
            const double tt = std::asin(std::sin(ti) / eta);
            const double rs = std::pow(std::sin(ti - tt) / std::sin(ti + tt), 2);
            const double rp = std::pow(std::tan(ti - tt) / std::tan(ti + tt), 2);
            EXPECT_NEAR(fresnelReflectance(eta, std::cos(ti)), 0.5 * (rs + rp), 1e-13)
                << "eta " << eta << " angle " << deg;
        }
    }
}

// The dipole's Fdr fit is the diffuse reflectance seen from inside; it follows
// from the outside one, 2∫Fr(μ)μ dμ, by reciprocity: 1 − (1 − Fdr_out)/η².
TEST(Fresnel, HemisphericalAverageMatchesFdrFit) {
    for (double eta : {1.3, 1.5}) {
        const int n = 100000;
        double out = 0.0;  // midpoint rule for 2∫0^1 Fr(μ) μ dμ
        for (int k = 0; k < n; ++k) {
            const double mu = (k + 0.5) / n;
            out += 2.0 * fresnelReflectance(eta, mu) * mu / n;
        }
        const double inside = 1.0 - (1.0 - out) / (eta * eta);
        EXPECT_NEAR(inside, diffuseFresnelReflectance(eta), 1e-3) << eta;  // measured 3e-4, 4e-4
    }
}

// Moments from the air side and from inside obey reciprocity: the
// transmitted fractions of diffuse light differ by η², 1 − 2FM1(1/η) =
// (1 − 2FM1(η)) / η²; and diffuse light on glass (η = 1.5) reflects 9.2%.
TEST(Fresnel, MomentsReciprocityAndGlass) {
    EXPECT_NEAR(fresnelMoment(1.0, 1), 0.0, 1e-12);
    for (double eta : {1.3, 1.44, 1.5, 2.0}) {
        const double outside = 1.0 - 2.0 * fresnelMoment(eta, 1);
        const double inside = 1.0 - 2.0 * fresnelMoment(1.0 / eta, 1);
        EXPECT_NEAR(inside, outside / (eta * eta), 1e-5) << eta;
    }
    EXPECT_NEAR(2.0 * fresnelMoment(1.5, 1), 0.092, 1e-3);
    // μ² weights grazing angles less: the second moment is below the first.
    EXPECT_LT(fresnelMoment(1.3, 2), fresnelMoment(1.3, 1));
}

// The normalised exit term's exitance is B: ∫ Ft(η, μ)/(cπ) μ dω = 1, here by
// the midpoint rule (not the Simpson of fresnelMoment).
TEST(Fresnel, NormalizedExitTermConservesExitance) {
    for (double eta : {1.0, 1.3, 1.5, 2.4}) {
        const int n = 100000;
        const double scale = normalizedExitScale(eta);
        double exitance = 0;
        for (int k = 0; k < n; ++k) {
            const double mu = (k + 0.5) / n;
            // dω = 2π dμ around the normal.
            exitance += fresnelTransmittance(eta, mu) * scale / std::numbers::pi * mu * 2.0 *
                        std::numbers::pi / n;
        }
        EXPECT_NEAR(exitance, 1.0, 1e-6) << eta;
    }
}

}  // namespace
}  // namespace tsis
