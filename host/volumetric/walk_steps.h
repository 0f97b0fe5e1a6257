// The steps the camera walk (camera_walk.h) and the light tracer
// (light_trace.h) share inside the medium.
#pragma once

#include <glm/vec3.hpp>

#include "volumetric/boundary.h"
#include "volumetric/medium.h"
#include "volumetric/rng.h"

namespace tsis {

// Russian roulette: a path whose strength (its weight over its start's) fell
// below 0.05 survives with probability strength / 0.05 and is weighted up by
// its inverse. False: the path ends.
bool survivesRoulette(SpectralWeight& w, double strength, Rng& rng);

// At the boundary from inside (dir · n > 0 when leaving): reflect with the
// Fresnel probability Fr(1/η), moving dir and pos off the surface. False: the
// path leaves through `surface` (dir unchanged).
bool reflectsInside(const Medium& m, const SurfaceHit& surface, double eps, glm::dvec3& dir,
                    glm::dvec3& pos, Rng& rng);

}  // namespace tsis
