#include "cli/scene_options.h"

#include <gtest/gtest.h>

namespace tsis {
namespace {

// Every option tsis render takes (scene and rendering).
Args parse(const std::vector<std::string>& argv) {
    return Args("render", sceneOptionSpecs(), argv);
}

TEST(SceneOptions, PrintedArgsParseBackExactly) {
    Scene scene = parseScene(parse({}));
    scene.material = presetMaterial("marble");
    scene.material.sigmaA.y = 0.1 / 3.0;  // not a short decimal
    scene.lights[0].vec = glm::vec3(1.0f / 3.0f, -2e-7f, 12345.678f);
    scene.lights[0].rgb = glm::vec3(0.1f);
    scene.camera.eye = glm::vec3(-6.609295f, 4.0936191f, 15.632452f);
    scene.camera.fovYDegrees = 27.5f;
    RenderOptions o;
    o.method = "hybrid";
    o.width = 320;
    o.samples = 77;
    o.seed = 9;
    o.atlasResolution = 256;
    o.lightResolution = 2048;
    o.key = 0.3f;
    o.rpBound = 0.07;
    o.rpK = 2.25;
    o.ltsmRings = 3;
    o.pyramidEpsilon = 0.01f;
    o.spacingMm = 0.125;
    o.specular = false;

    std::vector<std::string> argv = sceneArgs(scene, "builtin:sphere", 12.5);
    for (const std::string& a : renderOptionArgs(o)) argv.push_back(a);
    const Args args = parse(argv);
    EXPECT_EQ(args.getString("mesh", ""), "builtin:sphere");
    EXPECT_EQ(args.getDouble("size-mm", 0, 0, 1e9), 12.5);
    const Scene back = parseScene(args);
    EXPECT_EQ(back.material.name, "custom");  // the σ given override the preset's
    EXPECT_EQ(back.material.sigmaSPrime, scene.material.sigmaSPrime);
    EXPECT_EQ(back.material.sigmaA, scene.material.sigmaA);
    EXPECT_EQ(back.material.eta, scene.material.eta);
    ASSERT_EQ(back.lights.size(), scene.lights.size());
    for (size_t i = 0; i < back.lights.size(); ++i) {
        EXPECT_EQ(back.lights[i].type, scene.lights[i].type);
        EXPECT_EQ(back.lights[i].vec, scene.lights[i].vec);
        EXPECT_EQ(back.lights[i].rgb, scene.lights[i].rgb);
    }
    EXPECT_EQ(back.camera.eye, scene.camera.eye);
    EXPECT_EQ(back.camera.target, scene.camera.target);
    EXPECT_EQ(back.camera.up, scene.camera.up);
    EXPECT_EQ(back.camera.fovYDegrees, scene.camera.fovYDegrees);
    const RenderOptions b = renderOptionsFromArgs(args);
    EXPECT_EQ(b.method, o.method);
    EXPECT_EQ(b.width, o.width);
    EXPECT_EQ(b.height, o.height);
    EXPECT_EQ(b.samples, o.samples);
    EXPECT_EQ(b.seed, o.seed);
    EXPECT_EQ(b.atlasResolution, o.atlasResolution);
    EXPECT_EQ(b.lightResolution, o.lightResolution);
    EXPECT_EQ(b.key, o.key);
    EXPECT_EQ(b.rpBound, o.rpBound);
    EXPECT_EQ(b.rpK, o.rpK);
    EXPECT_EQ(b.ltsmRings, o.ltsmRings);
    EXPECT_EQ(b.pyramidEpsilon, o.pyramidEpsilon);
    EXPECT_EQ(b.spacingMm, o.spacingMm);
    EXPECT_EQ(b.specular, o.specular);
    EXPECT_EQ(b.reuseLighting, o.reuseLighting);
}

}  // namespace
}  // namespace tsis
