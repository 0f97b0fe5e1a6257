// The homogeneous medium inside the object (docs/design.md §2's units: mm, mm⁻¹),
// and the path weight of random walks through it.
//
// The medium scatters isotropically with σs = σs′: the dipole itself rests on
// the similarity relation σs′ = σs(1 − g), so an isotropic medium with σs′ is
// the volumetric problem the dipole approximates.
#pragma once

#include <glm/vec3.hpp>

#include "physics/material.h"
#include "volumetric/rng.h"

namespace tsis {

struct Medium {
    explicit Medium(const Material& m);
    glm::dvec3 sigmaS, sigmaA, sigmaT;
    double eta;
};

// Throughput of a path whose distances are drawn with one "hero" channel's
// σt: the one-sample balance heuristic over the three channels' samplers
// (hero-wavelength spectral MIS, Wilkie et al. 2014, as Mitsuba 3's volpath).
// beta = f / p_hero and ratio_k = p_k / p_hero; value() = f / mean_k p_k, so
// no channel's weight exceeds 3× what a walk sampled with its own σt gives,
// however different the channels' σt.
class SpectralWeight {
  public:
    explicit SpectralWeight(Rng& rng);
    int hero() const { return hero_; }
    // A deterministic factor (Fresnel, radiance scaling, Russian roulette).
    void scale(const glm::dvec3& f) { beta_ *= f; }
    // A sampled event: its contribution f and each channel's pdf of it.
    void sampled(const glm::dvec3& f, const glm::dvec3& pdf);
    glm::dvec3 value() const;

  private:
    glm::dvec3 beta_{1.0}, ratio_{1.0};
    int hero_;
};

// A free flight from the current vertex towards a surface `tSurface` away
// (infinity when there is none): scatters at distance t < tSurface, else
// reaches the surface. Updates the weight with σs·Tr (scattering) or Tr
// (surface) over the channels' pdfs.
struct FreeFlight {
    double t;
    bool scattered;
};
FreeFlight sampleFreeFlight(const Medium& m, double tSurface, SpectralWeight& w, Rng& rng);

// Transmittance e^(−σt·d) per channel.
glm::dvec3 transmittance(const Medium& m, double d);

}  // namespace tsis
