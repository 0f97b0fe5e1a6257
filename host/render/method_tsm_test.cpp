// tsm: its pattern and weights, a lit sphere against the ground truth, light
// through a thin slab, determinism.
#include "render/method_tsm.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "support/image_space.h"

namespace tsis {
namespace {

TEST(Tsm, PatternHas21TapsThatTileTheDisk) {
    const std::vector<TsisTsmTap> taps = TsmMethod::pattern();
    ASSERT_EQ(taps.size(), 21u);
    double area = 0;
    for (const TsisTsmTap& t : taps) {
        const int ring = static_cast<int>(t.ring);
        const double r = std::hypot(t.x, t.y);
        // Inside its own annulus.
        EXPECT_GE(r, TsmMethod::kRingEdges[ring] - 1e-6);
        EXPECT_LE(r, TsmMethod::kRingEdges[ring + 1] + 1e-6);
        area += t.area;
    }
    EXPECT_NEAR(area, std::numbers::pi, 1e-5);
}

TEST(Tsm, AnnulusMeanMatchesQuadrature) {
    const Dipole dipole(presetMaterial("skin1"));
    const RadialImportance rd([&](double r) { return dipole.Rd(r); }, 40.0);
    for (double z : {0.0, 0.3, 2.0})
        for (auto [a, b] : {std::pair{0.0, 0.9}, std::pair{1.8, 3.7}}) {
            // Midpoint rule over ρ: ∫ Rd(√(ρ²+z²)) 2πρ dρ / (π(b²−a²)).
            glm::dvec3 sum(0.0);
            const int n = 20000;
            for (int i = 0; i < n; ++i) {
                const double rho = a + (b - a) * (i + 0.5) / n;
                sum += dipole.Rd(std::hypot(rho, z)) * (2.0 * std::numbers::pi * rho * (b - a) / n);
            }
            const glm::dvec3 expected = sum / (std::numbers::pi * (b * b - a * a));
            const glm::dvec3 got = TsmMethod::annulusMean(rd, a, b, z);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(got[c] / expected[c], 1.0, 1e-3)
                    << "z " << z << " a " << a << " c " << c;
        }
}

TEST(Tsm, LitSphereIsSaneAgainstGroundTruth) {
    test::expectSaneOnLitSphere("tsm", 0.2, "tsm sphere");
}

// A slab of thickness t lit from behind: its front gets no irradiance, so all
// its radiosity comes through the slab, B = E·Ft(1)·∫_{ρ ≤ R} Rd(√(ρ² + t²)) dA
// — what the filter integrates exactly on a plane (the footprints tile the
// disk of radius R and each ring's weight is Rd's mean over its annulus).
TEST(Tsm, ThinSlabBackLitGlowsOnItsUnlitFront) {
    const float half = 20.0f, t = 1.0f;
    Scene scene;
    scene.material = presetMaterial("skin1");
    Mesh& m = scene.mesh;
    m.name = "slab";
    for (int face = 0; face < 2; ++face) {
        const float z = face == 0 ? 0.5f * t : -0.5f * t;  // front faces +z, back −z
        const float nz = face == 0 ? 1.0f : -1.0f;
        const uint32_t base = static_cast<uint32_t>(m.positions.size());
        for (int i = 0; i < 4; ++i) {
            const float u = (i == 1 || i == 2) ? 1.0f : 0.0f, v = i >= 2 ? 1.0f : 0.0f;
            // The back face is mirrored in x so both wind counter-clockwise seen from outside.
            const float x = (face == 0 ? 2.0f * u - 1.0f : 1.0f - 2.0f * u) * half;
            m.positions.emplace_back(x, (2.0f * v - 1.0f) * half, z);
            m.normals.emplace_back(0.0f, 0.0f, nz);
            m.uvs.emplace_back(0.5f * face + 0.45f * u + 0.02f, 0.02f + 0.96f * v);
        }
        m.triangles.push_back({base, base + 1, base + 2});
        m.triangles.push_back({base, base + 2, base + 3});
    }
    scene.lights = {{Light::Type::Directional, glm::vec3(0, 0, 1), glm::vec3(1.0f)}};
    scene.camera.eye = glm::vec3(0, 0, 30);
    scene.camera.fovYDegrees = static_cast<float>(2.0 * std::atan(2.5 / 30.0) * 180.0 / M_PI);
    RenderOptions opt = test::smallOptions(32, 256);
    opt.atlasResolution = 64;  // unused by tsm
    const FrameResult f = test::renderWith(scene, opt, "tsm");
    const glm::dvec3 got = test::meanRadiosity(f);

    const double boundingRadius = std::sqrt(2.0 * half * half + 0.25 * t * t);
    const double R = TsmMethod::filterRadiusMm(scene.material, opt.tsmRadius, boundingRadius);
    const Dipole dipole(scene.material);
    const RadialImportance rd([&](double r) { return dipole.Rd(r); }, 4.0 * R);
    const glm::dvec3 expected = fresnelTransmittance(scene.material.eta, 1.0) *
                                (rd.mass(std::hypot(R, double(t))) - rd.mass(t));
    for (int c = 0; c < 3; ++c) {
        std::printf("tsm slab t = %.1f mm channel %d: B = %.5f, expected %.5f\n", t, c, got[c],
                    expected[c]);
        EXPECT_GT(got[c], 0.0);
        EXPECT_NEAR(got[c] / expected[c], 1.0, 0.05) << "channel " << c;
    }
}

TEST(Tsm, SameInputSameRadiosity) {
    const Scene scene = test::torusScene("marble", 10.0);
    RenderOptions opt;
    opt.width = opt.height = 48;
    opt.lightResolution = 256;
    const FrameResult a = test::renderWith(scene, opt, "tsm");
    const FrameResult b = test::renderWith(scene, opt, "tsm");
    EXPECT_TRUE(test::sameRadiosity(a, b));
    EXPECT_GT(test::meanRadiosity(a).x, 0.0);
}

}  // namespace
}  // namespace tsis
