#include "render/accumulator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "support/render.h"

namespace tsis {
namespace {

TEST(RadiosityAccumulator, MeanOfFramesUntilTheKeyChanges) {
    RadiosityAccumulator acc;
    EXPECT_EQ(acc.framesFor(7), 0u);
    acc.add(7, {1, 2, 3, 1});
    EXPECT_EQ(acc.framesFor(7), 1u);
    EXPECT_EQ(acc.framesFor(8), 0u);
    acc.add(7, {3, 2, 1, 1});
    const std::vector<float>& mean = acc.add(7, {5, 8, 2, 1});
    EXPECT_EQ(acc.framesFor(7), 3u);
    EXPECT_EQ(mean, (std::vector<float>{3, 4, 2, 1}));
    // A new key starts over: the mean is the new frame alone.
    EXPECT_EQ(acc.add(8, {9, 9, 9, 1}), (std::vector<float>{9, 9, 9, 1}));
    EXPECT_EQ(acc.framesFor(8), 1u);
    EXPECT_EQ(acc.framesFor(7), 0u);
    // So does a new image size under the same key.
    EXPECT_EQ(acc.add(8, {1, 1, 1, 1, 2, 2, 2, 1}).size(), 8u);
    EXPECT_EQ(acc.framesFor(8), 1u);
}

// K progressive frames of N samples come as close to the converged image as
// one frame of K·N: the sets' offsets are spread by the golden ratio, so their
// union stays stratified (independent offsets would only gain √K).
TEST(Progressive, SixteenFramesOfNAreAsGoodAsOneFrameOf16N) {
    const Scene scene = test::sphereScene(
        "skimmilk", {Light::Type::Point, glm::vec3(-8, 10, -6), glm::vec3(200.0f)});
    Renderer& r = test::sharedRenderer();
    RenderOptions opt = test::smallOptions(64, 512, 1 << 16);
    const FrameResult ref = test::renderWith(scene, opt, "tsis");
    opt.samples = 4096;
    const double big = test::relativeRmse(test::renderWith(scene, opt, "tsis"), ref);
    opt.samples = 256;
    const FrameResult single = test::renderWith(scene, opt, "tsis");
    const double one = test::relativeRmse(single, ref);

    opt.progressive = true;
    r.restartAccumulation();
    FrameResult f = test::renderWith(scene, opt, "tsis");
    EXPECT_EQ(f.radiosity.pixels, single.radiosity.pixels) << "the first set is the plain frame's";
    for (int k = 1; k < 16; ++k) f = test::renderWith(scene, opt, "tsis");
    EXPECT_EQ(f.stats.number("accumulated_frames"), 16);
    const double progressive = test::relativeRmse(f, ref);
    std::printf("relative RMSE: N = 256 %.4f, 16 progressive frames of 256 %.4f, N = 4096 %.4f\n",
                one, progressive, big);
    // Measured: 0.0440, 0.0058, 0.0041. Independent offsets would give about
    // one/4; the golden-ratio sets do better than that.
    EXPECT_LT(progressive, one / 5);
    EXPECT_LT(progressive, 2 * big);
}

TEST(Progressive, AChangeStartsANewMean) {
    Scene scene = test::sphereScene(
        "marble", {Light::Type::Directional, glm::vec3(0, -1, 0), glm::vec3(1.0f)});
    RenderOptions opt = test::smallOptions(32, 256, 64);
    opt.progressive = true;
    test::sharedRenderer().restartAccumulation();
    test::renderWith(scene, opt, "tsis");
    EXPECT_EQ(test::renderWith(scene, opt, "tsis").stats.number("accumulated_frames"), 2);
    opt.key = 0.5f;  // tone mapping only: the radiosity's mean goes on
    EXPECT_EQ(test::renderWith(scene, opt, "tsis").stats.number("accumulated_frames"), 3);
    scene.lights[0].vec = glm::vec3(0.3f, -1, 0);
    EXPECT_EQ(test::renderWith(scene, opt, "tsis").stats.number("accumulated_frames"), 1);
    opt.samples = 128;
    EXPECT_EQ(test::renderWith(scene, opt, "tsis").stats.number("accumulated_frames"), 1);
    scene.material = presetMaterial("skin1");
    EXPECT_EQ(test::renderWith(scene, opt, "tsis").stats.number("accumulated_frames"), 1);
    opt.progressive = false;
    EXPECT_TRUE(
        std::isnan(test::renderWith(scene, opt, "tsis").stats.number("accumulated_frames")));
}

}  // namespace
}  // namespace tsis
