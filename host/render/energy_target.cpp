#include "render/energy_target.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>

#include "physics/dipole.h"
#include "render/profiles.h"

namespace tsis {

glm::dvec3 finiteEscapeFraction(const Material& m, double volumeToArea) {
    const double meanPath = 4.0 * m.eta * m.eta * volumeToArea;
    return glm::max(glm::dvec3(1.0) - m.sigmaA * meanPath, glm::dvec3(0.0));
}

glm::dvec3 profileTotalReflectance(const Material& m, ProfileModel model) {
    // ∫ f(r) 2πr dr = ∫ f(e^u) 2π e^(2u) du over u, from far inside the
    // first mean free path to far beyond the diffusion length (the profile
    // falls as e^(−σtr·r)); the midpoint rule in u.
    const RadialProfile f = radialProfile(m, model).f;
    const glm::dvec3 tr = Dipole(m).sigmaTr();
    const double ell = 1.0 / std::max({m.sigmaSPrime.x + m.sigmaA.x, m.sigmaSPrime.y + m.sigmaA.y,
                                       m.sigmaSPrime.z + m.sigmaA.z});
    const double lo = std::log(1e-6 * ell), hi = std::log(60.0 / std::min({tr.x, tr.y, tr.z}));
    const int n = 20000;
    const double du = (hi - lo) / n;
    glm::dvec3 sum(0.0);
    for (int i = 0; i < n; ++i) {
        const double r = std::exp(lo + (i + 0.5) * du);
        sum += f(r) * (2.0 * M_PI * r * r);
    }
    return sum * du;
}

glm::dvec3 energyScale(const Material& m, ProfileModel model, double volumeToArea) {
    return glm::max(glm::dvec3(1.0),
                    finiteEscapeFraction(m, volumeToArea) / profileTotalReflectance(m, model));
}

}  // namespace tsis
