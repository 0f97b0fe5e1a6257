#include "volumetric/boundary.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace tsis {

bool samePlane(const SurfaceHit& a, const SurfaceHit& b, double epsilon) {
    if (a.facet == b.facet) return true;
    return glm::dot(a.normal, b.normal) > 1.0 - 1e-9 &&
           std::abs(glm::dot(a.normal, b.position - a.position)) < epsilon;
}

bool HalfSpace::intersect(const glm::dvec3& origin, const glm::dvec3& dir, double tMax,
                          SurfaceHit& hit) const {
    // Crossing y = 0 from either side.
    if (dir.y == 0.0 || (origin.y < 0) == (dir.y < 0) || origin.y == 0.0) return false;
    const double t = -origin.y / dir.y;
    if (!(t > 0 && t < tMax)) return false;
    hit.t = t;
    hit.position = origin + t * dir;
    hit.position.y = 0.0;
    hit.normal = {0.0, 1.0, 0.0};
    hit.facet = 0;
    return true;
}

}  // namespace tsis
