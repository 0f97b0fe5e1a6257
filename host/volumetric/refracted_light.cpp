#include "volumetric/refracted_light.h"

#include <cmath>
#include <glm/geometric.hpp>

#include "physics/fresnel.h"
#include "volumetric/dielectric.h"

namespace tsis {

namespace {

// Facets tried before giving up: on smooth meshes the iteration settles in 1–3.
constexpr int kMaxFacetIterations = 32;

}  // namespace

double solveRefractionSine(double h1, double h2, double d, double eta) {
    auto rho = [&](double s) {
        const double st = s / eta;
        return h1 * s / std::sqrt(1.0 - s * s) + h2 * st / std::sqrt(1.0 - st * st);
    };
    double lo = 0.0, hi = 1.0;
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (rho(mid) < d ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

double pointRefractedSpreading(double h1, double h2, double cosI, double cosT, double eta) {
    const double rhoOverSin = h1 / cosI + h2 / (eta * cosT);
    const double dRho = h1 / (cosI * cosI) + h2 * cosI / (eta * cosT * cosT * cosT);
    return rhoOverSin * cosT * dRho;
}

LightPath refractedLight(const Boundary& boundary, const Light& light, double eta,
                         const glm::dvec3& x, RefractedLight& out, const SurfaceHit* straight) {
    const bool point = light.type == Light::Type::Point;
    const glm::dvec3 lightPos(light.vec);
    const glm::dvec3 travel = point ? glm::dvec3(0.0) : glm::normalize(glm::dvec3(light.vec));
    const double eps = boundary.epsilon();
    SurfaceHit facet;
    if (straight) {
        facet = *straight;
    } else {
        const glm::dvec3 towardLight = point ? glm::normalize(lightPos - x) : -travel;
        if (!boundary.intersect(x, towardLight, kInfinity, facet)) return LightPath::Blocked;
    }
    for (int iter = 0; iter < kMaxFacetIterations; ++iter) {
        const glm::dvec3 n = facet.normal;
        const double h2 = glm::dot(facet.position - x, n);  // depth of x below the plane
        if (h2 <= 0) return LightPath::Unsettled;
        glm::dvec3 y;
        double cosI, cosT;
        if (point) {
            const double h1 = glm::dot(lightPos - facet.position, n);
            if (h1 <= 0) return LightPath::Blocked;  // the light is behind this facet's plane
            const glm::dvec3 foot = lightPos - h1 * n, xOnPlane = x + h2 * n;
            const glm::dvec3 across = xOnPlane - foot;
            const double d = glm::length(across);
            const double s = solveRefractionSine(h1, h2, d, eta);
            cosI = std::sqrt(1.0 - s * s);
            cosT = std::sqrt(1.0 - s * s / (eta * eta));
            y = d > 0 ? foot + across * (h1 * s / (cosI * d)) : foot;
        } else {
            cosI = -glm::dot(travel, n);
            if (cosI <= 0) return LightPath::Blocked;
            glm::dvec3 t;
            refract(travel, n, eta, t);
            cosT = -glm::dot(t, n);
            y = x - t * (h2 / cosT);
        }
        // Is y where the ray from x towards it leaves the object?
        const glm::dvec3 toY = y - x;
        const double dist = glm::length(toY);
        SurfaceHit next;
        if (!boundary.intersect(x, toY / dist, kInfinity, next)) return LightPath::Unsettled;
        if (!(samePlane(next, facet, eps * 10) &&
              std::abs(next.t - dist) < eps * 10 + 1e-7 * dist)) {
            facet = next;
            continue;
        }
        // Shadow ray outside, from just above y to the light.
        const glm::dvec3 above = next.position + n * eps;
        const glm::dvec3 toLight = point ? lightPos - above : -travel;
        const double lightDist = point ? glm::length(toLight) : kInfinity;
        SurfaceHit blocker;
        if (boundary.intersect(above, toLight / (point ? lightDist : 1.0), lightDist, blocker))
            return LightPath::Blocked;
        const double ft = fresnelTransmittance(eta, cosI);
        const double spread =
            point ? 1.0 / pointRefractedSpreading(glm::dot(lightPos - y, n), h2, cosI, cosT, eta)
                  : cosI / cosT;
        out.entry = next.position;
        out.distance = dist;
        out.irradiance = glm::dvec3(light.rgb) * (ft * spread);
        return LightPath::Reached;
    }
    return LightPath::Unsettled;
}

}  // namespace tsis
