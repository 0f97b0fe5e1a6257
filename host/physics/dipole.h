// The dipole diffusion profile Rd(r) of Jensen et al. 2001 (docs/design.md §2), in
// double precision: the exact function the kernels' tables are checked against.
#pragma once

#include <array>
#include <glm/vec3.hpp>

#include "physics/material.h"

namespace tsis {

// One wavelength band.
struct DipoleChannel {
    DipoleChannel(double sigmaSPrime, double sigmaA, double eta);

    double Rd(double r) const;                                 // mm⁻²
    double totalReflectance() const;                           // closed-form ∫ Rd 2πr dr
    double meanFreePath() const { return 1.0 / sigmaTPrime; }  // ℓ = 1/σt' (mm)

    double sigmaSPrime, sigmaA, eta;
    double sigmaTPrime, alphaPrime, sigmaTr, Fdr, A, zr, zv;
};

// Fdr of docs/design.md §2 (Groenhuis' fit).
double diffuseFresnelReflectance(double eta);

struct Dipole {
    explicit Dipole(const Material& m);
    glm::dvec3 Rd(double r) const;
    glm::dvec3 totalReflectance() const;
    glm::dvec3 sigmaTr() const;
    glm::dvec3 meanFreePath() const;
    std::array<DipoleChannel, 3> ch;
};

}  // namespace tsis
