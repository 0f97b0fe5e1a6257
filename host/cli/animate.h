// `tsis animate`: a sequence of frames from one Renderer while the light
// orbits, the material changes or the object grows (thesis Fig. 4.5).
#pragma once

#include <string>
#include <vector>

namespace tsis {

int runAnimate(const std::vector<std::string>& argv);

}  // namespace tsis
