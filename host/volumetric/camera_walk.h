// The radiance a camera sees leaving the object at a surface point, by a
// random walk from the camera into the medium (a path tracer with next-event
// estimation through the refracting boundary, render/method_volumetric.h).
#pragma once

#include <functional>
#include <glm/vec3.hpp>
#include <limits>
#include <vector>

#include "scene/scene.h"
#include "volumetric/boundary.h"
#include "volumetric/medium.h"
#include "volumetric/rng.h"

namespace tsis {

struct WalkScene {
    const Boundary* boundary = nullptr;
    Medium medium;
    std::vector<Light> lights;
    // Uniform sky radiance around the object (W/(mm²·sr)); for the validation
    // scenes that Mitsuba renders too. Zero in tsis' scenes.
    glm::dvec3 sky{0.0};
    // Radiance arriving from direction d (unit, from the object outwards), on
    // top of the sky, read by paths that leave the object where the object
    // does not hide it (the sky is not hidden); empty for none.
    std::function<glm::dvec3(const glm::dvec3& d)> environment;
    // Scattering orders summed: paths end after this many scatterings (after
    // the last one's next-event estimation, and its leaving into the sky or
    // the environment); 1 = single scattering.
    int maxScatterings = std::numeric_limits<int>::max();
    // The first order summed: a scattering below it connects to nothing and a
    // path that leaves with fewer reads no sky (1: without the environment
    // seen straight through the object, refracted, which no subsurface model
    // makes; 2: multiple scattering alone).
    int minScatterings = 0;
};

struct WalkCounters {
    long long vertices = 0;      // scattering vertices
    long long nee = 0;           // next-event estimations attempted (after roulette)
    long long neeUnsettled = 0;  // of those, the entry point not found (refracted_light.h)
};

// Radiance leaving surface point `hit` towards the unit direction `toEye`
// (n·toEye > 0), excluding the specular reflection of the surroundings (as the
// dipole methods do): Ft(η, cosθo)/η² × the radiance arriving at hit from
// inside along the refracted camera ray. One sample; unbiased apart from the
// light paths refracted_light.h misses.
glm::dvec3 exitantRadiance(const WalkScene& scene, const SurfaceHit& hit, const glm::dvec3& toEye,
                           Rng& rng, WalkCounters& counters);

}  // namespace tsis
