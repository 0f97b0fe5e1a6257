#include "render/scene_media.h"

#include <algorithm>

namespace tsis {

uint32_t SceneMedia::slotOfTag(float tag) const {
    const auto m = static_cast<size_t>(tag) - 1;
    return tag >= 1 && m < slotOfMedium.size() ? slotOfMedium[m] : 0;
}

uint32_t SceneMedia::fileMaterialOfMedium(size_t m) const {
    return m < media.materialOf.size() ? media.materialOf[m] : kNoFileMaterial;
}

uint32_t SceneMedia::slotOfMaterial(uint32_t id) const {
    if (slotOfId.empty()) return 0;
    return slotOfId[std::min<size_t>(id, slotOfId.size() - 1)];
}

uint32_t SceneMedia::slotOfStep(uint32_t id, size_t step) const {
    if (!hasSteps(id)) return slotOfMaterial(id);
    return stepSlotsOfId[id][std::min(step, stepSlotsOfId[id].size() - 1)];
}

namespace {

// The medium of file material `id`, or of its map's step `step`.
const Material& mediumOf(const Scene& scene, uint32_t id, uint32_t step) {
    return step == SceneMedia::kNoStep ? scene.materialOf(id)
                                       : scene.objectMaterials[id].mfpSteps[step].medium;
}

}  // namespace

const Material& SceneMedia::slotMedium(const Scene& scene, size_t k) const {
    return mediumOf(scene, slotMaterial[k], slotStep[k]);
}

SceneMedia sceneMedia(const Scene& scene, Media media) {
    SceneMedia s;
    s.media = std::move(media);
    // Two materials with the same medium share a slot (a texture or an
    // albedo apart, they scatter alike); a map's step is a material of its own.
    auto slotOf = [&](uint32_t id, uint32_t step = SceneMedia::kNoStep) {
        const Material& mat = mediumOf(scene, id, step);
        for (size_t k = 0; k < s.slotMaterial.size(); ++k) {
            const Material& o = s.slotMedium(scene, k);
            if (o.sigmaSPrime == mat.sigmaSPrime && o.sigmaA == mat.sigmaA && o.eta == mat.eta)
                return static_cast<uint32_t>(k);
        }
        s.slotMaterial.push_back(id);
        s.slotStep.push_back(step);
        return static_cast<uint32_t>(s.slotMaterial.size() - 1);
    };
    // The media's own first (the slots of a scene without mixed solids, in
    // the order they always had), then every other material a triangle has.
    for (uint32_t m = 0; m < s.media.count; ++m) {
        const uint32_t id = s.fileMaterialOfMedium(m);
        s.slotOfMedium.push_back(slotOf(id));
        s.etaOfMedium.push_back(static_cast<float>(scene.materialOf(id).eta));
    }
    if (s.slotMaterial.empty()) slotOf(kNoFileMaterial);
    const Mesh& mesh = scene.mesh;
    s.slotOfId.assign(scene.objectMaterials.size() + 1, 0);
    s.stepSlotsOfId.resize(scene.objectMaterials.size());
    std::vector<char> seen(s.slotOfId.size(), 0);
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const uint32_t id = mesh.materialOf(t);
        const size_t k = std::min<size_t>(id, s.slotOfId.size() - 1);
        if (!seen[k]) {
            s.slotOfId[k] = slotOf(id), seen[k] = 1;
            // A map's texels scatter with their steps': several slots on a solid.
            if (id < scene.objectMaterials.size() && scene.objectMaterials[id].mfpMap &&
                mesh.hasTexcoords()) {
                for (size_t step = 0; step < scene.objectMaterials[id].mfpSteps.size(); ++step)
                    s.stepSlotsOfId[id].push_back(slotOf(id, static_cast<uint32_t>(step)));
                s.mixed = true;
            }
        }
        const uint32_t v = mesh.triangles[t][0];
        const uint32_t m = v < s.media.ofVertex.size() ? s.media.ofVertex[v] : 0;
        if (m < s.slotOfMedium.size() && s.slotOfId[k] != s.slotOfMedium[m]) s.mixed = true;
    }
    return s;
}

}  // namespace tsis
