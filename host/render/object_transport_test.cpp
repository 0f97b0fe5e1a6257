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
#include "tsis_shared.h"

namespace tsis {
namespace {

RenderOptions transportOptions() {
    RenderOptions opt = test::smallOptions(48, 128);
    opt.transport = Transport::Object;
    opt.method = "pyramid";
    return opt;
}

// The frame's product reads the coefficients packed in bfloat16: two media
// of different sizes, every coefficient distinct (a Δ, H or G row read for
// another, or one pair's for its neighbour's, shows), against the sum in
// double from the transfer's own accessors; within bfloat16's 2^-8.
TEST(PatchCorrection, PackedProductMatchesTheTransfersSums) {
    PatchTransfer t;
    t.mediumStart = {0, 3, 5};
    t.blockStart = {0, 9};
    const size_t pairs = 9 + 4;
    for (size_t n = 0; n < pairs; ++n) {
        const auto f = static_cast<float>(n);
        t.delta.emplace_back(0.01f * (f + 1), 0.02f * (f + 2), -0.005f * (f + 3));
        t.angular.emplace_back(0.3f - 0.01f * f, 0.1f + 0.02f * f, -0.2f);
        for (int c = 0; c < 3; ++c)
            t.gradient.emplace_back(0.05f * float(c + 1) + 0.001f * f, -0.03f * float(c + 1),
                                    0.02f - 0.004f * f * float(c));
    }
    const std::vector<glm::vec3> flux = {
        {1, 2, 3}, {0, 0, 0}, {0.5f, 0.2f, 0.1f}, {2, 1, 1}, {0.3f, 0.6f, 0.9f}};
    const std::vector<glm::vec4> direction = {{0.1f, -0.2f, 0.3f, 0.05f},
                                              {0, 0, 0, 0},
                                              {-0.04f, 0.01f, 0.02f, -0.01f},
                                              {0.2f, 0.2f, -0.1f, 0.3f},
                                              {0.0f, 0.1f, 0.05f, 0.02f}};
    const PackedTransfer packed = packTransfer(t);
    const double exitancePerB = 0.8;
    for (int m = 0; m < 2; ++m) {
        const std::vector<glm::vec3> got =
            patchCorrection(packed, m, flux, direction, exitancePerB);
        const int first = t.mediumStart[size_t(m)], last = t.mediumStart[size_t(m) + 1];
        ASSERT_EQ(got.size(), size_t(last - first));
        for (int j = first; j < last; ++j)
            for (int c = 0; c < 3; ++c) {
                double want = 0, scale = 0;
                for (int i = first; i < last; ++i) {
                    const glm::dvec3 phi(flux[size_t(i)]);
                    const double y =
                        TSIS_LUMA_R * phi.x + TSIS_LUMA_G * phi.y + TSIS_LUMA_B * phi.z;
                    if (y <= 0) continue;
                    const glm::dvec4 d(direction[size_t(i)]);
                    const double term =
                        t.at(m, i, j)[c] + t.angularAt(m, i, j)[c] * d.w / y +
                        glm::dot(glm::dvec3(t.gradientAt(m, i, j, c)), glm::dvec3(d) / y);
                    want += phi[c] * term;
                    scale += std::abs(phi[c]) * (std::abs(t.at(m, i, j)[c]) + 1.0);
                }
                EXPECT_NEAR(got[size_t(j - first)][c], want / exitancePerB,
                            scale / exitancePerB / 256)
                    << "medium " << m << " patch " << j << " channel " << c;
            }
    }
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
