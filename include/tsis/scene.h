// What a frame shows: a mesh (a file, builtin:NAME or arrays) with its
// materials, the lights, an environment and the camera, as typed values.
// A Scene keeps what it was told: a material given as albedo + mean free
// path stays so (each render inverts it through its own --profile), a file's
// materials stay the file's until setMaterial replaces them, and options()
// gives back the options that make the same scene again.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tsis/options.h"
#include "tsis/render_settings.h"

namespace tsis::api {

using Vec3 = std::array<float, 3>;

// A medium (docs/design.md §2): σs' and σa in 1/mm per RGB channel and the
// relative index of refraction η; or, where albedo and mfpMm are both given,
// the medium of that total diffuse reflectance (0, 0.99] and mean free path
// 1/σt' (mm), σ then the inversion's and set by the renderer.
struct Material {
    std::string name = "custom";  // a preset's name (Material::preset), else "custom"
    Vec3 sigmaSPrime{}, sigmaA{};
    float eta = 1.3f;
    std::optional<Vec3> albedo, mfpMm;
    // An albedo texture (an image file, sRGB when 8-bit), scaled by albedo
    // when given: a file's material names its own; an object's material
    // (Scene::fromObjects) applies it through the object's texture coordinates.
    std::string albedoTexture;

    // A preset of `tsis materials` ("skin1", "marble", …); throws tsis::Error.
    static Material preset(const std::string& name);
    static Material fromAlbedo(const Vec3& albedo, const Vec3& mfpMm, float eta = 1.3f);
};
Material presetMaterial(const std::string& name);  // Material::preset
std::vector<std::string> presetMaterialNames();

struct Light {
    bool directional = false;
    Vec3 vec{};         // point: position (mm); directional: the direction light travels
    Vec3 rgb{1, 1, 1};  // point: intensity (W/sr); directional: irradiance (W/mm²)
};

// A lat-long radiance map (.exr, .hdr) in W/(mm²·sr) lighting the scene,
// scaled by intensity and turned by rotateDegrees about the up axis (+y).
struct Environment {
    std::string path;  // the map's file; with pixels, only its name
    double intensity = 1;
    double rotateDegrees = 0;
    // The map as pixels: width × height RGB floats (2:1, row 0 = the top,
    // the zenith), in place of reading `path`.
    std::vector<float> pixels;
    int width = 0, height = 0;
};

struct Camera {
    Vec3 eye{0, 0, 20}, target{0, 0, 0}, up{0, 1, 0};
    float fovYDegrees = 35;  // vertical
};

// Where an object stands in its scene: scaled, then turned (degrees about
// X, then Y, then Z), then moved (mm).
struct Transform {
    float scale = 1;
    Vec3 rotateDegrees{0, 0, 0};
    Vec3 translateMm{0, 0, 0};
};

// One object of a scene of several (Scene::fromObjects): a mesh file (its
// positions in the unit it states, glTF's metres, else millimetres) or
// arrays (mm), placed by its transform, scattering in its material.
struct Object {
    std::string mesh;                 // a file (glTF, OBJ, PLY, STL, OFF) or builtin:NAME
    std::vector<float> vertices;      // with no mesh: x,y,z per vertex (mm)
    std::vector<uint32_t> triangles;  // three per triangle, counter-clockwise from outside
    Transform transform;
    // Over all of the object; none: its file's materials, and where it has
    // none the scene's (the options' material).
    std::optional<Material> material;
};

class Scene {
  public:
    // The scene of these scene options (`tsis render`'s: mesh, size-mm,
    // material, light, env, eye, …; Options::help lists them). Loads the
    // mesh. A render option (method, samples, …) is an error: it belongs to
    // Renderer::render. Throws tsis::Error.
    explicit Scene(const Options& options = {});
    // The mesh from arrays: x,y,z per vertex and three indices per triangle
    // (counter-clockwise seen from outside), turned, centred and scaled to
    // size-mm and given normals as a file is; the rest from `options` (no mesh).
    static Scene fromArrays(const std::vector<float>& vertices,
                            const std::vector<uint32_t>& triangles, const Options& options = {},
                            const std::string& name = "arrays");
    // Several objects, each placed and given its material, as one scene: the
    // whole scaled to size-mm (or with size-mm "file" kept at its own size in
    // mm); the rest from `options` (no mesh). Every method sees them as it
    // sees a file of several objects: a medium each, shadows between them.
    static Scene fromObjects(const std::vector<Object>& objects, const Options& options = {});
    // The objects as given to fromObjects (empty for any other scene).
    const std::vector<Object>& objects() const;

    Scene(const Scene& other);
    Scene(Scene&& other) noexcept;
    Scene& operator=(const Scene& other);
    Scene& operator=(Scene&& other) noexcept;
    ~Scene();

    // The material every triangle scatters in when one is set (setMaterial,
    // or the options' material); nullopt when each part of the mesh file
    // keeps its own (materials()).
    std::optional<Material> material() const;
    // Replaces every object's material (as --material does), checked as the
    // CLI checks it: throws tsis::Error and keeps the scene.
    void setMaterial(const Material& material);
    // What each part scatters in: the file's materials in the file's order
    // (σ as resolved by the default profile), or the one material.
    std::vector<Material> materials() const;

    // Checked as the CLI checks --light and --eye/--target/--up/--fov:
    // throws tsis::Error and keeps the scene.
    std::vector<Light> lights() const;
    void setLights(const std::vector<Light>& lights);
    std::optional<Environment> environment() const;
    void setEnvironment(const std::optional<Environment>& environment);
    Camera camera() const;
    void setCamera(const Camera& camera);

    // The scene options that make this scene again (Scene(options()); from
    // arrays: fromArrays with them). Lights and camera as set, the material
    // as given (none: the file's); an environment given as pixels is not
    // among them (environment() has it), nor are objects (objects()).
    Options options() const;
    // The notes loading the scene made (what `tsis render` prints as
    // "tsis: note: …"), in order.
    const std::vector<std::string>& notes() const;
    // The render settings this scene's frames start from: RenderSettings'
    // defaults, with the exposure that shows a scene in its file's light
    // units (light-units file) as Blender does. Renderer::render(scene,
    // options) fills what options leave unset from these.
    RenderSettings renderSettings() const;

    std::string meshName() const;
    size_t vertexCount() const;
    size_t triangleCount() const;

    struct Impl;

  private:
    friend class Renderer;
    explicit Scene(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

// Reads a mesh file (glTF, OBJ, PLY, STL, OFF) into a Scene with its
// materials, camera and lights; `options` as Scene's. Scene(options with mesh).
Scene load(const std::string& path, const Options& options = {});

}  // namespace tsis::api
