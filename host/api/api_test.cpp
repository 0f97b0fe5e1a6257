// The public API (include/tsis/): options by name with the CLI's parsing and
// messages, scenes from options or arrays, and frames equal to the internal
// renderer's for the same options.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "description/scene_params.h"
#include "image/image_io.h"
#include "render/render_params.h"
#include "render/renderer.h"
#include "support/boxes.h"
#include "support/error_of.h"
#include "support/scratch_dir.h"
#include "tsis/tsis.h"
#include "util/args.h"

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
    EXPECT_EQ(s.material()->name, "marble");
    EXPECT_EQ(s.material()->sigmaA[0], static_cast<float>(cli.material.sigmaA.x));
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
    EXPECT_EQ(s.material()->name, "skin1");
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
    EXPECT_EQ(s.material()->sigmaA[1], 0.5f);
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

// The options split as the command line's are: the scene's to Scene, the
// frame's to Renderer::render, and one given to the other is an error, not
// an option that does nothing.
TEST(ApiOptions, SceneAndRenderOptionsEachGoWhereTheyAct) {
    Options o{{"mesh", "builtin:sphere"}, {"method", "tsis"},   {"material", "marble"},
              {"samples", "64"},          {"atlas-res", "128"}, {"gl", "osmesa"}};
    EXPECT_EQ(o.sceneOptions().args(),
              (std::vector<std::string>{"--mesh", "builtin:sphere", "--material", "marble",
                                        "--atlas-res", "128"}));
    EXPECT_EQ(o.renderOptions().args(), (std::vector<std::string>{"--method", "tsis", "--samples",
                                                                  "64", "--atlas-res", "128"}));
    EXPECT_EQ(errorOf([&] { Scene{o}; }),
              "Scene: option --gl is the Renderer's: give it when making one");
    o.unset("gl");
    EXPECT_EQ(errorOf([&] { Scene{o}; }),
              "Scene: option --method is not the scene's: give it to Renderer::render");
    Renderer r;
    const Scene s(o.sceneOptions());
    EXPECT_EQ(errorOf([&] { r.render(s, o.sceneOptions()); }),
              "Renderer::render: option --mesh is the scene's: set it on the Scene");
    // Albedo and mean free path in either order: each value is checked when
    // set, the pair where the scene is made.
    Options a, b;
    a.set("albedo", "0.8,0.6,0.5").set("mfp", "3,1.5,0.8");
    b.set("mfp", "3,1.5,0.8").set("albedo", "0.8,0.6,0.5");
    EXPECT_EQ(Scene(a).material()->sigmaA, Scene(b).material()->sigmaA);
    EXPECT_NE(errorOf([] {
                  Scene(Options{{"albedo", "0.8,0.6,0.5"}});
              }).find("--mfp"),
              std::string::npos);
}

// A material given by albedo + mean free path stays so: each frame inverts it
// through its own --profile, as `tsis render --profile P` does, whatever the
// scene was made under.
TEST(ApiScene, AlbedoAndMfpAreInvertedThroughTheFramesProfile) {
    const Options scene{
        {"mesh", "builtin:sphere"}, {"albedo", "0.8,0.6,0.5"}, {"mfp", "3,1.5,0.8"}};
    const Options frame{{"width", "40"},      {"height", "32"},   {"atlas-res", "128"},
                        {"light-res", "256"}, {"method", "tsis"}, {"samples", "64"},
                        {"profile", "pbd"}};
    const Scene s(scene);
    ASSERT_TRUE(s.material()->albedo.has_value());
    EXPECT_EQ((*s.material()->albedo)[0], 0.8f);
    std::vector<std::string> argv = scene.args();
    argv.insert(argv.end(), frame.args().begin(), frame.args().end());
    const Args args("render", sceneOptionSpecs(), argv);
    Renderer api;
    tsis::Renderer internal;
    const std::vector<uint8_t> pbd = api.render(s, frame).rgb8;
    EXPECT_EQ(pbd, internal.render(sceneFromArgs(args), renderOptionsFromArgs(args)).rgb8);
    Options dipole = frame;
    dipole.set("profile", "dipole");
    EXPECT_NE(api.render(s, dipole).rgb8, pbd);  // not the σ of the default's inversion
}

// A file's materials stay the file's (material() has none to show), are
// listed by materials(), and options() makes the same scene again; a set
// material replaces them all, as --material does.
TEST(ApiScene, FileMaterialsStayTheFilesAndOptionsReplayTheScene) {
    const tsis::test::ScratchDir dir;
    std::ofstream(dir.file("cubes.obj")) << tsis::test::twoCubesObj();
    std::ofstream(dir.file("cubes.mtl"))
        << "newmtl textured\nKd 0.8 0.6 0.5\nnewmtl plain\nKd 0.3 0.3 0.3\nNi 1.3\n";
    Scene s(Options{{"mesh", dir.file("cubes.obj")}, {"size-mm", "30"}});
    EXPECT_FALSE(s.material().has_value());
    const std::vector<Material> file = s.materials();
    ASSERT_EQ(file.size(), 2u);
    EXPECT_EQ(file[0].name, "textured");
    EXPECT_EQ(file[1].name, "plain");
    EXPECT_FLOAT_EQ(file[1].eta, 1.3f);
    const Options frame{
        {"width", "40"}, {"height", "32"}, {"atlas-res", "128"}, {"light-res", "256"}};
    Renderer r;
    const std::vector<uint8_t> first = r.render(s, frame).rgb8;
    EXPECT_EQ(r.render(Scene(s.options()), frame).rgb8, first);
    s.setMaterial(Material::preset("marble"));
    EXPECT_EQ(s.material()->name, "marble");
    EXPECT_EQ(s.materials().size(), 1u);
    EXPECT_NE(r.render(s, frame).rgb8, first);
    EXPECT_EQ(r.render(Scene(s.options()), frame).rgb8, r.render(s, frame).rgb8);
}

// Mean red radiance of the covered pixels whose x position is beyond `x`
// on the side of `sign`, and how many there were.
std::pair<double, int> sideMean(const Frame& f, float x, float sign) {
    double sum = 0;
    int n = 0;
    for (int k = 0; k < f.width * f.height; ++k) {
        if (!(f.coverage.pixels[k] > 0.5f)) continue;
        if (sign * (f.position.pixels[3 * k] - x) <= 0) continue;
        sum += f.radiance.pixels[3 * k];
        ++n;
    }
    return {n ? sum / n : 0.0, n};
}

// A scene of objects: each stands where its transform puts it and scatters
// in its own material (a change of one object's material changes its pixels
// alone: no light crosses between media), each error names its object, and
// one object of arrays is fromArrays' scene.
TEST(ApiScene, ObjectsStandWhereTheyArePutAndScatterInTheirOwnMaterials) {
    const Options frame{
        {"width", "64"}, {"height", "32"}, {"atlas-res", "256"}, {"light-res", "256"}};
    auto objects = [](const char* right) {
        std::vector<Object> o(2);
        o[0].mesh = o[1].mesh = "builtin:sphere";
        o[0].transform.translateMm = {-3, 0, 0};
        o[1].transform = {1.5f, {0, 90, 0}, {3, 0, 0}};
        o[0].material = Material::preset("marble");
        o[1].material = Material::preset(right);
        return o;
    };
    const Options scene{{"size-mm", "file"}, {"light", "dir:0,0,-1:1,1,1"}, {"eye", "0,0,12"}};
    const Scene same = Scene::fromObjects(objects("marble"), scene);
    const Scene other = Scene::fromObjects(objects("ketchup"), scene);
    ASSERT_EQ(other.materials().size(), 2u);
    EXPECT_EQ(other.materials()[1].name, "object 1");
    EXPECT_EQ(other.objects().size(), 2u);
    Renderer r;
    const Frame a = r.render(same, frame), b = r.render(other, frame);
    // The left sphere (radius 1 mm at x = −3) and the right one (1.5 mm at x = +3).
    const auto [leftA, nLeft] = sideMean(a, -1.5f, -1);
    const auto [leftB, nLeftB] = sideMean(b, -1.5f, -1);
    const auto [rightA, nRight] = sideMean(a, 1.0f, 1);
    const auto [rightB, nRightB] = sideMean(b, 1.0f, 1);
    std::printf("left %.5f / %.5f (%d px), right %.5f / %.5f (%d px)\n", leftA, leftB, nLeft,
                rightA, rightB, nRight);
    EXPECT_GT(nLeft, 20);
    EXPECT_GT(nRight, 2 * nLeft);  // 1.5× the radius: 2.25× the pixels
    EXPECT_EQ(nLeftB, nLeft);
    EXPECT_EQ(nRightB, nRight);
    EXPECT_NEAR(leftB / leftA, 1.0, 0.03);
    EXPECT_GT(std::abs(rightB / rightA - 1.0), 0.1);
    // Errors name the object.
    std::vector<Object> bad = objects("marble");
    bad[1].transform.scale = -1;
    EXPECT_EQ(errorOf([&] { Scene::fromObjects(bad); }),
              "object 1 (builtin:sphere): scale -1 must be positive");
    bad[1].transform.scale = 1;
    bad[1].vertices = {0, 0, 0};
    EXPECT_EQ(errorOf([&] { Scene::fromObjects(bad); }),
              "object 1: a mesh file and arrays: give one");
    EXPECT_NE(errorOf([] { Scene::fromObjects({}); }).find("at least one object"),
              std::string::npos);
    // One object of arrays: the scene fromArrays makes.
    const std::vector<float> v = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    const std::vector<uint32_t> t = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    Object tet;
    tet.vertices = v;
    tet.triangles = t;
    EXPECT_EQ(r.render(Scene::fromObjects({tet}), frame).rgb8,
              r.render(Scene::fromArrays(v, t, {}, "object 0"), frame).rgb8);
}

// A volumetric frame split into batches of passes (--spp-offset) merges,
// as the spp-weighted mean of their radiance, into the whole frame's: to
// float rounding, for both estimators (tsis.distributed.render_split).
TEST(ApiRenderer, VolumetricBatchesMergeIntoTheWholeFrame) {
    const Scene s(Options{{"mesh", "builtin:sphere"}, {"material", "marble"}});
    Renderer r;
    for (const char* estimator : {"camera", "light"}) {
        SCOPED_TRACE(estimator);
        Options o{{"width", "24"},
                  {"height", "24"},
                  {"method", "volumetric"},
                  {"estimator", estimator},
                  {"seed", "7"}};
        o.set("spp", "6");
        const Image whole = r.render(s, o).radiance;
        std::vector<double> merged(whole.pixels.size(), 0.0);
        for (const auto& [offset, spp] : {std::pair{0, 1}, std::pair{1, 3}, std::pair{4, 2}}) {
            o.set("spp", spp).set("spp-offset", offset);
            const Image part = r.render(s, o).radiance;
            for (size_t k = 0; k < merged.size(); ++k) merged[k] += part.pixels[k] * spp / 6.0;
        }
        double worst = 0, mean = 0;
        for (size_t k = 0; k < merged.size(); ++k) {
            worst = std::max(worst, std::abs(merged[k] - whole.pixels[k]));
            mean += whole.pixels[k] / static_cast<double>(merged.size());
        }
        std::printf("%s: largest difference %.3g, mean radiance %.3g\n", estimator, worst, mean);
        EXPECT_GT(mean, 0.0);
        EXPECT_LE(worst, 1e-5 * std::max(mean, 1e-3)) << "mean " << mean;
        // Other seeds' passes are other pictures: the check can fail.
        o.set("spp", "6").set("spp-offset", "6");
        EXPECT_NE(r.render(s, o).radiance.pixels, whole.pixels);
    }
}

// An object's material with an albedo texture: the texture shows through
// the object's own texture coordinates (left half red, right half blue).
TEST(ApiScene, AnObjectsMaterialCarriesItsAlbedoTexture) {
    const tsis::test::ScratchDir dir;
    std::ofstream(dir.file("quad.obj"))
        << "v -5 -5 0\nv 5 -5 0\nv 5 5 0\nv -5 5 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
           "f 1/1 2/2 3/3 4/4\n";
    writeImage8(dir.file("halves.png"), 2, 1, 3, {220, 40, 40, 40, 40, 220});
    Object quad;
    quad.mesh = dir.file("quad.obj");
    Material m;
    m.albedo = Vec3{1, 1, 1};
    m.mfpMm = Vec3{0.5f, 0.5f, 0.5f};
    m.albedoTexture = dir.file("halves.png");
    quad.material = m;
    const Scene s = Scene::fromObjects(
        {quad}, Options{{"size-mm", "file"}, {"light", "dir:0,0,-1:1,1,1"}, {"eye", "0,0,30"}});
    const Frame f = Renderer().render(s, Options{{"width", "64"}, {"height", "64"}});
    double red[2] = {0, 0}, blue[2] = {0, 0};
    for (int k = 0; k < f.width * f.height; ++k) {
        const float x = f.position.pixels[3 * k];
        if (!(f.coverage.pixels[k] > 0.5f) || std::abs(x) < 1 || std::abs(x) > 4) continue;
        red[x > 0] += f.radiance.pixels[3 * k];
        blue[x > 0] += f.radiance.pixels[3 * k + 2];
    }
    EXPECT_GT(red[0], 2 * blue[0]);
    EXPECT_GT(blue[1], 2 * red[1]);
    quad.material->albedoTexture.clear();
    quad.mesh.clear();
    quad.vertices = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    quad.triangles = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    quad.material->albedoTexture = dir.file("halves.png");
    EXPECT_EQ(errorOf([&] { Scene::fromObjects({quad}); }),
              "object 0: an albedo texture needs texture coordinates (the mesh has none)");
}

// An environment given as pixels lights the scene as the same map read from
// its file does, and reads back with its pixels.
TEST(ApiScene, AnEnvironmentOfPixelsIsTheMapOfItsFile) {
    const std::string sky = std::string(TSIS_SOURCE_DIR) + "/data/env/sky.hdr";
    const Image map = readImage(sky);
    ASSERT_EQ(map.channels, 3);
    Scene file(Options{{"mesh", "builtin:sphere"}});
    Scene pixels = file;
    file.setEnvironment(Environment{sky, 2.0, 30.0, {}, 0, 0});
    pixels.setEnvironment(Environment{"", 2.0, 30.0, map.pixels, map.width, map.height});
    EXPECT_EQ(pixels.environment()->pixels.size(), map.pixels.size());
    const Options frame{
        {"width", "32"}, {"height", "32"}, {"atlas-res", "128"}, {"light-res", "256"}};
    Renderer r;
    EXPECT_EQ(r.render(file, frame).rgb8, r.render(pixels, frame).rgb8);
    Environment bad{"", 1.0, 0.0, {1, 2, 3}, 2, 1};
    EXPECT_EQ(errorOf([&] { pixels.setEnvironment(bad); }),
              "Environment: 3 values for 2×1 RGB pixels");
}

// The facade adds nothing to a frame: the same bytes as the internal renderer
// given the options `tsis render` would parse.
TEST(ApiRenderer, FrameEqualsTheInternalRenderersAndComparesToItself) {
    const Options o{{"mesh", "builtin:sphere"}, {"width", "48"},      {"height", "32"},
                    {"atlas-res", "128"},       {"light-res", "256"}, {"method", "tsis"},
                    {"samples", "64"}};
    Renderer renderer;
    const Frame f = renderer.render(Scene(o.sceneOptions()), o.renderOptions());
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

// Typed settings are the options by name: every parameter's example value
// set on RenderSettings comes back through Options::of and renderSettings()
// (the table's text of each field equal), and a frame from settings is the
// frame from the same options.
TEST(ApiRenderSettings, EveryParameterIsTheOptionOfItsName) {
    for (const RenderParam& p : renderParams()) {
        RenderSettings s;
        s.method = p.methods.empty() ? "pyramid" : p.methods.front();
        p.set(s, p.flag ? "1" : p.example);
        ASSERT_FALSE(p.isDefault(s)) << p.name;
        const Options o = Options::of(s);
        EXPECT_EQ(o.get(p.name).has_value(), true) << p.name;
        const RenderSettings back = o.renderSettings();
        EXPECT_EQ(back.method, s.method) << p.name;
        for (const RenderParam& q : renderParams())
            EXPECT_EQ(q.text(back), q.text(s)) << p.name << " changed " << q.name;
    }
    EXPECT_EQ(Options::of(RenderSettings{}).args(),
              (std::vector<std::string>{"--method", "pyramid"}));

    const Options o{{"mesh", "builtin:sphere"}, {"width", "40"},      {"height", "32"},
                    {"atlas-res", "128"},       {"light-res", "256"}, {"method", "tsis"},
                    {"samples", "64"},          {"exposure", "2.5"}};
    const Scene scene(o.sceneOptions());
    RenderSettings typed;
    typed.method = "tsis";
    typed.width = 40;
    typed.height = 32;
    typed.atlasResolution = 128;
    typed.lightResolution = 256;
    typed.samples = 64;
    typed.exposure = 2.5f;
    Renderer renderer;
    EXPECT_EQ(renderer.render(scene, typed).rgb8, renderer.render(scene, o.renderOptions()).rgb8);
}

// Each field by its option's name: set as typed, read back as typed, checked
// as the command line checks it; the rows are the table's.
TEST(ApiRenderSettings, FieldsByTheirOptionsName) {
    ASSERT_EQ(RenderSettings::parameters().size(), renderParams().size());
    for (const RenderParameter& p : RenderSettings::parameters()) {
        const RenderParam& row = *findRenderParam(p.name);
        RenderSettings s;
        const std::string value = row.flag ? "true" : row.example;
        s.set(p.name, value);
        EXPECT_EQ(s.get(p.name), value) << p.name;
        EXPECT_FALSE(row.isDefault(s)) << p.name;
        EXPECT_EQ(p.kind == RenderParameter::Kind::Flag, row.flag) << p.name;
        EXPECT_EQ(p.help.find("  "), std::string::npos) << p.name;  // no metavar
    }
    RenderSettings s;
    s.set("no-specular", "true");
    EXPECT_FALSE(s.specular);
    s.set("no-specular", "false");
    EXPECT_TRUE(s.specular);
    s.set("tone", "aces");
    EXPECT_EQ(s.tone, ToneCurve::Aces);
    s.set("roughness", "file");
    EXPECT_EQ(s.get("roughness"), "file");
    s.set("method", "mis");
    EXPECT_EQ(s.get("method"), "mis");
    EXPECT_EQ(errorOf([&] { s.set("method", "nope"); }).substr(0, 22), "unknown method 'nope';");
    EXPECT_EQ(errorOf([&] { s.set("width", "-3"); }), "--width -3 is out of range [1, 8192]");
    EXPECT_EQ(errorOf([&] { s.set("no-specular", "yes"); }),
              "option --no-specular is a flag: true or false, not 'yes'");
    EXPECT_EQ(errorOf([&] { s.set("mesh", "x.obj"); }),
              "RenderSettings: no render option --mesh (see tsis render --help)");
    EXPECT_EQ(s.method, "mis");
    EXPECT_EQ(s.width, 512);
    EXPECT_EQ(s.tone, ToneCurve::Aces);
}

// What the command line refuses, typed settings refuse with its message: a
// value out of range, a field the method does not read, an unknown method.
TEST(ApiRenderSettings, RefusesWhatTheCommandLineRefuses) {
    const Scene scene(Options{{"mesh", "builtin:sphere"}});
    Renderer renderer;
    RenderSettings s;
    s.misDistanceSamples = 4;
    EXPECT_EQ(errorOf([&] { renderer.render(scene, s); }),
              "--mis-distance is a parameter of mis, not of pyramid");
    EXPECT_EQ(errorOf([&] { Options::of(s); }),
              "--mis-distance is a parameter of mis, not of pyramid");
    s = {};
    s.width = -3;
    EXPECT_NE(errorOf([&] { renderer.render(scene, s); }).find("--width"), std::string::npos);
    s = {};
    s.method = "nope";
    EXPECT_NE(errorOf([&] { renderer.render(scene, s); }).find("unknown method 'nope'"),
              std::string::npos);
    s = {};
    s.samples = 64;  // not read by pyramid
    EXPECT_NE(errorOf([&] { renderer.render(scene, s); }).find("--samples is a parameter of"),
              std::string::npos);
}

// A scene in its file's light units starts from the exposure that shows it as
// Blender does, through options and through its renderSettings() alike.
TEST(ApiRenderSettings, AScenesDefaultsCarryItsLightUnits) {
    const std::string sky = std::string(TSIS_SOURCE_DIR) + "/data/env/sky.hdr";
    const Scene file(Options{{"mesh", "builtin:sphere"}, {"env", sky}, {"light-units", "file"}});
    const Scene own(Options{{"mesh", "builtin:sphere"}, {"env", sky}});
    EXPECT_EQ(own.renderSettings().exposure, RenderSettings{}.exposure);
    EXPECT_GT(file.renderSettings().exposure, 19.0f);
    const Options frame{
        {"width", "32"}, {"height", "32"}, {"atlas-res", "128"}, {"light-res", "256"}};
    RenderSettings s = file.renderSettings();
    s.width = s.height = 32;
    s.atlasResolution = 128;
    s.lightResolution = 256;
    Renderer renderer;
    EXPECT_EQ(renderer.render(file, frame).rgb8, renderer.render(file, s).rgb8);
    Options exposed = frame;
    exposed.set("exposure", "3.3");
    EXPECT_NE(renderer.render(file, exposed).rgb8, renderer.render(file, s).rgb8);
}

// Threads: one Renderer from two threads (either GL platform) renders every
// frame whole, the same as from one thread; one made on a thread that is gone
// renders on another (EGL refused that: "eglMakeCurrent failed (0x3002)").
TEST(ApiRenderer, OneRendererServesSeveralThreads) {
    const Options o{{"mesh", "builtin:sphere"},
                    {"width", "40"},
                    {"height", "32"},
                    {"atlas-res", "128"},
                    {"light-res", "256"}};
    for (const char* gl : {"osmesa", "egl"}) {
        SCOPED_TRACE(gl);
        Options marble = o;
        marble.set("material", "marble");
        const Scene scenes[2] = {Scene(o.sceneOptions()), Scene(marble.sceneOptions())};
        Renderer r("", gl);
        const std::vector<uint8_t> refs[2] = {r.render(scenes[0], o.renderOptions()).rgb8,
                                              r.render(scenes[1], o.renderOptions()).rgb8};
        std::vector<std::string> errors;
        int same[2] = {0, 0};
        std::mutex m;
        auto work = [&](int k) {
            for (int i = 0; i < 4; ++i) {
                try {
                    const bool equal = r.render(scenes[k], o.renderOptions()).rgb8 == refs[k];
                    const std::lock_guard lock(m);
                    same[k] += equal;
                } catch (const Error& e) {
                    const std::lock_guard lock(m);
                    errors.push_back(e.what());
                }
            }
        };
        std::thread a(work, 0), b(work, 1);
        a.join();
        b.join();
        EXPECT_EQ(errors, std::vector<std::string>{});
        EXPECT_EQ(same[0], 4);
        EXPECT_EQ(same[1], 4);
        std::unique_ptr<Renderer> made;
        std::thread([&] { made = std::make_unique<Renderer>("", gl); }).join();
        EXPECT_EQ(made->render(scenes[0], o.renderOptions()).rgb8, refs[0]);
    }
}

// A cancel that answers true stops the frame with tsis::Cancelled wherever it
// is (the volumetric walk either way, the reference's surface points and
// gather, between passes), soon after, and the next frame is whole: the same
// as a fresh renderer's.
TEST(ApiRenderer, CancelStopsTheFrameAndTheRendererStaysUsable) {
    const Options small{{"mesh", "builtin:sphere"},
                        {"width", "32"},
                        {"height", "32"},
                        {"atlas-res", "128"},
                        {"light-res", "256"}};
    const Scene scene(small.sceneOptions());
    const std::vector<uint8_t> fresh = Renderer().render(scene, small.renderOptions()).rgb8;
    Renderer r;
    // The options, and the poll that answers true: the third (100 ms in at
    // least, one per 50 ms) in a long frame, the first in a short one (the
    // first pass then stops).
    const std::vector<std::pair<std::vector<std::pair<std::string, std::string>>, int>> frames = {
        {{{"method", "volumetric"}, {"time", "60"}}, 3},
        {{{"method", "volumetric"}, {"time", "60"}, {"estimator", "light"}}, 3},
        {{{"method", "reference"}, {"spacing", "0.01"}, {"force", "true"}}, 3},
        {{{"method", "tsis"}, {"samples", "64"}}, 1},
    };
    for (const auto& [extra, stopAt] : frames) {
        Options o = small;
        for (const auto& [name, value] : extra) o.set(name, value);
        SCOPED_TRACE(o.args().size());
        int polls = 0;
        const auto start = std::chrono::steady_clock::now();
        EXPECT_THROW(
            r.render(scene, o.renderOptions(), [&, stop = stopAt] { return ++polls >= stop; }),
            Cancelled);
        const double s =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        EXPECT_EQ(polls, stopAt);
        EXPECT_LT(s, 20.0);  // not the 60 s asked for (the bound is loose: not a timing)
        EXPECT_EQ(r.render(scene, small.renderOptions()).rgb8, fresh);
    }
    // A cancel that never answers true changes nothing.
    EXPECT_EQ(r.render(scene, small.renderOptions(), [] { return false; }).rgb8, fresh);
}

// After fork(), a renderer made before refuses at once in the child, and so
// does making one (OpenCL's and GL's threads are gone); the child exits.
TEST(ApiRenderer, AForkedChildRefusesAtOnce) {
    const Options o{{"mesh", "builtin:sphere"},
                    {"width", "16"},
                    {"height", "16"},
                    {"atlas-res", "64"},
                    {"light-res", "256"}};
    const Scene scene(o.sceneOptions());
    Renderer r;
    r.render(scene, o.renderOptions());
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        const std::string same = errorOf([&] { r.render(scene, o.renderOptions()); });
        const std::string made = errorOf([&] { Renderer again; });
        const bool ok = same.find("forked child") != std::string::npos &&
                        made.find("child forked after one was made") != std::string::npos &&
                        made.find("'spawn'") != std::string::npos;
        std::_Exit(ok ? 0 : 1);
    }
    int status = -1;
    for (int i = 0; i < 300 && ::waitpid(child, &status, WNOHANG) == 0; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    if (status == -1) ::kill(child, SIGKILL), ::waitpid(child, &status, 0);
    EXPECT_TRUE(WIFEXITED(status)) << "the child hung or crashed";
    EXPECT_EQ(WEXITSTATUS(status), 0);
    EXPECT_FALSE(r.render(scene, o.renderOptions()).rgb8.empty());  // the parent's still renders
}

TEST(ApiCompare, RefusesImagesPastItsLimitsAndShortPixels) {
    const Image ok{4, 4, 3, std::vector<float>(48, 1.0f)};
    for (const Image& bad : {Image{70000, 1, 1, {}}, Image{8193, 8193, 1, {}}, Image{4, 4, 5, {}},
                             Image{0, 4, 3, {}}, Image{4, 4, 3, std::vector<float>(47)}}) {
        SCOPED_TRACE(bad.width);
        EXPECT_NE(errorOf([&] { compare(bad, ok); }).find("image: "), std::string::npos);
        EXPECT_NE(errorOf([&] { compare(ok, bad); }).find("reference: "), std::string::npos);
    }
    EXPECT_EQ(compare(ok, ok, &ok).rmse, 0);
}

}  // namespace
}  // namespace tsis::api
