// The light-side estimator of the volumetric problem (camera_walk.h is the
// camera side): photons from each light refract into the medium and random-
// walk; every scattering vertex is connected to the pinhole through the
// boundary (refracted_light.h's connections, the eye as the source), and
// adds its radiance to the pixel each connection's exit point falls in.
//
// A vertex x scattering power J = β·(1/4π)·e^(−σt·d) per steradian towards
// the exit point y puts L = J·E_eye(x)/(η²·Ωpix) into that pixel, where
// E_eye(x) is the irradiance at x of a unit-intensity source at the eye
// through y (Fresnel included) and Ωpix the pixel's solid angle: étendue
// η²·dA⊥·dΩx = dA_eye·dΩeye carries the flux J·Ft·dΩx into the aperture.
// It estimates each pixel's mean radiance (the camera walk: at the pixel's
// centre), unbiased for the paths it samples and missing what the
// connection misses (refracted_light.h).
#pragma once

#include <cstdint>
#include <functional>
#include <glm/vec3.hpp>
#include <vector>

#include "volumetric/camera_walk.h"

namespace tsis {

// A pinhole camera: its position, orientation and vertical field of view,
// and an image of width × height square pixels.
struct Pinhole {
    glm::dvec3 eye{0.0}, target{0.0}, up{0.0, 1.0, 0.0};
    double fovYDegrees = 40.0;
    int width = 64, height = 64;
};

// Where a connection's radiance goes: the pixel y·width + x (row 0 at the
// top) and the radiance estimate (per photon traced).
using RadianceSink = std::function<void(int pixel, const glm::dvec3& radiance)>;

// Traces photons first … first + photons − 1 from each light of `scene`
// (point lights into the cone around the object's bounding sphere,
// directional ones through its disc; `boundingRadius` bounds the object
// around the origin) and hands every connection's radiance to `add`, in the
// order traced: a pixel's estimate is the sum of what it was handed divided
// by the number of photons traced. Photon i uses Rng(seed, i).
void traceLight(const WalkScene& scene, const Pinhole& camera, double boundingRadius,
                uint64_t first, uint64_t photons, uint64_t seed, const RadianceSink& add,
                WalkCounters& counters);

// The same into an image: radiance[pixel] += what the photons give, divided
// by `totalPhotons`.
void traceLight(const WalkScene& scene, const Pinhole& camera, double boundingRadius,
                uint64_t first, uint64_t photons, uint64_t totalPhotons, uint64_t seed,
                std::vector<glm::dvec3>& radiance, WalkCounters& counters);

}  // namespace tsis
