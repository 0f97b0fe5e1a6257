// Photon beam diffusion (Habel, Christensen and Jarosz, "Photon Beam
// Diffusion: A Hybrid Monte Carlo Method for Subsurface Scattering", 2013;
// --profile pbd, docs/design.md §2 "Profile models"),
// tabulated as pbrt-v3 does (ComputeBeamDiffusionBSSRDF): the profile of a
// beam entering straight down, for σt′ = 1, over albedos ρ and optical radii;
// any σt′ by Rd(r) = σt′² Rd₁(σt′ r). Isotropic phase (σs = σs′).
//  * Multiple scattering: the better dipole's point source
//    (physics/better_dipole.h) at depths z along the beam, stratified by the
//    beam's attenuation e^(−σt′z), each weighted by ρ′² and by Habel's
//    κ = 1 − e^(−2σt′(dr + z)) that damps sources nearer than a free path.
//  * Single scattering: ∫ ρσt e^(−σt t) e^(−σt d)/(4π d²) Ft(μ) μ dt along the
//    beam (d = √(r² + t²), μ = t/d), from the critical depth r√(η² − 1) on.
// Rd is the flux leaving into air (use the normalised exit term, as pbrt).
#pragma once

#include <glm/vec3.hpp>
#include <memory>
#include <vector>

#include "physics/material.h"

namespace tsis {

struct BetterDipoleChannel;

// Multiple scattering of the medium of `dipole` at r, over `samples` depths.
double beamDiffusionMS(const BetterDipoleChannel& dipole, double r, int samples = 100);
// Single scattering at r for σt = 1 and albedo rho (r in mean free paths).
double beamDiffusionSS(double rho, double eta, double r, int samples = 100);

class BeamDiffusionTable {
  public:
    explicit BeamDiffusionTable(double eta);
    // SS + MS at (rho, r) by Catmull-Rom in both (of 2πr·Rd/ρ, smooth at
    // r = 0 and ρ = 0);
    // below the first radius it holds, that radius' value; past the last, 0.
    double Rd(double rho, double r) const;
    double eta() const { return eta_; }

  private:
    double eta_;
    std::vector<double> rho_, radius_, profile_;  // profile_: 2πr·Rd/ρ, rho-major
};

// One table per η, built on first use and kept for the process.
std::shared_ptr<const BeamDiffusionTable> beamDiffusionTable(double eta);

// The three bands of a material.
struct BeamDiffusion {
    explicit BeamDiffusion(const Material& m);
    glm::dvec3 Rd(double r) const;  // mm⁻²

    std::shared_ptr<const BeamDiffusionTable> table;
    glm::dvec3 rho, sigmaT;
};

}  // namespace tsis
