// A radial profile (Rd, or its local/global parts) tabulated for the kernels;
// layout and interpolation match kernels/tsis_shared.h and kernels/profile.h
// (docs/design.md §2, "Profiles on the device").
#pragma once

#include <functional>
#include <glm/vec3.hpp>
#include <vector>

#include "tsis_shared.h"

namespace tsis {

struct ProfileTable {
    TsisTableInfo info{};
    std::vector<float> rgba;  // TSIS_TABLE_SIZE entries × 4 floats

    // Samples f at TSIS_TABLE_SIZE points over [0, rMax].
    static ProfileTable build(const std::function<glm::dvec3(double r)>& f, double rMax);

    // The value the kernels compute at r (same float arithmetic).
    glm::vec3 lookup(float r) const;
};

}  // namespace tsis
