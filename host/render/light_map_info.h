// The kernels' view of one light's maps (kernels/light_map.h) from the GL
// light view: projection and texel size.
#pragma once

#include "gl/light_view.h"
#include "light_map.h"

namespace tsis {

TsisLightMapInfo lightMapInfo(const LightView& view, int resolution);

}  // namespace tsis
