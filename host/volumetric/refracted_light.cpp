#include "volumetric/refracted_light.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <unordered_set>
#include <vector>

#include "physics/fresnel.h"
#include "volumetric/dielectric.h"

namespace tsis {

namespace {

// Facets tried before giving up: on smooth meshes the iteration settles in 1–3.
constexpr int kMaxFacetIterations = 32;
// Facets the search around the settled one tests at most (a few rings).
constexpr int kMaxFacetsSearched = 512;

// Where light must enter the plane (point p, outward unit normal n) to reach
// x refracted once, with its cosines; false when it cannot from this plane.
struct PlaneEntry {
    glm::dvec3 y{0.0};
    double cosI = 0, cosT = 0, h2 = 0;
};

bool entryOnPlane(const Light& light, double eta, const glm::dvec3& x, const glm::dvec3& p,
                  const glm::dvec3& n, PlaneEntry& e) {
    e.h2 = glm::dot(p - x, n);  // depth of x below the plane
    if (e.h2 <= 0) return false;
    if (light.type == Light::Type::Point) {
        const glm::dvec3 lightPos(light.vec);
        const double h1 = glm::dot(lightPos - p, n);
        if (h1 <= 0) return false;  // the light is behind this plane
        const glm::dvec3 foot = lightPos - h1 * n, xOnPlane = x + e.h2 * n;
        const glm::dvec3 across = xOnPlane - foot;
        const double d = glm::length(across);
        const double s = solveRefractionSine(h1, e.h2, d, eta);
        e.cosI = std::sqrt(1.0 - s * s);
        e.cosT = std::sqrt(1.0 - s * s / (eta * eta));
        e.y = d > 0 ? foot + across * (h1 * s / (e.cosI * d)) : foot;
        return true;
    }
    const glm::dvec3 travel = glm::normalize(glm::dvec3(light.vec));
    e.cosI = -glm::dot(travel, n);
    if (e.cosI <= 0) return false;
    glm::dvec3 t;
    refract(travel, n, eta, t);
    e.cosT = -glm::dot(t, n);
    e.y = x - t * (e.h2 / e.cosT);
    return true;
}

// Does the ray from x towards the entry leave the object there, on `facet`'s
// plane? Fills the hit.
bool leavesAt(const Boundary& boundary, const glm::dvec3& x, const PlaneEntry& e,
              const SurfaceHit& facet, SurfaceHit& hit) {
    const glm::dvec3 toY = e.y - x;
    const double dist = glm::length(toY);
    const double eps = boundary.epsilon();
    return boundary.intersect(x, toY / dist, kInfinity, hit) && samePlane(hit, facet, eps * 10) &&
           std::abs(hit.t - dist) < eps * 10 + 1e-7 * dist;
}

// The light along the settled connection, or false when it is shadowed outside.
bool lightAlong(const Boundary& boundary, const Light& light, double eta, const glm::dvec3& x,
                const PlaneEntry& e, const SurfaceHit& at, RefractedLight& out) {
    const bool point = light.type == Light::Type::Point;
    const glm::dvec3 lightPos(light.vec);
    const glm::dvec3 n = at.normal;
    const glm::dvec3 above = at.position + n * boundary.epsilon();
    const glm::dvec3 toLight = point ? lightPos - above : -glm::normalize(glm::dvec3(light.vec));
    const double lightDist = point ? glm::length(toLight) : kInfinity;
    SurfaceHit blocker;
    if (boundary.intersect(above, toLight / (point ? lightDist : 1.0), lightDist, blocker))
        return false;
    const double ft = fresnelTransmittance(eta, e.cosI);
    const double spread = point ? 1.0 / pointRefractedSpreading(glm::dot(lightPos - e.y, n), e.h2,
                                                                e.cosI, e.cosT, eta)
                                : e.cosI / e.cosT;
    out.entry = at.position;
    out.distance = glm::length(at.position - x);
    out.irradiance = glm::dvec3(light.rgb) * (ft * spread);
    return true;
}

// Barycentric test of a point on the triangle's plane (edges included).
bool inTriangle(const glm::dvec3& y, const glm::dvec3 (&v)[3], const glm::dvec3& n) {
    for (int i = 0; i < 3; ++i)
        if (glm::dot(glm::cross(v[(i + 1) % 3] - v[i], y - v[i]), n) < 0) return false;
    return true;
}

// Whether facet g's own plane solution lies on it and is seen from x: its
// plane (`plane`), the solution (`entry`) and where the ray towards it
// leaves (`hit`).
bool facetConnects(const Boundary& boundary, const Light& light, double eta, const glm::dvec3& x,
                   int g, SurfaceHit& plane, PlaneEntry& entry, SurfaceHit& hit) {
    glm::dvec3 v[3], n;
    if (!boundary.facet(g, v, n)) return false;
    plane.position = v[0];
    plane.normal = n;
    plane.facet = g;
    return entryOnPlane(light, eta, x, v[0], n, entry) && inTriangle(entry.y, v, n) &&
           leavesAt(boundary, x, entry, plane, hit);
}

// Where the iteration cycles (a facet's solution lies on another whose
// solution lies back on the first: at grazing entry, where a small turn of
// the normal moves the solution far), the facets around `from` are searched
// breadth-first, nearest rings first, for one whose own solution lies on it
// and is seen from x.
constexpr size_t kMaxFacetsRescued = 256;
bool searchConnection(const Boundary& boundary, const Light& light, double eta, const glm::dvec3& x,
                      int from, PlaneEntry& entry, SurfaceHit& settled) {
    std::vector<int> queue{from};
    std::unordered_set<int> searched{from};
    for (size_t head = 0; head < queue.size() && queue.size() < kMaxFacetsRescued; ++head)
        for (int g : boundary.facetNeighbours(queue[head])) {
            if (!searched.insert(g).second) continue;
            queue.push_back(g);
            SurfaceHit plane;
            if (facetConnects(boundary, light, eta, x, g, plane, entry, settled)) return true;
        }
    return false;
}

}  // namespace

double solveRefractionSine(double h1, double h2, double d, double eta) {
    // ρ(s) − d is increasing and convex in s = sin θi: Newton's steps, kept
    // inside the bracket by bisection (a few steps where bisection took 60;
    // every next-event estimation solves it for several facets).
    double lo = 0.0, hi = 1.0, s = 0.5;
    for (int i = 0; i < 100; ++i) {
        const double st = s / eta;
        const double c = std::sqrt(1.0 - s * s), ct = std::sqrt(1.0 - st * st);
        const double f = h1 * s / c + h2 * st / ct - d;
        (f < 0 ? lo : hi) = s;
        const double slope = h1 / (c * c * c) + h2 / (eta * ct * ct * ct);
        double next = s - f / slope;
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (std::abs(next - s) < 1e-15 || hi - lo < 1e-15) return next;
        s = next;
    }
    return s;
}

double pointRefractedSpreading(double h1, double h2, double cosI, double cosT, double eta) {
    const double rhoOverSin = h1 / cosI + h2 / (eta * cosT);
    const double dRho = h1 / (cosI * cosI) + h2 * cosI / (eta * cosT * cosT * cosT);
    return rhoOverSin * cosT * dRho;
}

LightPath refractedLights(const Boundary& boundary, const Light& light, double eta,
                          const glm::dvec3& x, RefractedLights& out, const SurfaceHit* straight) {
    out.count = 0;
    SurfaceHit facet;
    if (straight) {
        facet = *straight;
    } else {
        const glm::dvec3 towardLight = light.type == Light::Type::Point
                                           ? glm::normalize(glm::dvec3(light.vec) - x)
                                           : -glm::normalize(glm::dvec3(light.vec));
        if (!boundary.intersect(x, towardLight, kInfinity, facet)) return LightPath::Blocked;
    }
    // Settle on one connection: cast from x towards the solution on the facet
    // hit, take the facet that ray hits, until it is the same plane.
    PlaneEntry entry;
    SurfaceHit settled;
    bool found = false;
    for (int iter = 0; iter < kMaxFacetIterations; ++iter) {
        if (!entryOnPlane(light, eta, x, facet.position, facet.normal, entry)) {
            if (entry.h2 <= 0) return LightPath::Unsettled;
            return LightPath::Blocked;
        }
        SurfaceHit next;
        if (leavesAt(boundary, x, entry, facet, next)) {
            settled = next;
            found = true;
            break;
        }
        if (!boundary.intersect(x, glm::normalize(entry.y - x), kInfinity, next))
            return LightPath::Unsettled;
        facet = next;
    }
    if (!found && !searchConnection(boundary, light, eta, x, facet.facet, entry, settled))
        return LightPath::Unsettled;
    if (lightAlong(boundary, light, eta, x, entry, settled, out.paths[0])) out.count = 1;

    // Other facets whose refracted beams reach x too: on a convex part the
    // beams of neighbouring facets overlap (the faceted form of the surface's
    // focusing), so every facet around the settled one whose own solution lies
    // on it and is seen from x adds its light. Searched breadth-first over
    // facets sharing a vertex, expanding only from facets that connect.
    glm::dvec3 v[3], n;
    if (!boundary.facet(settled.facet, v, n)) return LightPath::Reached;
    const double eps = boundary.epsilon() * 10;
    SurfaceHit planes[kMaxRefractedPaths];  // the planes connected so far
    int nPlanes = 0;
    planes[nPlanes++] = settled;
    int searched[kMaxFacetsSearched];
    int queue[kMaxFacetsSearched];
    int nSearched = 0, head = 0, tail = 0;
    searched[nSearched++] = settled.facet;
    queue[tail++] = settled.facet;
    auto seen = [&](int f) {
        return std::find(searched, searched + nSearched, f) != searched + nSearched;
    };
    while (head < tail) {
        for (int g : boundary.facetNeighbours(queue[head++])) {
            if (seen(g)) continue;
            if (nSearched == kMaxFacetsSearched) return LightPath::Reached;
            searched[nSearched++] = g;
            SurfaceHit plane, hit;
            PlaneEntry e;
            if (!facetConnects(boundary, light, eta, x, g, plane, e, hit)) continue;
            if (tail < kMaxFacetsSearched) queue[tail++] = g;
            // Coplanar facets share one solution: one connection per plane.
            if (std::any_of(planes, planes + nPlanes,
                            [&](const SurfaceHit& p) { return samePlane(p, plane, eps); }) ||
                nPlanes == kMaxRefractedPaths)
                continue;
            planes[nPlanes++] = plane;
            if (lightAlong(boundary, light, eta, x, e, hit, out.paths[out.count])) ++out.count;
        }
    }
    return LightPath::Reached;
}

}  // namespace tsis
