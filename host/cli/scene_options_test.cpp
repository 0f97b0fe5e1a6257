#include "cli/scene_options.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "render/frame_keys.h"
#include "render/method.h"
#include "render/render_params.h"
#include "util/error.h"

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
    o.rpBound = 1.0 / 3.0;

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
    EXPECT_EQ(b.rpBound, o.rpBound);
}

// Every parameter of every method that reads it (and every frame-wide one),
// set to a value other than its default: printed, parsed back, the same values
// and the same frame keys.
TEST(SceneOptions, EveryParameterRoundTripsForEveryMethod) {
    const Scene scene = parseScene(parse({}));
    int rows = 0;
    for (const std::string& method : methodNames()) {
        for (const RenderParam& p : renderParams()) {
            if (!p.usedBy(method)) continue;
            RenderOptions o;
            o.method = method;
            p.set(o, p.example);
            ASSERT_FALSE(p.isDefault(o)) << p.name << " " << p.example;
            std::vector<std::string> argv = renderOptionArgs(o);
            EXPECT_NE(std::find(argv.begin(), argv.end(), "--" + p.name), argv.end()) << p.name;
            const RenderOptions b = renderOptionsFromArgs(parse(argv));
            EXPECT_EQ(b.method, method);
            for (const RenderParam& q : renderParams())
                EXPECT_EQ(q.text(b), q.text(o)) << method << " --" << p.name << ": --" << q.name;
            const uint64_t lighting = lightingKey(scene, o, 1);
            EXPECT_EQ(lightingKey(scene, b, 1), lighting) << method << " --" << p.name;
            EXPECT_EQ(accumulationKey(scene, b, lighting), accumulationKey(scene, o, lighting))
                << method << " --" << p.name;
            // A parameter that changes the pixels changes its key; others none.
            const RenderOptions d = [&] {
                RenderOptions r;
                r.method = method;
                return r;
            }();
            const bool lightingMoved = lightingKey(scene, d, 1) != lighting;
            const bool accumulationMoved =
                accumulationKey(scene, d, lighting) != accumulationKey(scene, o, lighting);
            EXPECT_EQ(lightingMoved, p.effect == ParamEffect::Lighting) << p.name;
            EXPECT_EQ(accumulationMoved, p.effect == ParamEffect::Radiosity) << p.name;
            ++rows;
        }
    }
    EXPECT_GT(rows, static_cast<int>(renderParams().size()));
}

// A parameter the chosen method does not read is an error naming the methods
// that do; every method the table names is registered.
TEST(SceneOptions, ForeignParameterNamesItsMethods) {
    const std::vector<std::string> names = methodNames();
    for (const RenderParam& p : renderParams()) {
        for (const std::string& m : p.methods)
            EXPECT_NE(std::find(names.begin(), names.end(), m), names.end()) << p.name << ": " << m;
        for (const std::string& method : names) {
            if (p.usedBy(method)) continue;
            std::vector<std::string> argv = {"--method", method, "--" + p.name};
            if (!p.flag) argv.push_back(p.example);
            try {
                renderOptionsFromArgs(parse(argv));
                ADD_FAILURE() << "--" << p.name << " accepted by " << method;
            } catch (const Error& e) {
                EXPECT_EQ(std::string(e.what()), foreignParamMessage(p, method));
            }
        }
    }
    EXPECT_EQ(foreignParamMessage(*findRenderParam("mis-distance"), "pyramid"),
              "--mis-distance is a parameter of mis, not of pyramid");
    EXPECT_EQ(foreignParamMessage(*findRenderParam("ltsm-rings"), "tsis"),
              "--ltsm-rings is a parameter of ltsm and hybrid, not of tsis");
    EXPECT_EQ(foreignParamMessage(*findRenderParam("width"), "tsm"), "");
}

TEST(SceneOptions, ValuesOutsideTheirRangeAreRefused) {
    auto refused = [](const std::vector<std::string>& argv, const std::string& expect) {
        try {
            renderOptionsFromArgs(parse(argv));
            ADD_FAILURE() << expect;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(expect), std::string::npos) << e.what();
        }
    };
    refused({"--atlas-res", "1000"}, "--atlas-res 1000 must be a power of two from 16 to 4096");
    refused({"--atlas-res", "8192"}, "power of two");
    refused({"--light-res", "8"}, "--light-res 8 is out of range [16, 8192] (0: automatic)");
    refused({"--light-lod", "999"}, "--light-lod 999 is out of range [1000, 1073741824] (0: off)");
    refused({"--method", "volumetric", "--spp", "0"}, "--spp 0 is out of range");
    refused({"--method", "tsis", "--samples", "x"}, "--samples");
    refused({"--method", "tsis", "--rd-part", "middle"}, "--rd-part 'middle'");
    EXPECT_EQ(renderOptionsFromArgs(parse({"--light-res", "0"})).lightResolution, 0);
    // The atlas the mesh gets and the renderer's read the one row.
    EXPECT_EQ(meshOptionsFromArgs(parse({"--atlas-res", "128"})).atlas.resolution, 128);
    EXPECT_THROW(meshOptionsFromArgs(parse({"--atlas-res", "100"})), Error);
    // A struct filled in code goes through the same rows.
    RenderOptions o;
    o.samples = 0;
    EXPECT_THROW(validateRenderOptions(o), Error);
    o = RenderOptions();
    o.spp = 0;  // the default (automatic) though not typeable
    EXPECT_NO_THROW(validateRenderOptions(o));
}

TEST(SceneOptions, MeshOptionsParsePrintAndRefuse) {
    const MeshOptions d = meshOptionsFromArgs(parse({}));
    EXPECT_EQ(d.rotateDegrees, glm::dvec3(0.0));
    EXPECT_FALSE(d.zUp);
    EXPECT_EQ(d.creaseDegrees, kDefaultCreaseDegrees);
    EXPECT_EQ(meshOptionArgs(d), (std::vector<std::string>{"--atlas", "auto"}));

    const std::vector<std::string> argv = {"--rotate", "90,-12.5,0.1", "--mesh-up", "z",
                                           "--crease", "45",           "--atlas",   "build"};
    const MeshOptions o = meshOptionsFromArgs(parse(argv));
    EXPECT_EQ(o.rotateDegrees, glm::dvec3(90, -12.5, 0.1));
    EXPECT_TRUE(o.zUp);
    EXPECT_EQ(o.creaseDegrees, 45.0);
    EXPECT_EQ(meshOptionArgs(o), argv);  // printed as given, and parsed back the same
    EXPECT_EQ(meshOptionsFromArgs(parse({"--crease", "0"})).creaseDegrees, 0.0);
    EXPECT_EQ(meshOptionsFromArgs(parse({"--crease", "180"})).creaseDegrees, 180.0);

    // One line each, and parseScene (the options checked before the mesh) says it.
    auto refused = [](const std::vector<std::string>& argv, const std::string& expect) {
        try {
            parseScene(parse(argv));
            ADD_FAILURE() << expect;
        } catch (const Error& e) {
            EXPECT_EQ(std::string(e.what()), expect);
        }
    };
    refused({"--crease", "nan"}, "--crease: 'nan' is not a finite number");
    refused({"--crease", "-1"}, "--crease -1 is out of range [0, 180]");
    refused({"--crease", "180.5"}, "--crease 180.5 is out of range [0, 180]");
    refused({"--rotate", "90,0"}, "--rotate: '90,0' needs three numbers X,Y,Z");
    refused({"--rotate", "0,inf,0"}, "--rotate: 'inf' is not a finite number");
    refused({"--rotate", "0,0,361"}, "--rotate 0,0,361: each angle must be within [-360, 360]");
    refused({"--mesh-up", "x"}, "--mesh-up 'x': expected y or z");
    refused({"--up", "z"}, "--up z: --up is the camera's X,Y,Z; the mesh's up axis is --mesh-up z");
}

}  // namespace
}  // namespace tsis
