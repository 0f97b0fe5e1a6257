#include "volumetric/refracted_light.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "mesh/builtin.h"
#include "mesh/mesh.h"
#include "physics/fresnel.h"
#include "volumetric/dielectric.h"
#include "volumetric/mesh_boundary.h"

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
    RefractedLights all;
    ASSERT_EQ(refractedLights(slab, light, eta, x, all), LightPath::Reached);
    ASSERT_EQ(all.count, 1);
    const RefractedLight& in = all.paths[0];
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
    RefractedLights all;
    ASSERT_EQ(refractedLights(slab, light, eta, x, all), LightPath::Reached);
    ASSERT_EQ(all.count, 1);
    const RefractedLight& in = all.paths[0];
    EXPECT_NEAR(in.entry.y, 0.0, 1e-12);
    const glm::dvec3 incoming = glm::normalize(in.entry - glm::dvec3(light.vec));
    glm::dvec3 t;
    refract(incoming, {0, 1, 0}, eta, t);
    EXPECT_NEAR(glm::dot(t, glm::normalize(x - in.entry)), 1.0, 1e-9);
    EXPECT_NEAR(in.distance, glm::length(x - in.entry), 1e-12);
    // Below the light the beam is ≈ the inverse square over h1 + h2/η.
    const glm::dvec3 below(1.0, -0.9, -0.5);
    ASSERT_EQ(refractedLights(slab, light, eta, below, all), LightPath::Reached);
    EXPECT_NEAR(all.paths[0].irradiance.x,
                fresnelTransmittance(eta, 1.0) / std::pow(2.5 + 0.9 / eta, 2), 1e-9);
}

TEST(RefractedLight, LightBelowTheSurfaceDoesNotReach) {
    const HalfSpace slab;
    Light light;
    light.vec = glm::vec3(0.0f, -1.0f, 0.0f);  // inside the medium's half
    RefractedLights in;
    EXPECT_EQ(refractedLights(slab, light, 1.3, {0.0, -2.0, 0.0}, in), LightPath::Blocked);
}

// The light reaching x through every facet of the mesh, by brute force: each
// facet's own plane solution, kept where the ray from x towards it leaves the
// object on that facet.
double irradianceThroughEveryFacet(const Mesh& mesh, const MeshBoundary& boundary,
                                   const Light& light, double eta, const glm::dvec3& x) {
    double sum = 0;
    for (size_t f = 0; f < mesh.triangles.size(); ++f) {
        glm::dvec3 v[3], n;
        boundary.facet(static_cast<int>(f), v, n);
        const double h2 = glm::dot(v[0] - x, n);
        if (h2 <= 0) continue;
        glm::dvec3 y, incoming;
        if (light.type == Light::Type::Point) {
            const glm::dvec3 p(light.vec);
            const double h1 = glm::dot(p - v[0], n);
            if (h1 <= 0) continue;
            const glm::dvec3 foot = p - h1 * n, across = x + h2 * n - foot;
            const double d = glm::length(across);
            const double s = solveRefractionSine(h1, h2, d, eta);
            y = d > 0 ? foot + across * (h1 * s / (std::sqrt(1 - s * s) * d)) : foot;
            incoming = glm::normalize(y - p);
        } else {
            incoming = glm::normalize(glm::dvec3(light.vec));
            glm::dvec3 t;
            if (glm::dot(incoming, n) >= 0 || !refract(incoming, n, eta, t)) continue;
            y = x - t * (h2 / -glm::dot(t, n));
        }
        SurfaceHit hit;
        const double dist = glm::length(y - x);
        if (!boundary.intersect(x, (y - x) / dist, kInfinity, hit) ||
            hit.facet != static_cast<int>(f) || std::abs(hit.t - dist) > 1e-6)
            continue;
        const double cosI = -glm::dot(incoming, n);
        const double cosT = std::sqrt(1 - (1 - cosI * cosI) / (eta * eta));
        const double spread =
            light.type == Light::Type::Point
                ? 1.0 / pointRefractedSpreading(glm::dot(glm::dvec3(light.vec) - y, n), h2, cosI,
                                                cosT, eta)
                : cosI / cosT;
        sum += light.rgb.x * fresnelTransmittance(eta, cosI) * spread;
    }
    return sum;
}

TEST(RefractedLight, FindsEveryFacetWhoseBeamReachesThePoint) {
    // A 5 mm sphere at η = 1.5 focuses the light: below ~1 mm the refracted
    // beams of neighbouring facets overlap, 2–4 of them at the centre. The
    // connections must add up to the brute-force sum over all facets (down
    // to 6.5 mm; beyond, towards the far side, the rim's beams cross in the lens'
    // caustic, light that has crossed the object unscattered).
    Mesh mesh = builtinSphere();
    normalizeMesh(mesh, 10.0 * std::sqrt(3.0));
    const MeshBoundary boundary(mesh);
    Light directional;
    directional.type = Light::Type::Directional;
    directional.vec = glm::vec3(0.1f, -1.0f, 0.05f);
    directional.rgb = glm::vec3(1.0f);
    Light point;
    point.vec = glm::vec3(3.0f, 30.0f, -2.0f);
    point.rgb = glm::vec3(900.0f);
    int overlapping = 0;
    for (const Light& light : {directional, point})
        for (double depth : {0.5, 3.0, 5.0, 6.5})
            for (int k = 0; k < 6; ++k) {
                const double a = 0.4 * k;
                const glm::dvec3 x(std::sin(a) * 1.5, 5.0 - depth, std::cos(2 * a) * 1.2);
                RefractedLights in;
                ASSERT_EQ(refractedLights(boundary, light, 1.5, x, in), LightPath::Reached);
                double sum = 0;
                for (int i = 0; i < in.count; ++i) sum += in.paths[i].irradiance.x;
                EXPECT_NEAR(sum, irradianceThroughEveryFacet(mesh, boundary, light, 1.5, x),
                            1e-5 * sum)
                    << "depth " << depth << " k " << k;
                overlapping += in.count > 1;
            }
    EXPECT_GT(overlapping, 20);  // the case is there
}

TEST(RefractedLight, ReachesThePointWhereTheIterationCycles) {
    // Behind thin, curved parts lit near grazing, the iteration from the
    // straight line can cycle between facets whose solutions lie on each
    // other (5 % of the default scene's next-event estimations, 22 % of cow's):
    // where a facet nearby connects, the connection must be found, not
    // reported unsettled (light missed: the volumetric truth too dark there).
    Mesh mesh = builtinDefault();
    normalizeMesh(mesh, 10.0);
    const MeshBoundary boundary(mesh);
    Light light;
    light.vec = glm::vec3(-5.85f, 9.75f, -13.0f);
    light.rgb = glm::vec3(300.0f);
    int connected = 0, missed = 0;
    for (size_t k = 0; k < 600; ++k) {
        // Points 0.05–1.5 mm below facets spread over the mesh.
        const int f = static_cast<int>((k * 7919) % mesh.triangles.size());
        glm::dvec3 v[3], n;
        boundary.facet(f, v, n);
        const glm::dvec3 x = (v[0] + v[1] + v[2]) / 3.0 -
                             n * (0.05 + 1.45 * static_cast<double>((k * 37) % 100) / 100.0);
        SurfaceHit above;
        if (!boundary.intersect(x, n, kInfinity, above) || above.facet != f) continue;
        const double brute = irradianceThroughEveryFacet(mesh, boundary, light, 1.3, x);
        if (brute <= 0) continue;
        ++connected;
        RefractedLights in;
        missed += refractedLights(boundary, light, 1.3, x, in) == LightPath::Unsettled;
    }
    EXPECT_GT(connected, 300);  // the case is there
    // 8 of 415 before the search around the cycle; 1 now (its facet beyond
    // the 256 searched).
    EXPECT_LE(missed, 2) << "of " << connected << " points some facet connects to";
}

}  // namespace
}  // namespace tsis
