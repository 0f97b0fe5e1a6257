#include "render/renderer.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

#include "gl/gl_worker.h"
#include "scene/environment.h"
#include "support/render.h"

namespace tsis {
namespace {

// A frame that keeps the light maps and flux atlas of the frame before (only
// the camera or the method moved) is the same, byte for byte, as the frame
// made from scratch; a change of light is never served stale maps.
TEST(Renderer, ReusedLightingGivesTheSameFrameAsFreshLighting) {
    Scene a =
        test::sphereScene("skin1", {Light::Type::Point, glm::vec3(-8, 10, -6), glm::vec3(200.0f)});
    Scene moved = a;
    moved.camera.eye = glm::vec3(10, 4, 12);
    Scene relit = moved;
    relit.lights[0].vec = glm::vec3(8, 10, 6);
    RenderOptions opt = test::smallOptions(48, 256, 256);
    // pyramid's frame after a camera-only move reads B from its copy over the
    // atlas, another computation (Pyramid.CameraMoveReadsBFromTheAtlas…).
    opt.pyramidCache = PyramidCache::Pixels;

    for (const char* method : {"tsis", "hybrid", "pyramid"}) {
        SCOPED_TRACE(method);
        const FrameResult first = test::renderWith(a, opt, method);
        const FrameResult reused = test::renderWith(moved, opt, method);
        EXPECT_EQ(reused.stats.number("lighting_reused"), 1);
        // pyramid: the node sums are kept too.
        if (std::string(method) == "pyramid") {
            EXPECT_EQ(reused.stats.number("pyramid_rebuilt"), 0);
        }
        const FrameResult other = test::renderWith(relit, opt, method);
        EXPECT_EQ(other.stats.number("lighting_reused"), 0);
        EXPECT_NE(other.radiosity.pixels, reused.radiosity.pixels);
        // Back to a's light from a different one: made afresh.
        const FrameResult fresh = test::renderWith(moved, opt, method);
        EXPECT_EQ(fresh.stats.number("lighting_reused"), 0);
        EXPECT_EQ(fresh.radiosity.pixels, reused.radiosity.pixels);
        EXPECT_EQ(fresh.rgb8, reused.rgb8);
        EXPECT_EQ(test::renderWith(a, opt, method).rgb8, first.rgb8);
        RenderOptions again = opt;
        again.reuseLighting = false;
        const FrameResult forced = test::renderWith(a, again, method);
        EXPECT_EQ(forced.stats.number("lighting_reused"), 0);
        EXPECT_EQ(forced.rgb8, first.rgb8);
    }
}

// Two lights, one moved: only its view is drawn again (the other's shadow
// map, and for the light-view methods its flux and position maps, are kept),
// and the frame equals one whose every view was drawn afresh.
TEST(Renderer, MovingOneLightRedrawsOnlyItsView) {
    Scene a =
        test::sphereScene("skin1", {Light::Type::Point, glm::vec3(-8, 10, -6), glm::vec3(200.0f)});
    a.lights.push_back({Light::Type::Directional, glm::vec3(0.3f, -1, -0.5f), glm::vec3(0.5f)});
    Scene moved = a;
    moved.lights[0].vec = glm::vec3(8, 10, 6);
    const RenderOptions opt = test::smallOptions(48, 256, 256);
    RenderOptions fresh = opt;
    fresh.reuseLighting = false;
    for (const char* method : {"pyramid", "ltsm"}) {
        SCOPED_TRACE(method);
        // (The shared renderer may hold a view of a's first light already.)
        EXPECT_EQ(test::renderWith(a, fresh, method).stats.number("light_views_drawn"), 2);
        const FrameResult kept = test::renderWith(moved, opt, method);
        EXPECT_EQ(kept.stats.number("light_views_drawn"), 1);
        EXPECT_EQ(test::renderWith(moved, opt, method).stats.number("light_views_drawn"), 0);
        const FrameResult scratch = test::renderWith(moved, fresh, method);
        EXPECT_EQ(scratch.stats.number("light_views_drawn"), 2);
        EXPECT_EQ(scratch.radiosity.pixels, kept.radiosity.pixels);
        EXPECT_EQ(scratch.rgb8, kept.rgb8);
    }
}

// The views draw straight into the shadow map array's layers: a light added
// makes a new array, and every light's layer is drawn again (the others'
// views unchanged): the frame of a renderer that drew them all afresh.
TEST(Renderer, ALightAddedDrawsEveryShadowLayerAgain) {
    Scene a =
        test::sphereScene("skin1", {Light::Type::Point, glm::vec3(-8, 10, -6), glm::vec3(200.0f)});
    a.lights.push_back({Light::Type::Directional, glm::vec3(0.3f, -1, -0.5f), glm::vec3(0.5f)});
    Scene more = a;
    more.lights.push_back({Light::Type::Point, glm::vec3(9, -4, 8), glm::vec3(150.0f)});
    const RenderOptions opt = test::smallOptions(48, 256, 256);
    RenderOptions fresh = opt;
    fresh.reuseLighting = false;
    test::renderWith(a, opt, "pyramid");
    const FrameResult added = test::renderWith(more, opt, "pyramid");
    EXPECT_EQ(added.stats.number("light_views_drawn"), 1);
    const FrameResult scratch = test::renderWith(more, fresh, "pyramid");
    EXPECT_EQ(scratch.radiosity.pixels, added.radiosity.pixels);
    EXPECT_EQ(scratch.rgb8, added.rgb8);
}

// A mesh of enough triangles draws every other light view, and with the
// camera moving the composite's samples' G-buffer, on the GL worker's thread
// (gl/gl_worker.h): frames byte for byte those of a renderer without one, as
// the camera, then the lights, move.
TEST(Renderer, PassesOnTheGlWorkerGiveTheFramesOfOneThread) {
    Scene scene = test::torusScene("skin1", 10.0);
    scene.mesh.triangles.pop_back();  // open: no culling, every triangle set up
    ASSERT_GE(scene.mesh.triangles.size(), kWorkerMinTriangles);
    scene.lights.push_back({Light::Type::Directional, glm::vec3(0.6f, -0.4f, -1), glm::vec3(0.1f)});
    const RenderOptions opt = test::smallOptions(64, 256, 256);
    ::setenv("TSIS_GL_WORKER", "0", 1);
    Renderer serial;
    ::unsetenv("TSIS_GL_WORKER");
    Renderer threaded;
    Scene moved = scene;
    moved.camera.eye = glm::vec3(6, 4, 14);
    Scene relit = moved;
    relit.lights[0].vec = glm::vec3(12, 3, 8);  // both lights: both views drawn
    relit.lights[1].vec = glm::vec3(-0.6f, -0.4f, -1);
    int step = 0;
    for (const Scene* s : {&scene, &moved, &relit}) {
        SCOPED_TRACE(step++);
        const FrameResult a = serial.render(*s, opt), b = threaded.render(*s, opt);
        EXPECT_EQ(a.stats.number("light_views_on_worker"), 0);
        EXPECT_EQ(a.stats.number("samples_on_worker"), 0);
        EXPECT_EQ(b.stats.number("light_views_on_worker"), s == &moved ? 0 : 1);
        EXPECT_EQ(b.stats.number("samples_on_worker"), s == &relit ? 0 : 1);
        EXPECT_EQ(a.rgb8, b.rgb8);
    }
}

// A mesh over twice --light-lod triangles casts its shadows from a coarser
// copy (mesh/lod.h): the torus' thin top shadows its body as closely to the
// reference as the mesh's own shadows. A budget of half the mesh or more,
// and the views with maps (the light-view methods read positions from
// them), draw the mesh itself, to the bit.
TEST(Renderer, BigMeshCastsShadowsFromACoarserCopy) {
    const Scene scene = test::torusScene("marble", 50.0);
    const size_t triangles = scene.mesh.triangles.size();
    RenderOptions own = test::smallOptions(64, 256, 256);
    own.lightLodTriangles = 0;
    RenderOptions coarse = own;
    coarse.lightLodTriangles = static_cast<int>(triangles / 8);
    RenderOptions half = own;
    half.lightLodTriangles = static_cast<int>(triangles / 2);
    const FrameResult reference = test::renderWith(scene, own, "reference");
    const FrameResult a = test::renderWith(scene, own, "pyramid");
    EXPECT_EQ(a.stats.number("light_lod_triangles"), 0);
    const FrameResult b = test::renderWith(scene, coarse, "pyramid");
    EXPECT_GT(b.stats.number("light_lod_triangles"), 0.0);
    EXPECT_LT(b.stats.number("light_lod_triangles"), double(triangles) / 4);
    EXPECT_GT(b.stats.number("light_lod_mm"), 0.0);
    // The copy's shadows, not the mesh's view kept from the frame before.
    EXPECT_NE(b.radiosity.pixels, a.radiosity.pixels);
    const double errOwn = test::relativeRmse(a, reference);
    const double errCoarse = test::relativeRmse(b, reference);
    std::printf(
        "%zu triangles, copy %.0f (deviation %.4f mm): rel. RMSE vs reference %.4f -> %.4f\n",
        triangles, b.stats.number("light_lod_triangles"), b.stats.number("light_lod_mm"), errOwn,
        errCoarse);
    EXPECT_LT(errCoarse, errOwn + 0.002);
    EXPECT_EQ(test::renderWith(scene, half, "pyramid").radiosity.pixels, a.radiosity.pixels);
    EXPECT_EQ(test::renderWith(scene, coarse, "ltsm").radiosity.pixels,
              test::renderWith(scene, own, "ltsm").radiosity.pixels);
}

// Under a sky without a sun and a dark light, what ltsm and tsm give is the
// texture-space run over the residual's flux alone (design §12): the
// default method's B, to the bit, also right after a lit frame.
TEST(Renderer, LightViewMethodsUnderASunlessSkyAreTheResidualsRun) {
    const Scene lit =
        test::sphereScene("skin1", {Light::Type::Point, glm::vec3(-8, 10, -6), glm::vec3(200.0f)});
    Scene sky = lit;
    sky.lights[0].rgb = glm::vec3(0.0f);  // a frame needs a light: a dark one
    sky.env.map = splitEnvironment("white", 32, 16, 3, std::vector<float>(32 * 16 * 3, 0.3f));
    const RenderOptions opt = test::smallOptions(48, 256, 256);
    const FrameResult pyramid = test::renderWith(sky, opt, "pyramid");
    for (const char* method : {"ltsm", "tsm"}) {
        SCOPED_TRACE(method);
        test::renderWith(lit, opt, method);
        const FrameResult b = test::renderWith(sky, opt, method);
        EXPECT_EQ(b.radiosity.pixels, pyramid.radiosity.pixels);
    }
}

// Renderers of both GL platforms on one thread take turns (each frame makes
// its own context current) and one going away leaves the other drawing.
TEST(Renderer, RenderersOnOneThreadTakeTurns) {
    const Scene scene =
        test::sphereScene("skin1", {Light::Type::Point, glm::vec3(-8, 10, -6), glm::vec3(200.0f)});
    RenderOptions opt = test::smallOptions(48, 256, 256);
    opt.method = "pyramid";
    Renderer a("", "egl");
    const FrameResult first = a.render(scene, opt);
    {
        Renderer b("", "osmesa");
        EXPECT_EQ(b.render(scene, opt).rgb8, first.rgb8);
        EXPECT_EQ(a.render(scene, opt).rgb8, first.rgb8);
        EXPECT_EQ(b.render(scene, opt).rgb8, first.rgb8);
    }
    EXPECT_EQ(a.render(scene, opt).rgb8, first.rgb8);
}

// Light maps of 2048² only for objects many diffusion lengths across, where
// the shadow edges stay sharp in B; the frame reports the one it used.
TEST(Renderer, LightResolutionFollowsTheObjectsSizeInDiffusionLengths) {
    const Light light{Light::Type::Point, glm::vec3(-8, 10, -6), glm::vec3(200.0f)};
    Scene small = test::sphereScene("skin1", light);  // 10 mm box diagonal: ~8 of skin1's 1/σtr
    EXPECT_EQ(autoLightResolution(small), 1024);
    Scene large = test::sphereScene("ketchup", light);
    normalizeMesh(large.mesh, 80.0);  // a 46 mm sphere: ~117 of ketchup's blue 1/σtr
    EXPECT_EQ(autoLightResolution(large), 2048);
    RenderOptions opt = test::smallOptions(16, 64);
    opt.lightResolution = 0;
    EXPECT_EQ(test::renderWith(small, opt, "pyramid").stats.number("light_resolution"), 1024);
}

// A 256² atlas only where its texels are within 1/8 of the shortest mean
// free path and no map needs the atlas' detail; the frame reports the one
// it used.
TEST(Renderer, AtlasResolutionFollowsTheObjectsSizeInMeanFreePaths) {
    const Light light{Light::Type::Point, glm::vec3(-8, 10, -6), glm::vec3(200.0f)};
    Scene scene = test::sphereScene("marble", light);
    // marble's shortest mean free path 1/σt' is 0.33 mm (blue): a sphere of
    // area A takes 256² up to √A/256 = 0.33/8 mm, a box diagonal of 10.3 mm.
    normalizeMesh(scene.mesh, 9.0);
    EXPECT_EQ(autoAtlasResolution(scene, scene.mesh.surfaceArea()), 256);
    normalizeMesh(scene.mesh, 11.5);
    EXPECT_EQ(autoAtlasResolution(scene, scene.mesh.surfaceArea()), 512);
    normalizeMesh(scene.mesh, 9.0);
    // A file material of shorter mean free path than the scene's (cream, 0.14 mm).
    ObjectMaterial cream;
    cream.medium = presetMaterial("cream");
    scene.objectMaterials.push_back(cream);
    EXPECT_EQ(autoAtlasResolution(scene, scene.mesh.surfaceArea()), 512);
    scene.objectMaterials.back().medium = scene.material;
    EXPECT_EQ(autoAtlasResolution(scene, scene.mesh.surfaceArea()), 256);
    // Its albedo texture (or a surface map) keeps 512².
    scene.objectMaterials.back().texture = std::make_shared<AlbedoTexture>();
    EXPECT_EQ(autoAtlasResolution(scene, scene.mesh.surfaceArea()), 512);
    scene.objectMaterials.clear();
    RenderOptions opt = test::smallOptions(16, 64);
    opt.atlasResolution = 0;
    EXPECT_EQ(test::renderWith(scene, opt, "pyramid").stats.number("atlas_resolution"), 256);
}

}  // namespace
}  // namespace tsis
