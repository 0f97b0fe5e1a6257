#include "volumetric/dielectric.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace tsis {

glm::dvec3 reflect(const glm::dvec3& d, const glm::dvec3& n) {
    return d - 2.0 * glm::dot(d, n) * n;
}

bool refract(const glm::dvec3& d, const glm::dvec3& n, double eta, glm::dvec3& out) {
    const double cosI = -glm::dot(d, n);
    const double sin2T = std::max(0.0, 1.0 - cosI * cosI) / (eta * eta);
    if (sin2T >= 1.0) return false;
    const double cosT = std::sqrt(1.0 - sin2T);
    out = glm::normalize(d / eta + (cosI / eta - cosT) * n);
    return true;
}

glm::dvec3 uniformSphere(double u1, double u2) {
    const double z = 1.0 - 2.0 * u1;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = 2.0 * M_PI * u2;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

}  // namespace tsis
