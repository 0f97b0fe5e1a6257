// The hybrid's split of Rd into a local and a global part (docs/design.md §4, thesis
// §3.3.1): Rd = Rd·Wl + Rd·Wg, Wl + Wg = 1, the two equal at r = Rp.
#pragma once

#include <glm/vec3.hpp>

#include "physics/dipole.h"

namespace tsis {

// Rp: the largest r where the importance Rd(r)·2πr crosses lowerBound (> 0).
// If the importance never reaches the bound (a dark, absorbing channel such as
// ketchup blue), returns the r of its maximum instead, so that the local part
// still keeps the peak and the global part the tail.
double importanceRadius(const DipoleChannel& d, double lowerBound = 0.1);
glm::dvec3 importanceRadius(const Dipole& d, double lowerBound = 0.1);

// Wl(r): 1 − ½e^((r−Rp)K) for r ≤ Rp, ½e^(−(r−Rp)K) for r > Rp; K in mm⁻¹ (≥ 0).
double localWeight(double r, double Rp, double K);
inline double globalWeight(double r, double Rp, double K) {
    return 1.0 - localWeight(r, Rp, K);
}

// Per channel, for tabulating Rd·Wl and Rd·Wg.
glm::dvec3 localWeight(double r, const glm::dvec3& Rp, double K);
inline glm::dvec3 globalWeight(double r, const glm::dvec3& Rp, double K) {
    return 1.0 - localWeight(r, Rp, K);
}

}  // namespace tsis
