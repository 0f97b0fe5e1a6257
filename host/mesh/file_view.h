// The cameras, lights and materials a mesh file places (glTF camera nodes,
// KHR_lights_punctual, glTF materials and OBJ .mtl files), as the file gives
// them: what scene/from_file.h makes a Camera, Lights and materials of.
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

#include "mesh/mesh.h"

namespace tsis {

// A perspective camera node (orthographic ones are noted and dropped by the loader).
struct FileCamera {
    std::string name;     // the camera's name, else its node's, else ""
    glm::dvec3 eye{0.0};  // the node's world position
    glm::dvec3 forward{0.0, 0.0, -1.0}, up{0.0, 1.0, 0.0};  // unit, orthogonal
    double yfovRadians = 0.0;                               // as the file gives it
};

// A light node. Photometric units as KHR_lights_punctual has them.
struct FileLight {
    enum class Type { Point, Directional, Spot };
    Type type = Type::Point;
    std::string name;
    glm::dvec3 position{0.0};              // point, spot
    glm::dvec3 direction{0.0, 0.0, -1.0};  // unit, the direction of travel (the node's −z)
    glm::dvec3 color{1.0};                 // linear RGB
    double intensity = 1.0;  // point, spot: candela (lm/sr); directional: lux (lm/m²)
    double range = 0.0;      // 0: unlimited
};

// A material as the file gives it (a glTF material, an OBJ .mtl entry):
// what scene/scene_materials.h makes an object's material of. Every field is
// optional; the file's words are kept, the physics is decided later.
struct FileMaterial {
    std::string name;
    // Surface albedo, linear RGB: glTF baseColorFactor (rgb), OBJ Kd.
    std::optional<glm::dvec3> albedo;
    // The albedo texture (glTF baseColorTexture, OBJ map_Kd): a path resolved
    // against the file's folder, or for an image inside the file (glb, data
    // URI) its encoded bytes with `texturePath` naming it for messages.
    std::string texturePath;
    std::string textureBytes;  // empty: read texturePath
    bool textureSrgb = true;   // glTF base colour and 8-bit OBJ maps are sRGB
    // The tangent-space normal map (glTF normalTexture, OBJ norm/map_Bump),
    // as the albedo texture (linear, never sRGB), and its scale on x and y.
    std::string normalMapPath, normalMapBytes;
    double normalScale = 1.0;
    // The roughness map (glTF metallicRoughnessTexture, its G channel; OBJ
    // map_Pr, grey), as the normal map; R = `roughness` × its channel.
    std::string roughnessMapPath, roughnessMapBytes;
    int roughnessChannel = 1;
    // The mean-free-path map (extras.tsis.mfp_texture; render/mfp_map.h), as
    // the normal map.
    std::string mfpMapPath, mfpMapBytes;
    std::optional<double> eta;  // KHR_materials_ior, OBJ Ni
    // The surface's GGX roughness R (physics/ggx.h): glTF roughnessFactor
    // (1 where the file gives none, as glTF says), OBJ Pr, or OBJ Ns by
    // Blender's mapping R = 1 − √Ns / 30; none: --roughness's.
    std::optional<double> roughness;
    // KHR_materials_volume: the distance (file units) light travels before
    // its colour becomes attenuationColor.
    std::optional<double> attenuationDistance;
    glm::dvec3 attenuationColor{1.0};
    // KHR_materials_volume_scatter: the volume's multiple-scattering albedo
    // (what a deep slab of it reflects: tsis' albedo) and the phase
    // function's g; with it the attenuation above is extinction, σt, not
    // absorption alone.
    std::optional<glm::dvec3> multiscatterColor;
    double scatterAnisotropy = 0.0;
    // tsis' own parameters (glTF extras {"tsis": {...}}, docs/guide/scenes-and-materials.md "Scenes
    // and materials"): a preset name, σs′/σa (1/mm), or albedo + mean free path (mm).
    std::string preset;
    std::optional<glm::dvec3> sigmaS, sigmaA, mfp;
};

struct FileView {
    std::vector<FileCamera> cameras;      // in node order
    std::vector<FileLight> lights;        // in node order
    std::vector<FileMaterial> materials;  // Mesh::materialIds index it
    // What normalizeView scaled the positions by: mm per file unit (glTF: per metre).
    double mmPerFileUnit = 1.0;
    // The unit the format states, in mm (glTF: metres, 1000); none for the
    // formats that state none (OBJ, PLY, STL, OFF: --units).
    std::optional<double> statedMmPerUnit;
    bool empty() const { return cameras.empty() && lights.empty() && materials.empty(); }
};

// The positions through the mesh's normalisation (directions unchanged).
inline void normalizeView(FileView& view, const Normalization& n) {
    for (FileCamera& c : view.cameras) c.eye = n.apply(c.eye);
    for (FileLight& l : view.lights) l.position = n.apply(l.position);
    view.mmPerFileUnit = n.scale;
}

// Only the materials some triangle uses, renumbered in their order (the
// mesh's materialIds follow): a file's unused materials then cost nothing
// later (no texture decoded, no inversion, no note).
inline void keepUsedMaterials(Mesh& mesh, FileView& view) {
    std::vector<uint32_t> renumber(view.materials.size(), kNoFileMaterial);
    for (uint32_t id : mesh.materialIds)
        if (id < renumber.size()) renumber[id] = 0;
    std::vector<FileMaterial> used;
    for (size_t m = 0; m < view.materials.size(); ++m)
        if (renumber[m] == 0) {
            renumber[m] = static_cast<uint32_t>(used.size());
            used.push_back(std::move(view.materials[m]));
        }
    for (uint32_t& id : mesh.materialIds)
        id = id < renumber.size() ? renumber[id] : kNoFileMaterial;
    if (used.empty()) mesh.materialIds.clear();
    view.materials = std::move(used);
}

// The cameras and lights turned as rotateMesh turned the mesh (about `centre`).
inline void rotateView(FileView& view, const glm::dmat3& rotation, const glm::dvec3& centre) {
    for (FileCamera& c : view.cameras) {
        c.eye = centre + rotation * (c.eye - centre);
        c.forward = rotation * c.forward;
        c.up = rotation * c.up;
    }
    for (FileLight& l : view.lights) {
        l.position = centre + rotation * (l.position - centre);
        l.direction = rotation * l.direction;
    }
}

}  // namespace tsis
