#include "view/render_worker.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <memory>
#include <thread>

#include "support/render.h"
#include "support/scoped_env.h"
#include "support/scratch_dir.h"

namespace tsis {
namespace {

// Polls `ready` every 10 ms for up to a minute (a loaded machine is slow).
bool eventually(const std::function<bool()>& ready) {
    for (int i = 0; i < 6000; ++i) {
        if (ready()) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return false;
}

FrameDone frameOf(RenderWorker& worker, const FrameJob& job) {
    worker.submit(job);
    std::optional<FrameDone> done;
    EXPECT_TRUE(eventually([&] { return (done = worker.take()).has_value(); }));
    return done ? std::move(*done) : FrameDone{};
}

// Left idle after a frame that gathered at its pixels (the light moved), the
// worker makes pyramid's copy over the atlas: the first camera move then
// reads it on the GL side (no run of the method), and a frame that read the
// copy leaves nothing to prepare.
TEST(RenderWorker, PreparesCameraMovesWhileIdleAfterALightChange) {
    Scene scene = test::torusScene("skin1", 10.0);
    FrameJob job;
    job.mesh = std::make_shared<const Mesh>(scene.mesh);
    job.scene = scene;
    job.scene.mesh = Mesh();
    job.options = test::smallOptions(64, 256);
    job.options.method = "pyramid";
    RenderWorker worker("", "", nullptr);

    job.id = 1;
    const FrameDone lit = frameOf(worker, job);
    ASSERT_TRUE(lit.error.empty()) << lit.error;
    EXPECT_EQ(lit.frame.stats.number("pyramid_from_atlas"), 0);
    ASSERT_TRUE(eventually([&] { return worker.preparations() == 1 && !worker.busy(); }));

    job.id = 2;
    job.scene.camera.eye = glm::vec3(-6, 5, 12);
    const FrameDone moved = frameOf(worker, job);
    ASSERT_TRUE(moved.error.empty()) << moved.error;
    EXPECT_EQ(moved.frame.stats.number("radiosity_lookup_gl"), 1);
    std::this_thread::sleep_for(RenderWorker::kPrepareAfter * 3);
    EXPECT_FALSE(worker.busy());
    EXPECT_EQ(worker.preparations(), 1);
}

// A material whose transport is fitted for the first time: the worker shows
// the frame without it at once and, the fit done, the frame with it, unasked.
TEST(RenderWorker, MakesTheFrameAgainWhenItsTransportIsFitted) {
    const test::ScratchDir cache;
    const test::ScopedEnv env("TSIS_CACHE_DIR", cache.path().string());
    Scene scene = test::torusScene("skin1", 10.0);
    FrameJob job;
    job.id = 7;
    job.mesh = std::make_shared<const Mesh>(scene.mesh);
    job.scene = scene;
    job.scene.mesh = Mesh();
    job.options = test::smallOptions(48, 128);
    job.options.transport = Transport::Object;
    job.options.method = "pyramid";
    RenderWorker worker("", "", nullptr);

    const FrameDone first = frameOf(worker, job);
    ASSERT_TRUE(first.error.empty()) << first.error;
    EXPECT_EQ(first.frame.stats.number("transport_pending"), 1);
    std::optional<FrameDone> second;
    ASSERT_TRUE(eventually([&] { return (second = worker.take()).has_value(); }));
    ASSERT_TRUE(second->error.empty()) << second->error;
    EXPECT_EQ(second->id, 7u);
    EXPECT_TRUE(std::isnan(second->frame.stats.number("transport_pending")));
    EXPECT_NE(second->frame.rgb8, first.frame.rgb8);
}

}  // namespace
}  // namespace tsis
