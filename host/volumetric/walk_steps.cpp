#include "volumetric/walk_steps.h"

#include <cmath>
#include <glm/geometric.hpp>

#include "physics/fresnel.h"
#include "volumetric/dielectric.h"

namespace tsis {

namespace {

constexpr double kRouletteWeight = 0.05;

}  // namespace

bool survivesRoulette(SpectralWeight& w, double strength, Rng& rng) {
    if (strength >= kRouletteWeight) return true;
    const double survive = strength / kRouletteWeight;
    if (rng.uniform() >= survive) return false;
    w.scale(glm::dvec3(1.0 / survive));
    return true;
}

bool reflectsInside(const Medium& m, const SurfaceHit& surface, double eps, glm::dvec3& dir,
                    glm::dvec3& pos, Rng& rng) {
    const double cosI = glm::dot(dir, surface.normal);
    if (rng.uniform() >= fresnelReflectance(1.0 / m.eta, std::abs(cosI))) return false;
    dir = reflect(dir, surface.normal);
    pos = surface.position - surface.normal * (cosI > 0 ? eps : -eps);
    return true;
}

}  // namespace tsis
