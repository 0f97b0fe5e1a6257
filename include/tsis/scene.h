// What a frame shows: a mesh, its material, the lights and the camera. Made
// from the scene options (Options: mesh, size-mm, rotate, mesh-up, crease,
// material, sigma-s, sigma-a, eta, light, eye, target, up, fov, atlas,
// atlas-res) as `tsis render` makes it, or from vertex and triangle arrays;
// then changed through plain structs.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "tsis/options.h"

namespace tsis::api {

using Vec3 = std::array<float, 3>;

// Scattering coefficients (docs/design.md §2): σs' and σa in 1/mm per RGB
// channel, relative index of refraction η.
struct Material {
    std::string name = "custom";
    Vec3 sigmaSPrime{}, sigmaA{};
    float eta = 1.3f;
};
// A preset of `tsis materials` ("skin1", "marble", …); throws tsis::Error.
Material presetMaterial(const std::string& name);
std::vector<std::string> presetMaterialNames();

struct Light {
    bool directional = false;
    Vec3 vec{};         // point: position (mm); directional: the direction light travels
    Vec3 rgb{1, 1, 1};  // point: intensity (W/sr); directional: irradiance (W/mm²)
};

struct Camera {
    Vec3 eye{0, 0, 20}, target{0, 0, 0}, up{0, 1, 0};
    float fovYDegrees = 35;  // vertical
};

class Scene {
  public:
    // The scene of `tsis render` with these options (render options among
    // them are checked, not used). Loads the mesh: throws tsis::Error.
    explicit Scene(const Options& options = {});
    // The mesh from arrays: x,y,z per vertex and three indices per triangle
    // (counter-clockwise seen from outside), turned, centred and scaled to
    // size-mm and given normals as a file is; the rest from `options` (its
    // mesh is not used).
    static Scene fromArrays(const std::vector<float>& vertices,
                            const std::vector<uint32_t>& triangles, const Options& options = {},
                            const std::string& name = "arrays");
    Scene(const Scene& other);
    Scene(Scene&& other) noexcept;
    Scene& operator=(const Scene& other);
    Scene& operator=(Scene&& other) noexcept;
    ~Scene();

    // Checked as the CLI checks --sigma-s/--sigma-a/--eta, --light and
    // --eye/--target/--up/--fov: throws tsis::Error and keeps the scene.
    Material material() const;
    void setMaterial(const Material& material);
    std::vector<Light> lights() const;
    void setLights(const std::vector<Light>& lights);
    Camera camera() const;
    void setCamera(const Camera& camera);

    std::string meshName() const;
    size_t vertexCount() const;
    size_t triangleCount() const;

    struct Impl;

  private:
    friend class Renderer;
    explicit Scene(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

}  // namespace tsis::api
