#include "description/scene_description.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "description/mesh_preparation.h"
#include "description/objects.h"
#include "physics/material.h"
#include "render/albedo_inversion.h"
#include "render/renderer.h"
#include "scene/environment.h"
#include "util/error.h"
#include "util/input_file.h"

namespace tsis {

namespace {

constexpr double kPerM2ToPerMm2 = 1e-6;  // W/m² → W/mm²

// The default lights where neither lights nor an environment are given, and
// the default camera (framing an object of that diagonal) with the eye,
// target and up given over it.
void placeBySize(Scene& scene, const SceneDescription& d, double size) {
    if (d.lights.empty() && !scene.env) scene.lights = defaultLights(size);
    const CameraDescription& c = d.camera;
    scene.camera = defaultCamera(size, c.fovDegrees.value_or(SceneDefaults().fovDegrees));
    if (c.eye) scene.camera.eye = *c.eye;
    if (c.target) scene.camera.target = *c.target;
    if (c.up) scene.camera.up = *c.up;
}

}  // namespace

Material resolveMaterial(const MaterialDescription& d, ProfileModel profile) {
    Material m = presetMaterial(d.preset.value_or(SceneDefaults().material));
    if (d.sigmaSPrime) m.sigmaSPrime = *d.sigmaSPrime;
    if (d.sigmaA) m.sigmaA = *d.sigmaA;
    if (d.eta) m.eta = *d.eta;
    validateMaterial(m);
    // The artist's parameters (render/albedo_inversion.h): the albedo with
    // the mean free path, or the mean free path alone with the material's
    // own albedo.
    if (d.albedo && (d.sigmaSPrime || d.sigmaA))
        fail("--albedo sets σs' and σa: not with --sigma-s or --sigma-a");
    if (d.albedo && !d.mfpMm)
        fail(
            "--albedo needs --mfp R,G,B (mm): the albedo fixes σs'/σt', the mean free path the "
            "scale");
    if (d.mfpMm)
        m = materialFromAlbedo("custom", d.albedo ? *d.albedo : albedoOf(m, profile), *d.mfpMm,
                               m.eta, profile);
    if (d.sigmaSPrime || d.sigmaA || d.eta || d.mfpMm) m.name = "custom";
    return m;
}

MaterialOverrides overridesOf(const MaterialDescription& m) {
    MaterialOverrides o;
    o.replaceAll = m.preset || m.albedo || m.sigmaSPrime || m.sigmaA;
    o.mfp = m.mfpMm;
    o.eta = m.eta;
    return o;
}

MeshOptions meshOptionsOf(const MeshDescription& m) {
    MeshOptions o;
    o.rotateDegrees = m.rotateDegrees.value_or(o.rotateDegrees);
    o.zUp = m.zUp.value_or(o.zUp);
    o.creaseDegrees = m.creaseDegrees.value_or(o.creaseDegrees);
    o.atlasMode = m.atlasMode.value_or(o.atlasMode);
    // --atlas-res 0 (automatic) renders at 256² or 512²: packed for the finer.
    const int resolution = m.atlasResolution.value_or(0);
    o.atlas.resolution = resolution > 0 ? resolution : kAtlasPackResolution;
    return o;
}

double nominalSizeMm(const MeshDescription& m) {
    return m.sizeFromFile ? SceneDefaults().sizeMm : m.sizeMm.value_or(SceneDefaults().sizeMm);
}

std::optional<double> unitsMmOf(const MeshDescription& m) {
    if (!m.units) return std::nullopt;
    return *m.units == "m" ? 1000.0 : *m.units == "cm" ? 10.0 : 1.0;
}

std::string meshSpecOf(const MeshDescription& m) {
    return m.spec.value_or(SceneDefaults().mesh);
}

FileViewUse fileViewUseOf(const SceneDescription& d) {
    // The description's camera and lights win, per kind.
    FileViewUse use;
    use.camera = !d.camera.eye && !d.camera.target && !d.camera.up;
    use.cameraIndex = d.camera.fileCamera;
    use.fov = !d.camera.fovDegrees;
    use.lights = d.lights.empty() && !d.env;
    use.fileLightUnits = d.fileLightUnits;
    use.lightsGivenBy = !d.lights.empty() && d.env ? "--light and --env given"
                        : !d.lights.empty()        ? "--light given"
                                                   : "--env given: it lights alone";
    return use;
}

std::vector<Light> defaultLights(double sizeMm) {
    const float s = static_cast<float>(sizeMm);
    Light back;
    back.type = Light::Type::Point;
    back.vec = glm::vec3(-0.45f, 0.75f, -1.0f) * (1.3f * s);
    // Intensity so that the irradiance at the object's centre is about 1.
    back.rgb = glm::vec3(glm::dot(back.vec, back.vec));
    Light fill;
    fill.type = Light::Type::Directional;
    fill.vec = glm::vec3(0.6f, -0.4f, -1.0f);
    fill.rgb = glm::vec3(0.12f);
    return {back, fill};
}

Camera defaultCamera(double sizeMm, float fovYDegrees) {
    Camera c;
    c.fovYDegrees = fovYDegrees;
    float halfFov = glm::radians(fovYDegrees) * 0.5f;
    float dist = 0.5f * static_cast<float>(sizeMm) / std::sin(halfFov) * 1.05f;
    c.eye = glm::normalize(glm::vec3(0.0f, 0.35f, 1.0f)) * dist;
    return c;
}

Scene placedScene(const SceneDescription& d, ProfileModel profile) {
    Scene scene;
    // With the file's size the size is known once the mesh is: loadSceneMesh
    // places again by it.
    const double size = nominalSizeMm(d.mesh);
    if (d.mesh.units && !d.mesh.sizeFromFile)
        fail("--units ", *d.mesh.units, " is the file's unit for --size-mm file");
    scene.sizeMm = size;
    scene.material = resolveMaterial(d.material, profile);
    if (d.fileLightUnits && !d.lights.empty())
        fail(
            "--light-units file reads the glTF's lights (and --env in W/(m²·sr)): not with "
            "--light, whose values are tsis' own");
    scene.lights = d.lights;
    if (static_cast<int>(scene.lights.size()) > kMaxLights)
        fail("too many lights: ", scene.lights.size(), " (at most ", kMaxLights, ")");
    if (d.env && d.env->path.empty()) fail("--env-intensity and --env-rotate need --env FILE");
    if (d.env) {
        scene.env.map = d.env->map ? d.env->map : loadEnvironment(d.env->path);
        scene.env.intensity = d.env->intensity.value_or(1.0);
        // The file's light units: the map in W/(m²·sr), as Blender and Cycles read it.
        if (d.fileLightUnits) scene.env.intensity *= kPerM2ToPerMm2;
        scene.env.rotateDegrees = d.env->rotateDegrees.value_or(0.0);
    }
    placeBySize(scene, d, size);
    applyEnvironment(scene);  // the map's sun: one more directional light
    if (static_cast<int>(scene.lights.size()) > kMaxLights)
        fail("too many lights: ", scene.lights.size() - 1, " and the environment's sun (at most ",
             kMaxLights, " in all)");
    const CameraDescription& c = d.camera;
    if (c.fileCamera && (c.eye || c.target || c.up))
        fail("--camera picks the mesh file's camera: not with --eye, --target or --up");
    glm::vec3 forward = scene.camera.target - scene.camera.eye;
    if (glm::length(forward) == 0.0f) fail("--eye and --target are the same point");
    if (glm::length(glm::cross(forward, scene.camera.up)) < 1e-6f * glm::length(forward))
        fail("--up is parallel to the view direction (or zero)");
    return scene;
}

void loadSceneMesh(Scene& scene, const SceneDescription& d, ProfileModel profile,
                   FileMaterials* kept) {
    setOutsideAssetsAllowed(d.mesh.allowOutsideAssets);
    const auto placeAgain = [&d](Scene& s, double size) {
        placeBySize(s, d, size);
        applyEnvironment(s);
    };
    const std::function<void(Scene&, double)> fileSize =
        d.mesh.sizeFromFile ? std::function<void(Scene&, double)>(placeAgain) : nullptr;
    if (d.objects.empty()) {
        loadMeshInto(scene, meshSpecOf(d.mesh), nominalSizeMm(d.mesh), meshOptionsOf(d.mesh),
                     fileViewUseOf(d), overridesOf(d.material), profile, fileSize,
                     unitsMmOf(d.mesh), kept);
        return;
    }
    // The objects' own materials stay theirs: the description's fills the rest.
    FileView view;
    Mesh mesh = combinedMesh(d.objects, view);
    loadMeshInto(scene, std::move(mesh), std::move(view), "objects", nominalSizeMm(d.mesh),
                 meshOptionsOf(d.mesh), fileViewUseOf(d), MaterialOverrides{}, profile, fileSize,
                 std::nullopt, kept);
}

Scene buildScene(const SceneDescription& d, ProfileModel profile, FileMaterials* kept) {
    Scene scene = placedScene(d, profile);
    loadSceneMesh(scene, d, profile, kept);
    return scene;
}

}  // namespace tsis
