#include "volumetric/slab.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "physics/fresnel.h"
#include "support/volumetric_walk.h"
#include "volumetric/boundary.h"
#include "volumetric/camera_walk.h"

namespace tsis {
namespace {

// Chandrasekhar's H-function of isotropic scattering with albedo a < 1, by
// iterating 1/H(μ) = √(1−a) + (a/2)∫₀¹ μ′H(μ′)/(μ+μ′) dμ′ on a Simpson grid.
class HFunction {
  public:
    explicit HFunction(double a) : a_(a), h_(kNodes + 1, 1.0) {
        for (int iter = 0; iter < 200; ++iter) {
            std::vector<double> next(kNodes + 1);
            for (int i = 0; i <= kNodes; ++i) next[i] = (*this)(node(i));
            h_ = next;
        }
    }
    double operator()(double mu) const {
        double s = 0;
        for (int i = 0; i <= kNodes; ++i) {
            const double w = (i == 0 || i == kNodes) ? 1.0 : (i % 2 ? 4.0 : 2.0);
            s += w * node(i) * h_[i] / (mu + node(i) + 1e-300);
        }
        return 1.0 / (std::sqrt(1.0 - a_) + 0.5 * a_ * s / (3.0 * kNodes));
    }

  private:
    static constexpr int kNodes = 400;  // even
    static double node(int i) { return static_cast<double>(i) / kNodes; }
    double a_;
    std::vector<double> h_;
};

// The camera walk at the half-space's origin, seen along the normal.
MeanEstimate normalView(const WalkScene& scene, int paths, WalkCounters& counters) {
    SurfaceHit hit;
    hit.normal = {0, 1, 0};
    MeanEstimate walk;
    for (int i = 0; i < paths; ++i) {
        Rng rng(7, static_cast<uint64_t>(i));
        walk.add(exitantRadiance(scene, hit, {0, 1, 0}, rng, counters));
    }
    return walk;
}

TEST(Slab, IndexMatchedAlbedoProblemMatchesChandrasekhar) {
    // η = 1, light straight down: R = 1 − H(1)·√(1 − a) (the albedo problem of
    // a semi-infinite isotropic medium, Chandrasekhar 1960).
    for (double a : {0.5, 0.9}) {
        const Medium m = testMedium(glm::dvec3(a), glm::dvec3(1.0 - a), 1.0);
        SlabOptions o;
        o.photons = 200000;
        const SlabResult r = traceSlab(m, o);
        const double expected = 1.0 - HFunction(a)(1.0) * std::sqrt(1.0 - a);
        EXPECT_NEAR(r.reflectance.x, expected, 4 * r.reflectanceError.x + 1e-4) << "albedo " << a;
    }
}

TEST(Slab, ChandrasekharHMoment) {
    // The solver against the H-function's zeroth moment, a closed form:
    // ∫₀¹ H dμ = (2/a)(1 − √(1 − a)).
    for (double a : {0.5, 0.9}) {
        const HFunction h(a);
        double s = 0;
        const int n = 200;
        for (int i = 0; i <= n; ++i)
            s += ((i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0)) * h(static_cast<double>(i) / n);
        EXPECT_NEAR(s / (3.0 * n), 2.0 / a * (1.0 - std::sqrt(1.0 - a)), 1e-4) << "albedo " << a;
    }
}

TEST(Slab, LightTracerAndSkyLitCameraWalkAgree) {
    // Reciprocity: the normal-view radiance of the slab under a unit sky
    // (without the specular reflection) is the total reflectance of a beam
    // arriving along the normal, Ft(η, 1) × the reflectance per entered flux.
    // Two independent estimators: the light tracer and the camera walk.
    const Medium m = testMedium({0.74, 0.88, 1.01}, {0.032, 0.17, 0.48}, 1.3);  // skin1
    SlabOptions o;
    o.photons = 100000;
    const SlabResult light = traceSlab(m, o);
    const HalfSpace slab;
    WalkCounters counters;
    const MeanEstimate walk = normalView({&slab, m, {}, glm::dvec3(1.0)}, 100000, counters);
    const double ft = fresnelTransmittance(1.3, 1.0);
    for (int c = 0; c < 3; ++c) {
        const double mean = walk.mean()[c], err = walk.error(c);
        const double expected = ft * light.reflectance[c];
        EXPECT_NEAR(mean, expected, 4 * std::hypot(err, ft * light.reflectanceError[c]))
            << "channel " << c;
    }
}

TEST(Slab, DirectionalNextEventMatchesLightTracer) {
    // A directional light straight down, irradiance 1, seen along the normal:
    // the camera walk's refracted next-event estimation against the light
    // tracer's flux leaving in a narrow cone (per entered flux, × Ft(η, 1)).
    const Medium m = testMedium({1.0, 2.0, 0.5}, {0.25, 0.1, 0.5}, 1.3);
    SlabOptions o;
    o.photons = 400000;
    o.coneDegrees = 8;
    const SlabResult light = traceSlab(m, o);
    const HalfSpace slab;
    Light sun;
    sun.type = Light::Type::Directional;
    sun.vec = {0.0f, -1.0f, 0.0f};
    sun.rgb = glm::vec3(1.0f);
    WalkCounters counters;
    const MeanEstimate walk = normalView({&slab, m, {sun}, glm::dvec3(0.0)}, 40000, counters);
    EXPECT_EQ(counters.neeUnsettled, 0);
    const double ft = fresnelTransmittance(1.3, 1.0);
    for (int c = 0; c < 3; ++c) {
        const double mean = walk.mean()[c], err = walk.error(c);
        const double expected = ft * light.normalRadiance[c];
        // 4σ of both, and 1% for the cone's width (the radiance varies ~θ²).
        EXPECT_NEAR(mean, expected,
                    4 * std::hypot(err, ft * light.normalRadianceError[c]) + 0.01 * expected)
            << "channel " << c;
    }
}

}  // namespace
}  // namespace tsis
