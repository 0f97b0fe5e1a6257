// ltsm alone, with the full Rd, against the plane's closed form: a plane under
// a normal light is all visible from the light, so the light-view filter sees
// everything it integrates.
#include <gtest/gtest.h>

#include <string>

#include "support/render.h"

namespace tsis {
namespace {

void checkPlane(const char* material, int rings, int perRing, double tolerance) {
    const Scene scene = test::planeScene(material);
    RenderOptions opt = test::smallOptions(32, 1024);
    opt.atlasResolution = 64;  // unused by ltsm
    opt.ltsmRings = rings;
    opt.ltsmPerRing = perRing;
    const FrameResult f = test::renderWith(scene, opt, "ltsm");
    test::expectNearClosedForm(
        test::meanRadiosity(f), test::planeClosedForm(scene.material), tolerance,
        "ltsm " + std::to_string(rings) + "×" + std::to_string(perRing) + "+1 plane " + material);
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
