#include "volumetric/camera_walk.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "physics/fresnel.h"
#include "volumetric/dielectric.h"
#include "volumetric/refracted_light.h"
#include "volumetric/walk_steps.h"

namespace tsis {

namespace {

// Paths are cut after this many events (a bias far below the noise: at
// albedo 0.9995, marble's highest, e^(−100000·0.0005) of the weight is left).
constexpr int kMaxEvents = 100000;

// Next-event estimation only pays where light from the surface reaches x:
// beyond ~5 mean free paths below the nearest facet towards the light it is
// done with probability 100·e^(−σt·depth) (at least 2%) and weighted by the
// inverse (unbiased; the depth is a heuristic, not a bound).
double neeProbability(const Medium& m, double depth) {
    const double sigma = std::min({m.sigmaT.x, m.sigmaT.y, m.sigmaT.z});
    return std::clamp(100.0 * std::exp(-sigma * depth), 0.02, 1.0);
}

}  // namespace

glm::dvec3 exitantRadiance(const WalkScene& scene, const SurfaceHit& hit, const glm::dvec3& toEye,
                           Rng& rng, WalkCounters& counters) {
    const Medium& m = scene.medium;
    const Boundary& boundary = *scene.boundary;
    const double eps = boundary.epsilon();
    const double cosO = glm::dot(toEye, hit.normal);
    if (cosO <= 0) return glm::dvec3(0.0);
    glm::dvec3 dir;
    refract(-toEye, hit.normal, m.eta, dir);
    SpectralWeight w(rng);
    // Radiance leaving through the boundary: Ft and the n² scaling of radiance.
    w.scale(glm::dvec3(fresnelTransmittance(m.eta, cosO) / (m.eta * m.eta)));
    glm::dvec3 pos = hit.position - hit.normal * eps;
    glm::dvec3 radiance(0.0);
    constexpr double kPhase = 1.0 / (4.0 * M_PI);
    const bool escapes = scene.environment || scene.sky != glm::dvec3(0.0);
    int scatterings = 0;
    for (int event = 0; event < kMaxEvents; ++event) {
        SurfaceHit surface;
        const bool bounded = boundary.intersect(pos, dir, kInfinity, surface);
        const FreeFlight flight = sampleFreeFlight(m, bounded ? surface.t : kInfinity, w, rng);
        if (flight.scattered) {
            // Past the last order summed: the rest of the path is of higher ones.
            if (scatterings == scene.maxScatterings) break;
            pos += dir * flight.t;
            ++counters.vertices;
            for (const Light& light : scene.lights) {
                // The roulette's depth: below the facet straight towards the light.
                const glm::dvec3 toward = light.type == Light::Type::Point
                                              ? glm::normalize(glm::dvec3(light.vec) - pos)
                                              : -glm::normalize(glm::dvec3(light.vec));
                SurfaceHit straight;
                if (!boundary.intersect(pos, toward, kInfinity, straight)) continue;
                const double q =
                    neeProbability(m, glm::dot(straight.position - pos, straight.normal));
                if (rng.uniform() >= q) continue;
                // An order below the first summed draws what it would have
                // (a path's orders split exactly between two ranges).
                if (scatterings + 1 < scene.minScatterings) continue;
                ++counters.nee;
                RefractedLights in;
                const LightPath path = refractedLights(boundary, light, m.eta, pos, in, &straight);
                counters.neeUnsettled += path == LightPath::Unsettled;
                for (int k = 0; k < in.count; ++k)
                    radiance += w.value() * kPhase * in.paths[k].irradiance *
                                transmittance(m, in.paths[k].distance) / q;
            }
            // The last order summed also leaves into the sky; with none, it ends here.
            if (++scatterings == scene.maxScatterings && !escapes) break;
            const glm::dvec3 v = w.value();
            if (!survivesRoulette(w, std::max({v.x, v.y, v.z}), rng)) break;
            const double u1 = rng.uniform(), u2 = rng.uniform();
            dir = uniformSphere(u1, u2);
            continue;
        }
        if (!bounded) break;  // an open mesh: the walk left through a hole
        if (reflectsInside(m, surface, eps, dir, pos, rng)) continue;
        if (scatterings < scene.minScatterings) break;
        glm::dvec3 sky = scene.sky;
        if (scene.environment) {
            glm::dvec3 out;
            refract(dir, -surface.normal, 1.0 / m.eta, out);
            // Only where the object does not hide it (V, as the dipole methods' E has it).
            SurfaceHit again;
            if (!boundary.intersect(surface.position + surface.normal * eps, out, kInfinity, again))
                sky += scene.environment(out);
        }
        radiance += w.value() * (m.eta * m.eta) * sky;
        break;
    }
    return radiance;
}

}  // namespace tsis
