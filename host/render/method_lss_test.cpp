// lss: its radius table, the plane's closed form, a lit sphere against the
// ground truth, determinism.
#include "render/method_lss.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "render/image_space_test_util.h"

namespace tsis {
namespace {

TEST(Lss, RadiusTableRisesFromZeroToRMax) {
    const Dipole dipole(presetMaterial("marble"));
    const RadialImportance rd([&](double r) { return dipole.Rd(r); }, 12.0);
    const std::vector<float> radii = LssMethod::radiusTable(rd, 64);
    ASSERT_EQ(radii.size(), 65u);
    EXPECT_EQ(radii.front(), 0.0f);
    EXPECT_FLOAT_EQ(radii.back(), 12.0f);
    for (size_t k = 1; k < radii.size(); ++k) EXPECT_GT(radii[k], radii[k - 1]) << k;
    // Half the samples fall within the mixture's median.
    EXPECT_NEAR(rd.cdf(radii[32]), 0.5, 1e-6);
}

// The plane under a normal light, all of it the method integrates in view:
// the camera sees ±25 mm (Rd's tail beyond that is < 1% for skin1) and the
// centre pixels must give B = E·Ft(1)·∫Rd dA.
TEST(Lss, PlaneMatchesClosedForm) {
    Scene scene;
    scene.material = presetMaterial("skin1");
    scene.mesh = builtinPlane();
    normalizeMesh(scene.mesh, 2.0 * 40.0 * std::sqrt(2.0));
    ensureNormals(scene.mesh);
    scene.lights = {{Light::Type::Directional, glm::vec3(0, -1, 0), glm::vec3(1.0f)}};
    scene.camera.eye = glm::vec3(0, 60, 0);
    scene.camera.up = glm::vec3(0, 0, -1);
    scene.camera.fovYDegrees = static_cast<float>(2.0 * std::atan(25.0 / 60.0) * 180.0 / M_PI);
    RenderOptions opt;
    opt.width = opt.height = 96;
    opt.atlasResolution = 64;  // unused by lss
    opt.lightResolution = 256;
    opt.samples = 2048;
    const FrameResult f = test::renderWith(scene, opt, "lss");
    glm::dvec3 got(0.0);
    int n = 0;
    for (int y = 44; y < 52; ++y)
        for (int x = 44; x < 52; ++x, ++n)
            for (int c = 0; c < 3; ++c) got[c] += f.radiosity.at(x, y, c);
    got /= static_cast<double>(n);
    const glm::dvec3 expected = test::planeClosedForm(scene.material);
    for (int c = 0; c < 3; ++c) {
        const double err = got[c] / expected[c] - 1.0;
        std::printf("lss plane skin1 channel %d: B = %.5f, closed form %.5f, %+.3f%%\n", c, got[c],
                    expected[c], 100 * err);
        EXPECT_NEAR(err, 0.0, 0.03) << "channel " << c;
    }
}

TEST(Lss, LitSphereIsSaneAgainstGroundTruth) {
    const Scene scene = test::litSphereScene("skin1");
    RenderOptions opt;
    opt.width = opt.height = 64;
    opt.atlasResolution = 512;
    opt.lightResolution = 512;
    const FrameResult truth = test::groundTruth(scene, opt);
    opt.samples = 256;
    test::expectSaneAgainstTruth(test::renderWith(scene, opt, "lss"), truth, 0.1, "lss sphere");
}

TEST(Lss, SameSeedSameRadiosity) {
    const Scene scene = test::litSphereScene("marble");
    RenderOptions opt;
    opt.width = opt.height = 48;
    opt.lightResolution = 256;
    opt.samples = 64;
    opt.seed = 7;
    const FrameResult a = test::renderWith(scene, opt, "lss");
    const FrameResult b = test::renderWith(scene, opt, "lss");
    EXPECT_TRUE(test::sameRadiosity(a, b));
    opt.seed = 8;
    EXPECT_FALSE(test::sameRadiosity(a, test::renderWith(scene, opt, "lss")));
}

}  // namespace
}  // namespace tsis
