#include "volumetric/slab.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "physics/fresnel.h"
#include "volumetric/boundary.h"
#include "volumetric/camera_walk.h"

namespace tsis {
namespace {

Medium medium(glm::dvec3 sigmaS, glm::dvec3 sigmaA, double eta) {
    Material mat;
    mat.sigmaSPrime = sigmaS;
    mat.sigmaA = sigmaA;
    mat.eta = eta;
    return Medium(mat);
}

// Chandrasekhar's H-function of isotropic scattering with albedo a, by
// iterating 1/H(μ) = √(1−a) + (a/2)∫₀¹ μ′H(μ′)/(μ+μ′) dμ′ on a Simpson grid.
double chandrasekharH(double a, double mu) {
    const int n = 2000;  // even
    std::vector<double> nodes(n + 1), h(n + 1, 1.0);
    for (int i = 0; i <= n; ++i) nodes[i] = static_cast<double>(i) / n;
    auto integral = [&](double m) {
        double s = 0;
        for (int i = 0; i <= n; ++i) {
            const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
            s += w * nodes[i] * h[i] / (m + nodes[i]);
        }
        return s / (3.0 * n);
    };
    for (int iter = 0; iter < 300; ++iter) {
        std::vector<double> next(n + 1);
        for (int i = 0; i <= n; ++i)
            next[i] = 1.0 / (std::sqrt(1.0 - a) + 0.5 * a * integral(std::max(nodes[i], 1e-12)));
        h = next;
    }
    return 1.0 / (std::sqrt(1.0 - a) + 0.5 * a * integral(mu));
}

TEST(Slab, IndexMatchedAlbedoProblemMatchesChandrasekhar) {
    // η = 1, light straight down: R = 1 − H(1)·√(1 − a) (the albedo problem of
    // a semi-infinite isotropic medium, Chandrasekhar 1960).
    for (double a : {0.5, 0.9}) {
        const Medium m = medium(glm::dvec3(a), glm::dvec3(1.0 - a), 1.0);
        SlabOptions o;
        o.photons = 200000;
        const SlabResult r = traceSlab(m, o);
        const double expected = 1.0 - chandrasekharH(a, 1.0) * std::sqrt(1.0 - a);
        EXPECT_NEAR(r.reflectance.x, expected, 4 * r.reflectanceError.x + 1e-4) << "albedo " << a;
    }
}

TEST(Slab, ChandrasekharHKnownValue) {
    // Conservative scattering: H(1) = 2.9078 (Chandrasekhar's table).
    EXPECT_NEAR(chandrasekharH(1.0, 1.0), 2.9078, 2e-3);
}

TEST(Slab, LightTracerAndSkyLitCameraWalkAgree) {
    // Reciprocity: the normal-view radiance of the slab under a unit sky
    // (without the specular reflection) is the total reflectance of a beam
    // arriving along the normal, Ft(η, 1) × the reflectance per entered flux.
    // Two independent estimators: the light tracer and the camera walk.
    const Medium m = medium({0.74, 0.88, 1.01}, {0.032, 0.17, 0.48}, 1.3);  // skin1
    SlabOptions o;
    o.photons = 100000;
    const SlabResult light = traceSlab(m, o);
    const HalfSpace slab;
    WalkScene scene{&slab, m, {}, glm::dvec3(1.0)};
    SurfaceHit hit;
    hit.normal = {0, 1, 0};
    WalkCounters counters;
    glm::dvec3 sum(0.0), sumSq(0.0);
    const int n = 100000;
    for (int i = 0; i < n; ++i) {
        Rng rng(7, static_cast<uint64_t>(i));
        const glm::dvec3 v = exitantRadiance(scene, hit, {0, 1, 0}, rng, counters);
        sum += v;
        sumSq += v * v;
    }
    const double ft = fresnelTransmittance(1.3, 1.0);
    for (int c = 0; c < 3; ++c) {
        const double mean = sum[c] / n;
        const double err = std::sqrt((sumSq[c] / n - mean * mean) / n);
        const double expected = ft * light.reflectance[c];
        EXPECT_NEAR(mean, expected, 4 * std::hypot(err, ft * light.reflectanceError[c]))
            << "channel " << c;
    }
}

TEST(Slab, DirectionalNextEventMatchesLightTracer) {
    // A directional light straight down, irradiance 1, seen along the normal:
    // the camera walk's refracted next-event estimation against the light
    // tracer's flux leaving in a narrow cone (per entered flux, × Ft(η, 1)).
    const Medium m = medium({1.0, 2.0, 0.5}, {0.25, 0.1, 0.5}, 1.3);
    SlabOptions o;
    o.photons = 400000;
    o.coneDegrees = 8;
    const SlabResult light = traceSlab(m, o);
    const HalfSpace slab;
    Light sun;
    sun.type = Light::Type::Directional;
    sun.vec = {0.0f, -1.0f, 0.0f};
    sun.rgb = glm::vec3(1.0f);
    WalkScene scene{&slab, m, {sun}, glm::dvec3(0.0)};
    SurfaceHit hit;
    hit.normal = {0, 1, 0};
    WalkCounters counters;
    glm::dvec3 sum(0.0), sumSq(0.0);
    const int n = 40000;
    for (int i = 0; i < n; ++i) {
        Rng rng(3, static_cast<uint64_t>(i));
        const glm::dvec3 v = exitantRadiance(scene, hit, {0, 1, 0}, rng, counters);
        sum += v;
        sumSq += v * v;
    }
    EXPECT_EQ(counters.neeUnsolved, 0);
    const double ft = fresnelTransmittance(1.3, 1.0);
    for (int c = 0; c < 3; ++c) {
        const double mean = sum[c] / n;
        const double err = std::sqrt((sumSq[c] / n - mean * mean) / n);
        const double expected = ft * light.normalRadiance[c];
        // 4σ of both, and 1% for the cone's width (the radiance varies ~θ²).
        EXPECT_NEAR(mean, expected,
                    4 * std::hypot(err, ft * light.normalRadianceError[c]) + 0.01 * expected)
            << "channel " << c;
    }
}

}  // namespace
}  // namespace tsis
