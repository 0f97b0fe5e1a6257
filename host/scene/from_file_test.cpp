#include "scene/from_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "support/error_of.h"

namespace tsis {
namespace {

using ::testing::HasSubstr;

FileLight light(FileLight::Type type, glm::dvec3 v, glm::dvec3 color, double intensity) {
    FileLight l;
    l.type = type;
    l.position = l.direction = v;
    l.color = color;
    l.intensity = intensity;
    return l;
}

// 100 cd at 30 mm of a scene 10× its file's size (3 m of the file's metres:
// 100/9 lux) against a 1 lux sun: the lamp is the strongest and gives 1 W/mm²
// at the centre, the sun keeps its ratio, 1 : 100/9.
TEST(FromFile, LightsKeepTheirBalanceAndTheStrongestGivesOne) {
    const std::vector<Light> out =
        lightsFromFile({light(FileLight::Type::Point, {0, 0, 30}, {1, 0.5, 0}, 100),
                        light(FileLight::Type::Directional, {0, -1, 0}, {1, 1, 1}, 1)},
                       10.0, 10.0);
    ASSERT_EQ(out.size(), 2u);
    EXPECT_EQ(out[0].type, Light::Type::Point);
    EXPECT_EQ(out[0].vec, glm::vec3(0, 0, 30));
    // I / d² = 1 W/mm² in its brightest channel.
    EXPECT_NEAR(out[0].rgb.x, 900.0f, 1e-3f);
    EXPECT_NEAR(out[0].rgb.y, 450.0f, 1e-3f);
    EXPECT_EQ(out[0].rgb.z, 0.0f);
    EXPECT_EQ(out[1].type, Light::Type::Directional);
    EXPECT_EQ(out[1].vec, glm::vec3(0, -1, 0));
    EXPECT_NEAR(out[1].rgb.x, 0.09f, 1e-7f);
    EXPECT_EQ(out[1].rgb.x, out[1].rgb.z);

    // A light inside the object counts at half its diagonal; spots are points.
    const std::vector<Light> near =
        lightsFromFile({light(FileLight::Type::Spot, {1, 0, 0}, {1, 1, 1}, 5)}, 1.0, 10.0);
    EXPECT_EQ(near[0].type, Light::Type::Point);
    EXPECT_NEAR(near[0].rgb.x, 25.0f, 1e-4f);
    // Nothing to scale by: dark lights stay dark.
    EXPECT_EQ(
        lightsFromFile({light(FileLight::Type::Point, {0, 0, 9}, {1, 1, 1}, 0)}, 1, 10)[0].rgb,
        glm::vec3(0));
}

// --light-units file: the file's own power, no common factor, at any scale
// and over point, spot and directional lights: candela/683 × (s/1000)² W/sr
// and lux/683 × 10⁻⁶ W/mm² (a Blender light of P W exported as
// P/4π·683 cd is P/4π W/sr at the file's size, s = 1000 mm per metre).
TEST(FromFile, FileLightUnitsKeepTheFilesPower) {
    for (const double mmPerMetre : {1000.0, 10.0, 2.5e4})
        for (const double cd : {1.0, 683.0 * 100 / (4 * M_PI)}) {
            const std::vector<Light> out =
                lightsFromFile({light(FileLight::Type::Point, {0, 0, 30}, {1, 0.5, 0}, cd),
                                light(FileLight::Type::Spot, {0, 9, 0}, {1, 1, 1}, 2 * cd),
                                light(FileLight::Type::Directional, {0, -1, 0}, {1, 1, 1}, 3)},
                               mmPerMetre, 10.0, false);
            const double k = mmPerMetre / 1000.0;
            EXPECT_NEAR(out[0].rgb.x, cd / 683.0 * k * k, 1e-6 * cd * k * k) << mmPerMetre;
            EXPECT_NEAR(out[0].rgb.y, 0.5 * cd / 683.0 * k * k, 1e-6 * cd * k * k);
            EXPECT_NEAR(out[1].rgb.z, 2 * cd / 683.0 * k * k, 1e-6 * cd * k * k);
            EXPECT_NEAR(out[2].rgb.x, 3 / 683.0 * 1e-6, 1e-15) << mmPerMetre;
            // Re-levelled, the same lights give 1 W/mm² at the centre instead.
            const std::vector<Light> relevelled =
                lightsFromFile({light(FileLight::Type::Directional, {0, -1, 0}, {1, 1, 1}, 3)},
                               mmPerMetre, 10.0, true);
            EXPECT_NEAR(relevelled[0].rgb.x, 1.0, 1e-6);
        }
}

TEST(FromFile, CameraTargetIsNearestTheCentreAndAtLeastHalfTheSize) {
    FileCamera c;
    c.eye = {3, 0, 20};
    c.forward = {0, 0, -1};
    c.up = {0, 1, 0};
    c.yfovRadians = 0.5;
    Camera cam = cameraFromFile(c, 10.0);
    EXPECT_EQ(cam.eye, glm::vec3(3, 0, 20));
    EXPECT_EQ(cam.target, glm::vec3(3, 0, 0));
    EXPECT_EQ(cam.up, glm::vec3(0, 1, 0));
    EXPECT_NEAR(cam.fovYDegrees, 28.6479f, 1e-4f);
    c.forward = {0, 0, 1};  // looking away from the object
    EXPECT_EQ(cameraFromFile(c, 10.0).target, glm::vec3(3, 0, 25));
}

FileView twoCameras() {
    FileView v;
    for (const char* name : {"A", "B"}) {
        FileCamera c;
        c.name = name;
        c.eye = {0, 0, name[0] == 'A' ? 20 : 30};
        c.yfovRadians = 0.6;
        v.cameras.push_back(c);
    }
    return v;
}

std::string notesOf(Scene& scene, const FileView& view, const FileViewUse& use) {
    testing::internal::CaptureStderr();
    useFileView(scene, view, use, 10.0, "s.gltf");
    return testing::internal::GetCapturedStderr();
}

TEST(FromFile, CameraChoiceAndWhatIsLeftIsNoted) {
    Scene scene;
    FileViewUse use;
    use.cameraIndex = 1;
    EXPECT_EQ(notesOf(scene, twoCameras(), use),
              "tsis: note: mesh 's.gltf': 1 other camera ignored (camera 1 'B' used; --camera N "
              "picks another)\n");
    EXPECT_EQ(scene.camera.eye, glm::vec3(0, 0, 30));
    // --fov wins over the file's.
    scene.camera.fovYDegrees = 12;
    use.fov = false;
    notesOf(scene, twoCameras(), use);
    EXPECT_EQ(scene.camera.fovYDegrees, 12.0f);

    use.cameraIndex = 2;
    EXPECT_THAT(
        test::errorOf([&] { useFileView(scene, twoCameras(), use, 10, "s.gltf"); }, "s.gltf"),
        HasSubstr("--camera 2: mesh 's.gltf' has 2 cameras (0 'A', 1 'B')"));
    EXPECT_THAT(test::errorOf([&] { useFileView(scene, FileView{}, use, 10, "s.obj"); }, "s.obj"),
                HasSubstr("--camera 2: mesh 's.obj' has no perspective camera"));

    FileViewUse cli;
    cli.camera = false;
    const Camera before = scene.camera;
    EXPECT_EQ(notesOf(scene, twoCameras(), cli),
              "tsis: note: mesh 's.gltf': 2 cameras ignored (--eye, --target or --up given)\n");
    EXPECT_EQ(scene.camera.eye, before.eye);

    FileView narrow = twoCameras();
    narrow.cameras[0].yfovRadians = 0.001;
    EXPECT_THAT(
        test::errorOf([&] { useFileView(scene, narrow, FileViewUse{}, 10, "s.gltf"); }, "s.gltf"),
        HasSubstr("camera 0 'A': yfov 0.001 rad is outside"));
}

TEST(FromFile, LightsLeftOutAreNoted) {
    FileView v;
    for (int i = 0; i < kMaxLights + 1; ++i)
        v.lights.push_back(light(i == 0 ? FileLight::Type::Spot : FileLight::Type::Point,
                                 {0, 0, 10 + i}, {1, 1, 1}, 1));
    v.lights[1].range = 4;
    Scene scene;
    EXPECT_EQ(notesOf(scene, v, FileViewUse{}),
              "tsis: note: mesh 's.gltf': 1 light beyond the first 8 ignored (at most 8)\n"
              "tsis: note: mesh 's.gltf': 1 spot light used as point light (cones ignored)\n"
              "tsis: note: mesh 's.gltf': range of 1 light ignored (tsis' lights reach "
              "everything)\n");
    EXPECT_EQ(scene.lights.size(), static_cast<size_t>(kMaxLights));

    FileViewUse cli;
    cli.lights = false;
    Scene given;
    given.lights = {Light{}};
    EXPECT_EQ(notesOf(given, v, cli),
              "tsis: note: mesh 's.gltf': 9 lights ignored (--light given)\n");
    EXPECT_EQ(given.lights.size(), 1u);
    // The note gives the reason it was handed (the command line's own words).
    for (const std::string why : {"--env given: it lights alone", "tsis view has its own lights"}) {
        cli.lightsGivenBy = why;
        EXPECT_EQ(notesOf(given, v, cli),
                  "tsis: note: mesh 's.gltf': 9 lights ignored (" + why + ")\n");
    }
}

}  // namespace
}  // namespace tsis
