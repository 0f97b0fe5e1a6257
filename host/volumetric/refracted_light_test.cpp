#include "volumetric/refracted_light.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "physics/fresnel.h"
#include "volumetric/dielectric.h"

namespace tsis {
namespace {

// Where a ray from a point light h1 above the plane z = 0, leaving at (θ, φ),
// lands on the plane z = −h2 after refracting into index eta (refract()).
glm::dvec3 landing(double h1, double h2, double eta, double theta, double phi) {
    const glm::dvec3 d(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                       -std::cos(theta));
    const glm::dvec3 y = glm::dvec3(0, 0, h1) + d * (h1 / std::cos(theta));
    glm::dvec3 t;
    refract(d, {0, 0, 1}, eta, t);
    return y + t * (h2 / -t.z);
}

TEST(RefractedLight, PointSpreadingIsTheRayBundlesArea) {
    // dA⊥/dΩ against finite differences of refracted rays: an independent
    // measure of the beam's spreading through the plane.
    for (double eta : {1.0, 1.3, 1.5})
        for (double theta : {0.05, 0.4, 0.9, 1.3}) {
            const double h1 = 3.0, h2 = 1.7, e = 1e-6, phi = 0.3;
            const glm::dvec3 dTheta =
                (landing(h1, h2, eta, theta + e, phi) - landing(h1, h2, eta, theta - e, phi)) /
                (2 * e);
            const glm::dvec3 dPhi =
                (landing(h1, h2, eta, theta, phi + e) - landing(h1, h2, eta, theta, phi - e)) /
                (2 * e);
            const double cosT = std::sqrt(1.0 - std::pow(std::sin(theta) / eta, 2));
            const double areaPerp = glm::length(glm::cross(dTheta, dPhi)) * cosT;
            const double expected = areaPerp / std::sin(theta);
            EXPECT_NEAR(pointRefractedSpreading(h1, h2, std::cos(theta), cosT, eta) / expected, 1.0,
                        1e-6)
                << "eta " << eta << " theta " << theta;
        }
    // Index-matched: the inverse-square law over the whole distance.
    EXPECT_NEAR(pointRefractedSpreading(2.0, 1.0, 1.0, 1.0, 1.0), 9.0, 1e-12);
}

TEST(RefractedLight, SolvesSnellsLawOnThePlane) {
    for (double d : {0.0, 0.3, 2.0, 10.0}) {
        const double h1 = 2.0, h2 = 0.8, eta = 1.4;
        const double s = solveRefractionSine(h1, h2, d, eta);
        const double st = s / eta;
        EXPECT_NEAR(h1 * s / std::sqrt(1 - s * s) + h2 * st / std::sqrt(1 - st * st), d, 1e-9);
    }
}

TEST(RefractedLight, DirectionalLightThroughTheHalfSpace) {
    const HalfSpace slab;
    Light light;
    light.type = Light::Type::Directional;
    const double angle = 0.5;
    light.vec = glm::vec3(std::sin(angle), -std::cos(angle), 0.0);
    light.rgb = glm::vec3(1.0f, 2.0f, 3.0f);
    const double eta = 1.3;
    const glm::dvec3 x(0.4, -0.7, 0.2);
    RefractedLight in;
    ASSERT_EQ(refractedLight(slab, light, eta, x, in), LightPath::Reached);
    const double sinT = std::sin(angle) / eta, cosT = std::sqrt(1 - sinT * sinT);
    // light.vec is float: its direction is good to ~1e-8.
    EXPECT_NEAR(in.distance, 0.7 / cosT, 1e-6);
    EXPECT_NEAR(in.entry.x, 0.4 - 0.7 * sinT / cosT, 1e-6);
    const double e = fresnelTransmittance(eta, std::cos(angle)) * std::cos(angle) / cosT;
    EXPECT_NEAR(in.irradiance.y, 2.0 * e, 1e-6);
}

TEST(RefractedLight, PointLightEntryObeysSnell) {
    const HalfSpace slab;
    Light light;
    light.vec = glm::vec3(1.0f, 2.5f, -0.5f);
    const double eta = 1.5;
    const glm::dvec3 x(-1.2, -0.9, 0.7);
    RefractedLight in;
    ASSERT_EQ(refractedLight(slab, light, eta, x, in), LightPath::Reached);
    EXPECT_NEAR(in.entry.y, 0.0, 1e-12);
    const glm::dvec3 incoming = glm::normalize(in.entry - glm::dvec3(light.vec));
    glm::dvec3 t;
    refract(incoming, {0, 1, 0}, eta, t);
    EXPECT_NEAR(glm::dot(t, glm::normalize(x - in.entry)), 1.0, 1e-9);
    EXPECT_NEAR(in.distance, glm::length(x - in.entry), 1e-12);
    // Below the light the beam is ≈ the inverse square over h1 + h2/η.
    const glm::dvec3 below(1.0, -0.9, -0.5);
    ASSERT_EQ(refractedLight(slab, light, eta, below, in), LightPath::Reached);
    EXPECT_NEAR(in.irradiance.x, fresnelTransmittance(eta, 1.0) / std::pow(2.5 + 0.9 / eta, 2),
                1e-9);
}

TEST(RefractedLight, LightBelowTheSurfaceDoesNotReach) {
    const HalfSpace slab;
    Light light;
    light.vec = glm::vec3(0.0f, -1.0f, 0.0f);  // inside the medium's half
    RefractedLight in;
    EXPECT_EQ(refractedLight(slab, light, 1.3, {0.0, -2.0, 0.0}, in), LightPath::Blocked);
}

}  // namespace
}  // namespace tsis
