#include "volumetric/light_trace.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "physics/fresnel.h"
#include "volumetric/dielectric.h"
#include "volumetric/refracted_light.h"
#include "volumetric/walk_steps.h"

namespace tsis {

namespace {

// As the camera walk's (camera_walk.cpp).
constexpr int kMaxEvents = 100000;
constexpr double kPhase = 1.0 / (4.0 * M_PI);

// Where a direction from the eye lands on the image, and the solid angle of
// that pixel.
struct ImageFrame {
    explicit ImageFrame(const Pinhole& c)
        : eye(c.eye),
          forward(glm::normalize(c.target - c.eye)),
          right(glm::normalize(glm::cross(forward, c.up))),
          up(glm::cross(right, forward)),
          tanHalf(std::tan(c.fovYDegrees * M_PI / 360.0)),
          aspect(static_cast<double>(c.width) / c.height),
          width(c.width),
          height(c.height) {}

    // Pixel index of direction d (unit), or −1 off the image; its solid angle.
    int pixel(const glm::dvec3& d, double& solidAngle) const {
        const double z = glm::dot(d, forward);
        if (z <= 0) return -1;
        const double x = glm::dot(d, right) / z / (tanHalf * aspect);
        const double y = glm::dot(d, up) / z / tanHalf;
        const int px = static_cast<int>(std::floor((x + 1.0) * 0.5 * width));
        const int py = static_cast<int>(std::floor((1.0 - y) * 0.5 * height));
        if (px < 0 || px >= width || py < 0 || py >= height) return -1;
        const double pitch = 2.0 * tanHalf / height;  // on the plane at distance 1
        solidAngle = pitch * pitch * z * z * z;
        return py * width + px;
    }

    glm::dvec3 eye, forward, right, up;
    double tanHalf, aspect;
    int width, height;
};

// A photon's first hit: from the light towards the object, with the power
// it carries (W) and its direction.
struct Emission {
    glm::dvec3 origin{0.0}, dir{0.0}, power{0.0};
};

// The unit vector at angle phi around the unit `axis`, across it.
glm::dvec3 across(const glm::dvec3& axis, double phi) {
    const glm::dvec3 t1 = glm::normalize(
        glm::cross(axis, std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
    const glm::dvec3 t2 = glm::cross(axis, t1);
    return std::cos(phi) * t1 + std::sin(phi) * t2;
}

Emission emit(const Light& light, double radius, Rng& rng) {
    Emission e;
    const double u1 = rng.uniform(), u2 = rng.uniform();
    const double phi = 2.0 * M_PI * u2;
    if (light.type == Light::Type::Point) {
        // Uniform in the cone around the object's bounding sphere.
        e.origin = glm::dvec3(light.vec);
        const double dist = glm::length(e.origin);
        const double cosMax =
            dist > radius ? std::sqrt(1.0 - radius * radius / (dist * dist)) : -1.0;
        const double cosT = 1.0 - u1 * (1.0 - cosMax), sinT = std::sqrt(1.0 - cosT * cosT);
        const glm::dvec3 axis = dist > 0 ? -e.origin / dist : glm::dvec3(0, 0, -1);
        e.dir = cosT * axis + sinT * across(axis, phi);
        e.power = glm::dvec3(light.rgb) * (2.0 * M_PI * (1.0 - cosMax));
        return e;
    }
    // Uniform over the bounding sphere's disc across the light's direction.
    e.dir = glm::normalize(glm::dvec3(light.vec));
    const double r = radius * std::sqrt(u1);
    e.origin = -e.dir * (2.0 * radius) + r * across(e.dir, phi);
    e.power = glm::dvec3(light.rgb) * (M_PI * radius * radius);
    return e;
}

}  // namespace

void traceLight(const WalkScene& scene, const Pinhole& camera, double boundingRadius,
                uint64_t first, uint64_t photons, uint64_t totalPhotons, uint64_t seed,
                std::vector<glm::dvec3>& radiance, WalkCounters& counters) {
    const double scale = 1.0 / static_cast<double>(totalPhotons);
    traceLight(
        scene, camera, boundingRadius, first, photons, seed,
        [&](int pixel, const glm::dvec3& l) { radiance[static_cast<size_t>(pixel)] += l * scale; },
        counters);
}

void traceLight(const WalkScene& scene, const Pinhole& camera, double boundingRadius,
                uint64_t first, uint64_t photons, uint64_t seed, const RadianceSink& add,
                WalkCounters& counters) {
    const Medium& m = scene.medium;
    const Boundary& boundary = *scene.boundary;
    const double eps = boundary.epsilon();
    const ImageFrame frame(camera);
    // The eye as a unit point source: its irradiance at x through the
    // boundary is E_eye(x).
    Light eye;
    eye.type = Light::Type::Point;
    eye.vec = glm::vec3(camera.eye);
    eye.rgb = glm::vec3(1.0f);
    const double scale = 1.0 / (m.eta * m.eta);
    for (const Light& light : scene.lights)
        for (uint64_t i = first; i < first + photons; ++i) {
            Rng rng(seed, i);
            const Emission e = emit(light, boundingRadius, rng);
            SurfaceHit hit;
            if (!boundary.intersect(e.origin, e.dir, kInfinity, hit)) continue;
            const double cosI = -glm::dot(e.dir, hit.normal);
            if (cosI <= 0) continue;
            glm::dvec3 dir;
            refract(e.dir, hit.normal, m.eta, dir);
            SpectralWeight w(rng);
            w.scale(e.power * fresnelTransmittance(m.eta, cosI));
            glm::dvec3 pos = hit.position - hit.normal * eps;
            int scatterings = 0;
            for (int event = 0; event < kMaxEvents; ++event) {
                SurfaceHit surface;
                const bool bounded = boundary.intersect(pos, dir, kInfinity, surface);
                const FreeFlight flight =
                    sampleFreeFlight(m, bounded ? surface.t : kInfinity, w, rng);
                if (flight.scattered) {
                    pos += dir * flight.t;
                    ++counters.vertices;
                    RefractedLights out;  // empty below the first order summed
                    if (scatterings + 1 >= scene.minScatterings) {
                        ++counters.nee;
                        counters.neeUnsettled +=
                            refractedLights(boundary, eye, m.eta, pos, out) == LightPath::Unsettled;
                    }
                    for (int k = 0; k < out.count; ++k) {
                        double solidAngle = 0;
                        const int p =
                            frame.pixel(glm::normalize(out.paths[k].entry - frame.eye), solidAngle);
                        if (p < 0) continue;
                        add(p, w.value() * kPhase * transmittance(m, out.paths[k].distance) *
                                   out.paths[k].irradiance * (scale / solidAngle));
                    }
                    if (++scatterings == scene.maxScatterings) break;
                    const glm::dvec3 v = w.value();
                    if (!survivesRoulette(w,
                                          std::max({v.x, v.y, v.z}) /
                                              std::max({e.power.x, e.power.y, e.power.z, 1e-300}),
                                          rng))
                        break;
                    const double u1 = rng.uniform(), u2 = rng.uniform();
                    dir = uniformSphere(u1, u2);
                    continue;
                }
                if (!bounded) break;
                if (reflectsInside(m, surface, eps, dir, pos, rng)) continue;
                break;  // left the object: a pinhole is never hit
            }
        }
}

}  // namespace tsis
