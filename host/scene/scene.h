// What a frame shows: the object, its material, the lights and the camera.
// Plain data, shared by the GL passes and the methods.
#pragma once

#include <glm/vec3.hpp>
#include <memory>
#include <string>
#include <vector>

#include "image/image_io.h"
#include "mesh/mesh.h"
#include "physics/material.h"
#include "scene/environment.h"
#include "tsis_shared.h"

namespace tsis {

struct Light {
    enum class Type { Point, Directional };
    Type type = Type::Point;
    glm::vec3 vec{0.0f};  // point: position (mm); directional: direction the light travels
    glm::vec3 rgb{1.0f};  // point: intensity (W/sr); directional: irradiance (W/mm²)
    bool shadows =
        true;  // V from the shadow map; false: V = 1 (tests against unshadowed integrals)
    // The sun of Scene::env (applyEnvironment makes it; not a --light of its own).
    bool environment = false;
};

struct Camera {
    glm::vec3 eye{0.0f, 0.0f, 20.0f};
    glm::vec3 target{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fovYDegrees = 40.0f;  // vertical; `tsis render` frames the object with --fov (35)
};

// An albedo texture (a glTF baseColorTexture, an OBJ map_Kd): linear RGB,
// three channels, row 0 = the image's top, read through Mesh::texcoords.
struct AlbedoTexture {
    std::string name;  // for messages: the file it came from
    ImageF image;
};

// One step of a mean-free-path map (render/mfp_map.h): the material's
// medium with its mean free path × `scale`.
struct MfpStep {
    double scale = 1.0;
    Material medium;
};

// The material of the triangles that carry one file material (issue 20,
// docs/design.md §2 "Materials"): the medium light scatters in, and the
// albedo its surface shows — the medium's own total reflectance unless a
// texture (times `textureScale`) or another material of the same medium sets
// it per texel.
struct ObjectMaterial {
    Material medium;
    glm::dvec3 albedo{0.0};  // what `medium` reflects in total (its profile's ∫Rd 2πr dr)
    std::shared_ptr<const AlbedoTexture> texture;  // null: none
    glm::dvec3 textureScale{1.0};                  // albedo = textureScale · texel
    // The surface's GGX roughness R from the file, in [kMinRoughness, 1];
    // < 0: none given (RenderOptions::roughness decides).
    double roughness = -1.0;
    // A tangent-space normal map (+x along the texture's u, +y up the image,
    // glTF's convention; linear RGB), its x and y scaled by normalScale;
    // null: none (render/surface_atlas.h bakes it per atlas texel).
    std::shared_ptr<const AlbedoTexture> normalMap;
    double normalScale = 1.0;
    // A roughness map (linear): R = roughness (1 when none given) × its
    // channel `roughnessChannel` (glTF's metallic-roughness texture: G, 1;
    // OBJ map_Pr, a grey map: 0); null: none (render/surface_atlas.h).
    std::shared_ptr<const AlbedoTexture> roughnessMap;
    int roughnessChannel = 1;
    // A mean-free-path map (linear; render/mfp_map.h) and the steps it is
    // quantised to; null and empty: none (`medium` everywhere).
    std::shared_ptr<const AlbedoTexture> mfpMap;
    std::vector<MfpStep> mfpSteps;
};

struct Scene {
    Mesh mesh;          // normalised (mm), with normals and valid UVs
    Material material;  // of every triangle without a file material
    // The file's materials, indexed by Mesh::materialIds (empty: none).
    std::vector<ObjectMaterial> objectMaterials;
    // The medium of file material `id` (kNoFileMaterial: `material`).
    const Material& materialOf(uint32_t id) const {
        return id < objectMaterials.size() ? objectMaterials[id].medium : material;
    }
    std::vector<Light> lights;
    Camera camera;
    Environment env;  // --env: its residual; its sun is among the lights
    // The object's bounding-box diagonal, mm (--size-mm S, or with
    // --size-mm file the file's own once the mesh is loaded).
    double sizeMm = 10;
};

// The sizes --size-mm takes (tsis render and tsis view alike) and the view's
// size slider spans, mm.
constexpr double kMinSizeMm = 1e-3, kMaxSizeMm = 1e5;

// The largest number of lights a frame takes (GL uniform arrays and the mis
// kernel's private arrays are sized by it): kernels/tsis_shared.h.
constexpr int kMaxLights = TSIS_MAX_LIGHTS;

}  // namespace tsis
