#include "render/ring_pattern.h"

#include <cmath>
#include <numbers>

#include "util/error.h"

namespace tsis {

RingPattern RingPattern::build(const RadialImportance& importance, const ProfileTable& table,
                               int rings, int perRing) {
    TSIS_CHECK_GE(rings, 0);
    TSIS_CHECK_GE(perRing, 1);
    const double parts = static_cast<double>(rings) * perRing + 1.0;
    RingPattern p;
    double inner = 0.0;
    for (int k = 0; k <= rings; ++k) {
        // Ring k (k = 0: the centre disk) holds cdf (1 + (k−1)C, 1 + kC]/(LC+1).
        const int count = k == 0 ? 1 : perRing;
        const double outer =
            k == rings ? importance.rMax() : importance.inverse((1.0 + k * perRing) / parts);
        const double r = k == 0 ? 0.0 : importance.inverse((1.0 + (k - 0.5) * perRing) / parts);
        const glm::dvec3 sector = (importance.mass(outer) - importance.mass(inner)) / double(count);
        const glm::vec3 f = table.lookup(static_cast<float>(r));
        for (int m = 0; m < count; ++m) {
            const double angle = 2.0 * std::numbers::pi * (m + (k % 2) * 0.5) / count;
            TsisRingSample s{};
            s.dx = static_cast<float>(r * std::cos(angle));
            s.dy = static_cast<float>(r * std::sin(angle));
            s.r = static_cast<float>(r);
            // A channel whose profile is 0 at the sample cannot carry its sector.
            s.ar = f.x > 0.0f ? static_cast<float>(sector.x / f.x) : 0.0f;
            s.ag = f.y > 0.0f ? static_cast<float>(sector.y / f.y) : 0.0f;
            s.ab = f.z > 0.0f ? static_cast<float>(sector.z / f.z) : 0.0f;
            p.samples.push_back(s);
        }
        p.edges.push_back(outer);
        inner = outer;
    }
    return p;
}

glm::dvec3 RingPattern::planeIntegral(const ProfileTable& table) const {
    glm::dvec3 sum(0.0);
    for (const TsisRingSample& s : samples) {
        const glm::vec3 f = table.lookup(s.r);
        sum += glm::dvec3(s.ar * f.x, s.ag * f.y, s.ab * f.z);
    }
    return sum;
}

}  // namespace tsis
