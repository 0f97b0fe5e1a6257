#include "physics/ggx.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "physics/fresnel.h"

namespace tsis {
namespace {

constexpr double kPi = std::numbers::pi;
const double kRoughness[] = {0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 1.0};
const double kCosines[] = {0.02, 0.1, 0.3, 0.5, 0.8, 1.0};

// ∫ f(wi, wo) cosθi dωi by the midpoint rule in (cosθi, φ), independent of
// the importance sampling in ggxDirectionalAlbedo.
double bruteForceAlbedo(double eta, double roughness, double cosO, int n) {
    const glm::dvec3 wo(std::sqrt(1.0 - cosO * cosO), 0.0, cosO);
    double sum = 0;
    for (int i = 0; i < n; ++i) {
        const double c = (i + 0.5) / n, s = std::sqrt(1.0 - c * c);
        for (int j = 0; j < 2 * n; ++j) {
            const double phi = kPi * (j + 0.5) / n;
            sum += ggxBrdf(eta, roughness, {s * std::cos(phi), s * std::sin(phi), c}, wo) * c;
        }
    }
    return sum * (1.0 / n) * (kPi / n);
}

// D is a distribution of normals: ∫ D(h) cosθh dωh = 1.
TEST(Ggx, DistributionProjectsToUnitArea) {
    for (double r : kRoughness) {
        if (r < 0.1) continue;  // narrower than the grid
        const double alpha = ggxAlpha(r);
        const int n = 200000;
        double sum = 0;
        for (int i = 0; i < n; ++i) {
            const double c = (i + 0.5) / n;
            sum += ggxD(alpha, c) * c;
        }
        EXPECT_NEAR(sum * 2 * kPi / n, 1.0, 2e-3) << "roughness " << r;
    }
}

// The white furnace: with F = 1 the lobe reflects at most what arrives
// (Smith's masking loses the multiple-scattered rest), for every roughness
// and view, and loses a measurable part when rough and grazing.
TEST(Ggx, WhiteFurnaceReflectsAtMostOne) {
    for (double r : kRoughness)
        for (double c : kCosines) {
            const double a = ggxDirectionalAlbedo(0, r, c);
            EXPECT_LE(a, 1.0 + 1e-4) << "roughness " << r << " cos " << c;
            EXPECT_GT(a, 0.3) << "roughness " << r << " cos " << c;
        }
    EXPECT_GT(ggxDirectionalAlbedo(0, 0.05, 0.8), 0.995);  // nearly a mirror: all of it
    EXPECT_LT(ggxDirectionalAlbedo(0, 1.0, 0.1), 0.8);     // rough and grazing: masked
}

// The split with the subsurface term: what the lobe reflects from a
// direction plus the Fresnel transmittance the subsurface term takes in
// there (irradiance's Ft) is at most the light that arrives.
TEST(Ggx, ReflectionPlusTransmissionAtMostOne) {
    for (double eta : {1.3, 1.5})
        for (double r : kRoughness)
            for (double c : kCosines) {
                const double total = ggxDirectionalAlbedo(eta, r, c) + fresnelTransmittance(eta, c);
                EXPECT_LE(total, 1.0 + 1e-3) << "eta " << eta << " roughness " << r << " cos " << c;
            }
}

// A nearly smooth surface reflects the Fresnel reflectance of the view.
TEST(Ggx, SmoothLimitIsFresnel) {
    for (double c : {0.3, 0.6, 1.0})
        EXPECT_NEAR(ggxDirectionalAlbedo(1.3, 0.05, c), fresnelReflectance(1.3, c), 2e-3) << c;
}

// The albedo (what a uniform environment of radiance 1 reflects) against an
// independent quadrature of the same BRDF, within 1 %.
TEST(Ggx, DirectionalAlbedoMatchesBruteForceQuadrature) {
    for (double r : {0.2, 0.3, 0.5, 1.0})
        for (double c : {0.1, 0.5, 0.9}) {
            const double a = ggxDirectionalAlbedo(1.3, r, c);
            const double b = bruteForceAlbedo(1.3, r, c, r < 0.25 ? 1600 : 400);
            EXPECT_NEAR(a, b, 0.01 * b) << "roughness " << r << " cos " << c;
        }
}

// Reciprocity: f(wi, wo) = f(wo, wi) (F at wi·h = wo·h).
TEST(Ggx, BrdfIsReciprocal) {
    const glm::dvec3 a(0.3, 0.1, std::sqrt(1 - 0.1)), b(-0.6, 0.2, std::sqrt(1 - 0.4));
    EXPECT_NEAR(ggxBrdf(1.3, 0.3, a, b), ggxBrdf(1.3, 0.3, b, a), 1e-12);
    EXPECT_GT(ggxBrdf(1.3, 0.3, a, b), 0);
    EXPECT_EQ(ggxBrdf(1.3, 0.3, a, {0.0, 0.6, -0.8}), 0);
}

}  // namespace
}  // namespace tsis
