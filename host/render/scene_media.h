// The media of a scene (mesh/media.h) and the materials they scatter in: a
// frame runs its method once per distinct material ("slot") and keeps, for
// every point, the run of the material of its own triangle, over the entry
// points of its whole medium (docs/design.md §2 "Materials": a solid of
// several materials; a material's mean-free-path map, one slot per step,
// render/mfp_map.h). One material: one slot, the frame as it always was.
#pragma once

#include <cstdint>
#include <vector>

#include "mesh/media.h"
#include "scene/scene.h"

namespace tsis {

struct SceneMedia {
    Media media;
    std::vector<uint32_t> slotMaterial;  // the file material of each slot (Mesh::materialIds)
    // The step of its material's mean-free-path map each slot scatters with
    // (render/mfp_map.h); kNoStep: the material's medium.
    static constexpr uint32_t kNoStep = ~0u;
    std::vector<uint32_t> slotStep;
    std::vector<uint32_t> slotOfMedium;  // the slot of each medium's first triangle
    // The slot of each file material (Mesh::materialIds), and of
    // kNoFileMaterial last; materials no triangle uses: 0.
    std::vector<uint32_t> slotOfId;
    // Some solid holds triangles of two slots: a point's slot is its texel's
    // (render/albedo_atlas.h), not its medium's.
    bool mixed = false;
    std::vector<float> etaOfMedium;  // η of each medium's material (GL's Fresnel terms)
    size_t slots() const { return slotMaterial.size(); }
    // The slot of a point that carries medium tag `tag` (1 + medium; 0: none → slot 0).
    uint32_t slotOfTag(float tag) const;
    // The file material of medium m's first triangle (kNoFileMaterial: none).
    uint32_t fileMaterialOfMedium(size_t m) const;
    // The slot of file material `id` (kNoFileMaterial: the scene's material).
    uint32_t slotOfMaterial(uint32_t id) const;
    // Whether file material `id`'s texels scatter with its mean-free-path
    // map's steps, and the slot of step `step` (the material's without).
    bool hasSteps(uint32_t id) const {
        return id < stepSlotsOfId.size() && !stepSlotsOfId[id].empty();
    }
    uint32_t slotOfStep(uint32_t id, size_t step) const;
    // The medium slot k scatters in.
    const Material& slotMedium(const Scene& scene, size_t k) const;
    // The slots of each file material's map steps (empty: no map).
    std::vector<std::vector<uint32_t>> stepSlotsOfId;
};

SceneMedia sceneMedia(const Scene& scene, Media media);

}  // namespace tsis
