// The public API (include/tsis/): options by name with the CLI's parsing and
// messages, scenes from options or arrays, and frames equal to the internal
// renderer's for the same options.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cli/args.h"
#include "cli/scene_options.h"
#include "render/renderer.h"
#include "support/error_of.h"
#include "tsis/tsis.h"

namespace tsis::api {
namespace {

using test::errorOf;

TEST(ApiOptions, SetReplacesAddsLightsAndReadsBack) {
    Options o{{"method", "tsis"}, {"samples", "64"}};
    o.set("samples", 128.0).set("light", "point:0,10,0:1,1,1").set("light", "dir:0,-1,0:1,1,1");
    o.set("no-specular", "true");
    EXPECT_EQ(o.get("samples"), "128");
    EXPECT_EQ(o.get("no-specular"), "true");
    EXPECT_EQ(o.get("width"), std::nullopt);
    EXPECT_EQ(o.args(), (std::vector<std::string>{"--method", "tsis", "--samples", "128", "--light",
                                                  "point:0,10,0:1,1,1", "--light",
                                                  "dir:0,-1,0:1,1,1", "--no-specular"}));
    o.set("no-specular", "false").unset("light").unset("method");
    EXPECT_EQ(o.args(), (std::vector<std::string>{"--samples", "128"}));
}

// The message is the CLI's for the same option, and a refused value leaves
// the options as they were.
TEST(ApiOptions, ErrorsAreTheClisAndLeaveTheOptions) {
    Options o{{"method", "tsis"}, {"samples", "64"}};
    auto cli = [](std::vector<std::string> argv) {
        argv.insert(argv.begin(), {"--method", "tsis"});
        return errorOf([&] { renderOptionsFromArgs(Args("render", sceneOptionSpecs(), argv)); });
    };
    EXPECT_EQ(errorOf([&] { o.set("samples", "0"); }), cli({"--samples", "0"}));
    EXPECT_EQ(errorOf([&] { o.set("method", "nope"); }), errorOf([&] {
                  renderOptionsFromArgs(
                      Args("render", sceneOptionSpecs(), {"--method", "nope", "--samples", "64"}));
              }));
    EXPECT_EQ(errorOf([&] { o.set("nope", "1"); }), cli({"--nope", "1"}));
    EXPECT_EQ(errorOf([&] { o.set("material", "nope"); }), errorOf([&] {
                  parseScene(Args("render", sceneOptionSpecs(), {"--material", "nope"}));
              }));
    EXPECT_NE(errorOf([&] { o.set("no-specular", "yes"); }), "(no error)");
    // A parameter the method does not read: the CLI's line naming its methods.
    EXPECT_EQ(errorOf([&] { o.set("pyramid-epsilon", "0.1"); }), cli({"--pyramid-epsilon", "0.1"}));
    EXPECT_EQ(o.args(), (std::vector<std::string>{"--method", "tsis", "--samples", "64"}));
}

TEST(ApiScene, FromOptionsAsTheCliMakesIt) {
    const Options o{{"mesh", "builtin:sphere"}, {"material", "marble"}, {"size-mm", "20"}};
    const Scene s(o);
    const tsis::Scene cli = sceneFromArgs(Args("render", sceneOptionSpecs(), o.args()));
    EXPECT_EQ(s.triangleCount(), cli.mesh.triangles.size());
    EXPECT_EQ(s.material().name, "marble");
    EXPECT_EQ(s.material().sigmaA[0], static_cast<float>(cli.material.sigmaA.x));
    ASSERT_EQ(s.lights().size(), cli.lights.size());
    EXPECT_EQ(s.lights()[1].directional, true);
    EXPECT_EQ(s.camera().eye[2], cli.camera.eye.z);
    EXPECT_EQ(s.camera().fovYDegrees, 35.0f);
}

TEST(ApiScene, SettersCheckAsTheCliAndKeepTheSceneOnError) {
    Scene s(Options{{"mesh", "builtin:sphere"}});
    Material m = presetMaterial("skin1");
    m.sigmaA[1] = -1;
    EXPECT_NE(errorOf([&] { s.setMaterial(m); }).find("negative"), std::string::npos);
    EXPECT_EQ(s.material().name, "skin1");
    Camera c = s.camera();
    c.target = c.eye;
    EXPECT_EQ(errorOf([&] { s.setCamera(c); }), "--eye and --target are the same point");
    EXPECT_EQ(errorOf([&] {
                  s.setLights({{false, {0, 1, 0}, {-1, 1, 1}}});
              }),
              "--light 'point:0,1,0:-1,1,1': negative intensity");
    EXPECT_EQ(errorOf([&] { s.setLights(std::vector<Light>(kMaxLights + 1)); }).find("too many"),
              0u);
    EXPECT_EQ(s.lights().size(), 2u);
    s.setLights({{true, {0, -1, 0}, {2, 2, 2}}});
    ASSERT_EQ(s.lights().size(), 1u);
    EXPECT_EQ(s.lights()[0].rgb[0], 2.0f);
    m.sigmaA[1] = 0.5f;
    s.setMaterial(m);
    EXPECT_EQ(s.material().sigmaA[1], 0.5f);
}

// --env flows through the options as on the command line; its sun is the
// map's, kept when the lights are set and not listed among them.
TEST(ApiScene, EnvironmentIsAnOptionAndItsSunStaysWithNewLights) {
    const std::string sky = std::string(TSIS_SOURCE_DIR) + "/data/env/sky.hdr";
    Scene s(Options{{"mesh", "builtin:sphere"}, {"env", sky}, {"env-rotate", "45"}});
    EXPECT_TRUE(s.lights().empty());
    s.setLights({{true, {0, -1, 0}, {2, 2, 2}}});
    ASSERT_EQ(s.lights().size(), 1u);
    EXPECT_NE(errorOf([] {
                  Scene(Options{{"env", "/nonexistent.exr"}});
              }).find("no such file"),
              std::string::npos);
}

TEST(ApiScene, FromArraysNormalisesAndRefusesBadIndices) {
    // A tetrahedron, counter-clockwise from outside.
    const std::vector<float> v = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    const std::vector<uint32_t> t = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    const Scene s = Scene::fromArrays(v, t, Options{{"size-mm", "5"}}, "tet");
    EXPECT_EQ(s.meshName(), "tet");
    EXPECT_EQ(s.triangleCount(), 4u);
    EXPECT_EQ(errorOf(
                  [&] {
                      Scene::fromArrays(v, {0, 1, 9});
                  },
                  "arrays"),
              "mesh 'arrays': triangle 0 uses vertex 9 but there are only 4 vertices");
    EXPECT_NE(errorOf([&] {
                  Scene::fromArrays({0, 0}, t);
              }).find("multiple of 3"),
              std::string::npos);
}

// The facade adds nothing to a frame: the same bytes as the internal renderer
// given the options `tsis render` would parse.
TEST(ApiRenderer, FrameEqualsTheInternalRenderersAndComparesToItself) {
    const Options o{{"mesh", "builtin:sphere"}, {"width", "48"},      {"height", "32"},
                    {"atlas-res", "128"},       {"light-res", "256"}, {"method", "tsis"},
                    {"samples", "64"}};
    Renderer renderer;
    const Frame f = renderer.render(Scene(o), o);
    const Args args("render", sceneOptionSpecs(), o.args());
    tsis::Renderer internal;
    const FrameResult r = internal.render(sceneFromArgs(args), renderOptionsFromArgs(args));
    EXPECT_EQ(f.width, 48);
    EXPECT_EQ(f.rgb8, r.rgb8);
    EXPECT_EQ(f.radiance.width, 48);
    EXPECT_EQ(f.radiance.channels, 3);
    EXPECT_EQ(f.coverage.channels, 1);
    EXPECT_EQ(f.fluxAtlas.width, 128);
    EXPECT_NE(f.statsJson.find("\"ms\""), std::string::npos);
    const Metrics same = compare(f.radiance, f.radiance, &f.coverage);
    EXPECT_EQ(same.rmse, 0);
    EXPECT_TRUE(std::isinf(same.psnr));
    EXPECT_GT(same.pixels, 0);
    EXPECT_EQ(same.nonfiniteImage + same.nonfiniteReference, 0);
    EXPECT_NE(errorOf([&] { compare(f.radiance, f.coverage); }), "(no error)");
    // A NaN pixel is counted and left out, as `tsis compare` does.
    Image nan = f.radiance;
    const size_t covered =
        static_cast<size_t>(std::find_if(f.coverage.pixels.begin(), f.coverage.pixels.end(),
                                         [](float c) { return c > 0.5f; }) -
                            f.coverage.pixels.begin());
    nan.pixels[covered * 3] = std::nanf("");
    const Metrics withNan = compare(nan, f.radiance, &f.coverage);
    EXPECT_EQ(withNan.nonfiniteImage, 1);
    EXPECT_EQ(withNan.pixels, same.pixels - 1);
}

}  // namespace
}  // namespace tsis::api
