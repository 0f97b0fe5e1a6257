// ltsm alone, with the full Rd, against the plane's closed form: a plane under
// a normal light is all visible from the light, so the light-view filter sees
// everything it integrates.
#include <gtest/gtest.h>

#include <cstdio>

#include "render/render_test_util.h"

namespace tsis {
namespace {

void checkPlane(const char* material, int rings, int perRing, double tolerance) {
    const Scene scene = test::planeScene(material);
    RenderOptions opt;
    opt.width = opt.height = 32;
    opt.atlasResolution = 64;  // unused by ltsm
    opt.lightResolution = 1024;
    opt.ltsmRings = rings;
    opt.ltsmPerRing = perRing;
    const FrameResult f = test::renderWith(scene, opt, "ltsm");
    const glm::dvec3 got = test::meanRadiosity(f);
    const glm::dvec3 expected = test::planeClosedForm(scene.material);
    for (int c = 0; c < 3; ++c) {
        const double err = got[c] / expected[c] - 1.0;
        std::printf("ltsm %d×%d+1 plane %s channel %d: B = %.5f, closed form %.5f, %+.3f%%\n",
                    rings, perRing, material, c, got[c], expected[c], 100 * err);
        EXPECT_NEAR(err, 0.0, tolerance) << material << " channel " << c;
    }
}

TEST(Ltsm, PlaneMarbleMatchesClosedForm) {
    checkPlane("marble", 4, 4, 0.03);
}
TEST(Ltsm, PlaneSkin1MatchesClosedForm) {
    checkPlane("skin1", 4, 4, 0.03);
}
TEST(Ltsm, PlaneCreamMatchesClosedFormWithOneRing) {
    checkPlane("cream", 1, 3, 0.03);
}

}  // namespace
}  // namespace tsis
