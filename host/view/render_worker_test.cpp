#include "view/render_worker.h"

#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <memory>
#include <thread>

#include "support/render.h"

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

}  // namespace
}  // namespace tsis
