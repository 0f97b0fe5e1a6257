#include "physics/profile_table.h"

#include <cmath>

#include "util/error.h"

namespace tsis {

ProfileTable ProfileTable::build(const std::function<glm::dvec3(double r)>& f, double rMax) {
    TSIS_CHECK(std::isfinite(rMax) && rMax > 0.0);
    ProfileTable t;
    t.info.r_max = static_cast<float>(rMax);
    t.info.inv_step = static_cast<float>((TSIS_TABLE_SIZE - 1) / rMax);
    t.info.size = TSIS_TABLE_SIZE;
    t.rgba.resize(4 * TSIS_TABLE_SIZE);
    for (int k = 0; k < TSIS_TABLE_SIZE; ++k) {
        const glm::dvec3 v = f(k * rMax / (TSIS_TABLE_SIZE - 1));
        for (int c = 0; c < 3; ++c) t.rgba[4 * k + c] = static_cast<float>(v[c]);
        t.rgba[4 * k + 3] = 0.0f;
    }
    return t;
}

glm::vec3 ProfileTable::lookup(float r) const {
    // Mirrors the kernels step by step, in float, so host tests see kernel values.
    const float x = r * info.inv_step;
    if (!(x < info.size - 1)) return glm::vec3(0.0f);  // at/after r_max, or NaN
    // Distances are never negative; the kernels would read before the table.
    TSIS_CHECK_GE(x, 0.0f);
    const int i = static_cast<int>(x);
    const float t = x - i;
    const float* a = &rgba[4 * i];
    const float* b = a + 4;
    return {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
}

}  // namespace tsis
