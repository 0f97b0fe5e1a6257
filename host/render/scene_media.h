// The media of a scene (mesh/media.h) and the material each scatters in: a
// frame runs its method once per distinct material ("slot") and keeps, for
// every point, the run of its own medium's material (docs/design.md §2
// "Materials"). One material: one slot, the frame as it always was.
#pragma once

#include <cstdint>
#include <vector>

#include "mesh/media.h"
#include "scene/scene.h"

namespace tsis {

struct SceneMedia {
    Media media;
    std::vector<uint32_t> slotMaterial;  // the file material of each slot (Mesh::materialIds)
    std::vector<uint32_t> slotOfMedium;  // the slot of each medium
    std::vector<float> etaOfMedium;      // η of each medium's material (GL's Fresnel terms)
    size_t slots() const { return slotMaterial.size(); }
    // The slot of a point that carries medium tag `tag` (1 + medium; 0: none → slot 0).
    uint32_t slotOfTag(float tag) const;
};

SceneMedia sceneMedia(const Scene& scene, Media media);

}  // namespace tsis
