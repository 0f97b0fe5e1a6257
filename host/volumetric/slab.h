// Light tracing in the semi-infinite slab (boundary.h's HalfSpace): a pencil
// beam enters at the origin at normal incidence and random-walks until it
// leaves through the surface (Fresnel chosen stochastically at each hit from
// inside) or is absorbed; what leaves is tallied per unit flux that entered —
// the quantities the dipole's ∫Rd 2πr dr and Rd(r) predict.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "volumetric/medium.h"

namespace tsis {

struct SlabOptions {
    long long photons = 100000;
    uint64_t seed = 1;
    // Radial bins per channel, log-spaced in r/ℓ (ℓ = 1/σt the channel's mean
    // free path) from minMfp to maxMfp.
    int binsPerDecade = 10;
    double minMfp = 0.01, maxMfp = 100;
    // Half-angle of the cone around the normal (outside) for normalRadiance.
    double coneDegrees = 10;
    // When set, a progress line (util/progress.h) under this label.
    const char* progressLabel = nullptr;
};

struct SlabResult {
    glm::dvec3 reflectance{0.0}, reflectanceError{0.0};  // mean and its standard error
    std::vector<double> edges;                           // bin edges, in mean free paths
    std::vector<glm::dvec3> binFlux;                     // flux fraction leaving per annulus
    // binFlux's standard error, from the spread of the 4096-photon batches
    // (batch means: the photons' weights vary, so counts alone would not do).
    std::vector<glm::dvec3> binFluxError;
    // Radiance leaving within the cone per unit entered flux and unit irradiance
    // (flux in the cone / (π sin²θ)): the slab's normal-view radiance under a
    // normally incident directional light, per transmitted irradiance.
    glm::dvec3 normalRadiance{0.0}, normalRadianceError{0.0};
    double meanEvents = 0;  // scattering events per photon

    // Rd(r) of a channel from its bin around r mm: the bin's flux over its area.
    double profile(int channel, double rMm, const Medium& m) const;
};

SlabResult traceSlab(const Medium& medium, const SlabOptions& options);

}  // namespace tsis
