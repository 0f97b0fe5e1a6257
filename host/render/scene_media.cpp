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

SceneMedia sceneMedia(const Scene& scene, Media media) {
    SceneMedia s;
    s.media = std::move(media);
    // Two file materials with the same medium share a slot (a texture or an
    // albedo apart, they scatter alike).
    auto slotOf = [&](uint32_t id) {
        const Material& mat = scene.materialOf(id);
        auto same = [&](uint32_t other) {
            const Material& o = scene.materialOf(other);
            return o.sigmaSPrime == mat.sigmaSPrime && o.sigmaA == mat.sigmaA && o.eta == mat.eta;
        };
        auto it = std::find_if(s.slotMaterial.begin(), s.slotMaterial.end(), same);
        if (it == s.slotMaterial.end()) it = s.slotMaterial.insert(s.slotMaterial.end(), id);
        return static_cast<uint32_t>(it - s.slotMaterial.begin());
    };
    // The media's own first (the slots of a scene without mixed solids, in
    // the order they always had), then every other material a triangle has.
    for (uint32_t m = 0; m < s.media.count; ++m) {
        const uint32_t id = s.fileMaterialOfMedium(m);
        s.slotOfMedium.push_back(slotOf(id));
        s.etaOfMedium.push_back(static_cast<float>(scene.materialOf(id).eta));
    }
    if (s.slotMaterial.empty()) s.slotMaterial.push_back(kNoFileMaterial);
    const Mesh& mesh = scene.mesh;
    s.slotOfId.assign(scene.objectMaterials.size() + 1, 0);
    std::vector<char> seen(s.slotOfId.size(), 0);
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const uint32_t id = mesh.materialOf(t);
        const size_t k = std::min<size_t>(id, s.slotOfId.size() - 1);
        if (!seen[k]) s.slotOfId[k] = slotOf(id), seen[k] = 1;
        const uint32_t v = mesh.triangles[t][0];
        const uint32_t m = v < s.media.ofVertex.size() ? s.media.ofVertex[v] : 0;
        if (m < s.slotOfMedium.size() && s.slotOfId[k] != s.slotOfMedium[m]) s.mixed = true;
    }
    return s;
}

}  // namespace tsis
