#include "render/scene_media.h"

#include <algorithm>

namespace tsis {

uint32_t SceneMedia::slotOfTag(float tag) const {
    const auto m = static_cast<size_t>(tag) - 1;
    return tag >= 1 && m < slotOfMedium.size() ? slotOfMedium[m] : 0;
}

SceneMedia sceneMedia(const Scene& scene, Media media) {
    SceneMedia s;
    s.media = std::move(media);
    for (uint32_t m = 0; m < s.media.count; ++m) {
        const uint32_t id = m < s.media.materialOf.size() ? s.media.materialOf[m] : kNoFileMaterial;
        // Two file materials with the same medium share a slot (a texture
        // or an albedo apart, they scatter alike).
        const Material& mat = scene.materialOf(id);
        auto same = [&](uint32_t other) {
            const Material& o = scene.materialOf(other);
            return o.sigmaSPrime == mat.sigmaSPrime && o.sigmaA == mat.sigmaA && o.eta == mat.eta;
        };
        auto it = std::find_if(s.slotMaterial.begin(), s.slotMaterial.end(), same);
        if (it == s.slotMaterial.end()) it = s.slotMaterial.insert(s.slotMaterial.end(), id);
        s.slotOfMedium.push_back(static_cast<uint32_t>(it - s.slotMaterial.begin()));
        s.etaOfMedium.push_back(static_cast<float>(mat.eta));
    }
    if (s.slotMaterial.empty()) s.slotMaterial.push_back(kNoFileMaterial);
    return s;
}

}  // namespace tsis
