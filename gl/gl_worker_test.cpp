// The worker thread's context shares the caller's textures, reports its
// errors, and draws light views the caller reads as if it had drawn them.
#include "gl/gl_worker.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <thread>

#include "gl/gl.h"
#include "gl/gl_context.h"
#include "gl/gpu_mesh.h"
#include "gl/passes.h"
#include "mesh/builtin.h"
#include "tsis/error.h"

namespace tsis {
namespace {

TEST(GlWorker, DrawsIntoATextureTheCallerReadsOnEitherPlatform) {
    for (GlChoice choice : {GlChoice::Egl, GlChoice::OsMesa}) {
        GlContext gl(choice);
        RenderTarget target(4, 4, {GL_RGBA32F}, false);
        GlWorker worker(gl);
        std::thread::id where;
        worker.start([&] {
            where = std::this_thread::get_id();
            GLuint fbo = 0;
            glGenFramebuffers(1, &fbo);
            glBindFramebuffer(GL_FRAMEBUFFER, fbo);
            glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D,
                                   target.color(0), 0);
            const float value[4] = {1, 2, 3, 4};
            glClearBufferfv(GL_COLOR, 0, value);
            glDeleteFramebuffers(1, &fbo);
        });
        worker.wait();
        EXPECT_NE(where, std::this_thread::get_id());
        const std::vector<float> texels = target.readRGBA(0);
        ASSERT_EQ(texels.size(), 64u);
        for (size_t i = 0; i < texels.size(); ++i)
            EXPECT_EQ(texels[i], float(i % 4 + 1)) << glChoiceName(choice) << " " << i;
    }
}

TEST(GlWorker, ATaskErrorReachesWaitAndTheWorkerGoesOn) {
    GlContext gl;
    GlWorker worker(gl);
    worker.start([] { throw Error("no mesh"); });
    try {
        worker.wait();
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "no mesh");
    }
    bool ran = false;
    worker.start([&] { ran = true; });
    worker.wait();
    EXPECT_TRUE(ran);
}

// The default scene's mesh on the GL side, η = 1.3, no albedo atlas.
class GlWorkerScene : public ::testing::Test {
  protected:
    static Mesh defaultMesh() {
        Mesh mesh = builtinDefault();
        normalizeMesh(mesh, 10.0);
        ensureNormals(mesh);
        return mesh;
    }
    void SetUp() override {
        tables.updateMedia({{1.3f, 1.0f}});
        tables.updateAlbedo({}, 0, 0);
        tables.updateSurface({}, {}, 0, 0);
    }
    GlContext gl;
    GpuMesh gpu{defaultMesh()};
    MaterialTables tables;
};

// Three lights' shadows, half drawn on the worker's thread: the flux atlas
// they shade (the default scene's thin parts shadow its body) is the one of
// views all drawn here, byte for byte.
TEST_F(GlWorkerScene, LightViewsDrawnOnItShadeTheSameFluxAtlas) {
    GeometryAtlasPass geometry;
    geometry.run(gpu, 256);
    const std::vector<Light> lights = {
        {Light::Type::Point, glm::vec3(-6.0f, 10.0f, -13.0f), glm::vec3(300.0f)},
        {Light::Type::Directional, glm::vec3(0.6f, -0.4f, -1.0f), glm::vec3(0.1f)},
        {Light::Type::Point, glm::vec3(12.0f, -3.0f, 8.0f), glm::vec3(200.0f)}};
    // Depth-only views (no maps): those the worker takes.
    auto fluxAtlas = [&](GlWorker* worker) {
        std::vector<LightView> views;
        views.reserve(lights.size());
        for (const Light& l : lights) views.push_back(makeLightView(l, 6.0f, 512, false));
        LightViewPass pass;
        pass.setWorker(worker, 0);  // whatever the mesh's size
        pass.run(gpu, views, tables);
        FluxAtlasPass atlas;
        atlas.run(geometry.target(), views, pass.shadows(), tables);
        return atlas.target().readRGBA(0);
    };
    const std::vector<float> alone = fluxAtlas(nullptr);
    GlWorker worker(gl);
    const std::vector<float> shared = fluxAtlas(&worker);
    ASSERT_EQ(alone.size(), shared.size());
    size_t differ = 0;
    for (size_t i = 0; i < alone.size(); ++i) differ += alone[i] != shared[i];
    EXPECT_EQ(differ, 0u);
}

// The composite's samples' G-buffer (depth cleared only) drawn on the
// worker's thread: the same texels as one drawn here, the second time too
// (its framebuffer then holds the first draw's attachments).
TEST_F(GlWorkerScene, GBufferDrawnOnItIsTheOneDrawnHere) {
    std::vector<LightView> views;
    LightViewPass lights;
    lights.run(gpu, views, tables);
    const glm::mat4 viewProj = glm::perspective(0.7f, 1.0f, 1.0f, 100.0f) *
                               glm::lookAt(glm::vec3(0, 5, 16), glm::vec3(0), glm::vec3(0, 1, 0));
    GlWorker worker(gl);
    GBufferPass here(false), there(false);
    there.setWorker(&worker, 0);
    ASSERT_TRUE(there.onWorker(gpu, true));
    for (int size : {96, 128}) {
        here.run(gpu, views, lights.shadows(), tables, viewProj, size, size, 0, 0, true);
        there.start(gpu, views, lights.shadows(), tables, viewProj, size, size, false, 0, true);
        there.finish();
        for (int i = 0; i < 2; ++i) {
            const std::vector<float> a = here.target().readRGBA(i), b = there.target().readRGBA(i);
            size_t covered = 0, differ = 0;
            // Uncovered pixels keep what the target held (not cleared).
            const std::vector<float> position = here.target().readRGBA(0);
            for (size_t k = 0; k < a.size(); k += 4) {
                if (position[k + 3] == 0) continue;
                ++covered;
                for (size_t c = 0; c < 4; ++c) differ += a[k + c] != b[k + c];
            }
            EXPECT_GT(covered, size_t(size * size / 8)) << size;
            EXPECT_EQ(differ, 0u) << "attachment " << i << " at " << size;
        }
    }
}

}  // namespace
}  // namespace tsis
