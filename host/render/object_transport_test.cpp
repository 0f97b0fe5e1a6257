// --transport object's fits in the background (ObjectTransport::
// setBackgroundFits, for `tsis view`): the frames while a fit runs are the
// frames without the correction, and the first frame after it is the one a
// renderer that waits for its fit makes.
#include "render/object_transport.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <thread>

#include "support/render.h"
#include "support/scoped_env.h"
#include "support/scratch_dir.h"

namespace tsis {
namespace {

RenderOptions transportOptions() {
    RenderOptions opt = test::smallOptions(48, 128);
    opt.transport = Transport::Object;
    opt.method = "pyramid";
    return opt;
}

// An empty cache, so that the fit is made (not read from disk).
TEST(ObjectTransportBackground, FramesWithoutTheFitThenTheFrameWithIt) {
    const test::ScratchDir cache;
    const test::ScopedEnv env("TSIS_CACHE_DIR", cache.path().string());
    Scene scene = test::torusScene("skin1", 10.0);
    const RenderOptions opt = transportOptions();
    RenderOptions off = opt;
    off.transport = Transport::Off;

    Renderer background;
    background.setBackgroundFits(true);
    const FrameResult first = background.render(scene, opt);
    EXPECT_EQ(first.stats.number("transport_pending"), 1);
    const FrameResult without = background.render(scene, off);
    EXPECT_EQ(first.rgb8, without.rgb8);

    const auto start = std::chrono::steady_clock::now();
    while (!background.backgroundFitReady()) {
        ASSERT_LT(std::chrono::steady_clock::now() - start, std::chrono::minutes(2));
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    const FrameResult fitted = background.render(scene, opt);
    EXPECT_TRUE(std::isnan(fitted.stats.number("transport_pending")));
    EXPECT_EQ(fitted.stats.number("transport_loaded"), 0);
    EXPECT_NE(fitted.rgb8, without.rgb8);

    // A renderer that waits: the same fit, read from the disk the
    // background fit wrote, and the same frame.
    Renderer waits;
    const FrameResult same = waits.render(scene, opt);
    EXPECT_EQ(same.stats.number("transport_loaded"), 1);
    EXPECT_EQ(same.rgb8, fitted.rgb8);

    // A fit on disk is read at once, in the background mode too.
    Renderer again;
    again.setBackgroundFits(true);
    const FrameResult read = again.render(scene, opt);
    EXPECT_TRUE(std::isnan(read.stats.number("transport_pending")));
    EXPECT_EQ(read.stats.number("transport_loaded"), 1);
    EXPECT_EQ(read.rgb8, fitted.rgb8);
}

// Requests while one fit runs: the newest runs after it (one in between may
// be dropped, as the timing falls), and the frame gets its own material's
// fit; the first runs to its end.
TEST(ObjectTransportBackground, TheNewestRequestRunsNext) {
    const test::ScratchDir cache;
    const test::ScopedEnv env("TSIS_CACHE_DIR", cache.path().string());
    Scene scene = test::torusScene("skin1", 10.0);
    const RenderOptions opt = transportOptions();
    Renderer background;
    background.setBackgroundFits(true);
    auto waitAndRender = [&] {
        const auto start = std::chrono::steady_clock::now();
        for (;;) {
            FrameResult f = background.render(scene, opt);
            if (std::isnan(f.stats.number("transport_pending"))) return f;
            EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::minutes(2));
            if (std::chrono::steady_clock::now() - start > std::chrono::minutes(2)) return f;
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
    };
    EXPECT_EQ(background.render(scene, opt).stats.number("transport_pending"), 1);
    scene.material = presetMaterial("marble");
    EXPECT_EQ(background.render(scene, opt).stats.number("transport_pending"), 1);
    scene.material = presetMaterial("ketchup");
    EXPECT_EQ(background.render(scene, opt).stats.number("transport_pending"), 1);
    const FrameResult ketchup = waitAndRender();

    Renderer waits;
    const FrameResult same = waits.render(scene, opt);
    EXPECT_EQ(same.rgb8, ketchup.rgb8);
    EXPECT_EQ(same.stats.number("transport_loaded"), 1);
    scene.material = presetMaterial("skin1");
    EXPECT_EQ(waits.render(scene, opt).stats.number("transport_loaded"), 1);
}

// A frame fills only the grid nodes its points read: nodes a view read under
// an earlier lighting are filled again when a later view reads them. The
// camera goes back to a view after the light moved elsewhere, and the frame
// is a fresh renderer's; both on the CL side (the points) and through the
// copy a frame that only moved the camera reads (pyramid's camera cache).
TEST(ObjectTransport, NodesReadAgainHoldTheNewLighting) {
    const test::ScratchDir cache;
    const test::ScopedEnv env("TSIS_CACHE_DIR", cache.path().string());
    for (const PyramidCache where : {PyramidCache::Pixels, PyramidCache::Camera}) {
        Scene scene = test::torusScene("skin1", 10.0);
        RenderOptions opt = transportOptions();
        opt.pyramidCache = where;
        const glm::vec3 eye = scene.camera.eye, light = scene.lights[0].vec;
        Renderer moving;
        moving.render(scene, opt);
        scene.lights[0].vec = glm::vec3(-light.x, light.y, light.z);
        scene.camera.eye = glm::vec3(eye.y, eye.x, eye.z);
        moving.render(scene, opt);
        scene.camera.eye = eye;
        const FrameResult back = moving.render(scene, opt);
        // The same two frames without the first lighting before them.
        Renderer fresh;
        scene.camera.eye = glm::vec3(eye.y, eye.x, eye.z);
        fresh.render(scene, opt);
        scene.camera.eye = eye;
        EXPECT_EQ(back.rgb8, fresh.render(scene, opt).rgb8);
    }
}

}  // namespace
}  // namespace tsis
