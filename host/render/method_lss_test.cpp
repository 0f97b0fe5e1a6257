// lss: its radius table, the plane's closed form, a lit sphere against the
// ground truth, determinism.
#include "render/method_lss.h"

#include <gtest/gtest.h>

#include "support/image_space.h"

namespace tsis {
namespace {

TEST(Lss, RadiusTableRisesFromZeroToRMax) {
    const Dipole dipole(presetMaterial("marble"));
    const RadialImportance rd([&](double r) { return dipole.Rd(r); }, 12.0);
    const std::vector<float> radii = rd.inverseTable(64);
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
    const Scene scene = test::squarePlaneScene("skin1", 40.0, 60.0, 25.0);
    RenderOptions opt = test::smallOptions(96, 256, 2048);
    opt.atlasResolution = 64;  // unused by lss
    const FrameResult f = test::renderWith(scene, opt, "lss");
    glm::dvec3 got(0.0);
    int n = 0;
    for (int y = 44; y < 52; ++y)
        for (int x = 44; x < 52; ++x, ++n)
            for (int c = 0; c < 3; ++c) got[c] += f.radiosity.at(x, y, c);
    got /= static_cast<double>(n);
    test::expectNearClosedForm(got, test::planeClosedForm(scene.material), 0.03, "lss plane skin1");
}

TEST(Lss, LitSphereIsSaneAgainstGroundTruth) {
    test::expectSaneOnLitSphere("lss", 0.1, "lss sphere", 256);
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
