// Where a radial profile f (Rd, Rd·Wl, …) puts its mass on the plane: the
// importance f(r)·2πr of thesis 3.3.1, integrated per channel, and the
// distribution of distances the ltsm rings and the mis distance samples follow.
#pragma once

#include <glm/vec3.hpp>
#include <vector>

#include "render/profiles.h"

namespace tsis {

class RadialImportance {
  public:
    // Integrates f·2πr over [0, rMax] on a grid that is dense near r = 0, where
    // the dipole peaks (Simpson per cell).
    RadialImportance(const RadialProfile& f, double rMax, int cells = 16384);

    double rMax() const { return r_.back(); }
    // ∫ f_c 2πr dr per channel over [0, rMax], and over [0, r].
    glm::dvec3 mass() const { return cum_.back(); }
    glm::dvec3 mass(double r) const;

    // The distance distribution: the mean over channels of each channel's
    // normalised mass, so every channel's range gets its share of samples
    // whatever its magnitude. cdf(rMax) = 1; inverse(u) for u in the unit interval.
    double cdf(double r) const;
    double inverse(double u) const;
    // inverse(k / entries) for k = 0 … entries: `entries` equal-probability
    // intervals (a draw picks one uniformly and a radius linearly inside it).
    std::vector<float> inverseTable(int entries) const;

  private:
    std::vector<double> r_;        // cell edges
    std::vector<glm::dvec3> cum_;  // mass over [0, r_k]
    std::vector<double> mix_;      // mixture cdf at r_k
};

}  // namespace tsis
