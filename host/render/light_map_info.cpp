#include "render/light_map_info.h"

#include <cstring>
#include <glm/gtc/type_ptr.hpp>

#include "util/error.h"

namespace tsis {

TsisLightMapInfo lightMapInfo(const LightView& view, int resolution) {
    TSIS_CHECK_GT(resolution, 0);
    TsisLightMapInfo info{};
    std::memcpy(info.view_proj, glm::value_ptr(view.viewProj), sizeof(info.view_proj));
    info.res = resolution;
    // Perspective: a texel spans 2·tan(half)/res of the axial distance (clip w).
    // Orthographic: clip w = 1 and the texel size is fixed.
    info.tau_per_w = view.light.type == Light::Type::Point
                         ? 2.0f * view.tanHalf / static_cast<float>(resolution)
                         : view.texelMm;
    return info;
}

}  // namespace tsis
