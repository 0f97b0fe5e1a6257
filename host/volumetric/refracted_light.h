// Next-event estimation through the smooth boundary: the light that reaches an
// interior point x straight from the point y where it entered, refracted once.
//
// A point or directional light seen through a smooth dielectric cannot be
// connected to x by a straight shadow ray; the connection is the specular
// path light → y → x, which Snell's law fixes. On a flat facet it is solved
// in closed form (directional: the refracted direction is the facet's; point:
// one monotone equation in the angle of incidence), and the facet is found by
// iterating "cast from x towards the solution, take the facet hit" from the
// straight line towards the light. On a mesh this is exact for flat facets
// (the transport of the faceted mesh) once every facet whose beam covers x is
// found: from the settled facet the search walks the facets around it (below).
// Where the iteration cycles between facets (behind thin, curved parts lit
// near grazing), the 256 facets around the last one are searched for one that
// connects. It misses entry points that no iteration reaches nor search finds
// (a facet farther away, or none: a gap between facets' beams) and light
// reflected inside before x: see method_volumetric.h.
#pragma once

#include <glm/vec3.hpp>

#include "scene/scene.h"
#include "volumetric/boundary.h"

namespace tsis {

struct RefractedLight {
    glm::dvec3 entry{0.0};  // y, on the surface
    double distance = 0;    // |x − y|, inside the medium
    // Irradiance at x on a plane perpendicular to the refracted ray (W/mm²),
    // Fresnel transmittance at y included, before the medium's attenuation.
    glm::dvec3 irradiance{0.0};
};

enum class LightPath {
    Reached,    // `out` holds the connections' entry points and irradiances
    Blocked,    // no light: behind the facet
    Unsettled,  // the facet iteration did not settle (light missed: a bias)
};

// Every connection from the light to x: the iteration settles on one facet,
// then the facets around it whose own solutions reach x add theirs (on a
// convex part the refracted beams of neighbouring facets overlap: without them
// the light's focusing by the curved surface is missed, 10–60 % of the light
// at depths of a few mm in a 5 mm marble sphere). `straight`: the first hit
// from x straight towards the light when the caller has it (the iteration's
// start), else null. Reached: out holds the connections that are not shadowed
// outside (possibly none).
constexpr int kMaxRefractedPaths = 32;
struct RefractedLights {
    int count = 0;
    RefractedLight paths[kMaxRefractedPaths];
};
LightPath refractedLights(const Boundary& boundary, const Light& light, double eta,
                          const glm::dvec3& x, RefractedLights& out,
                          const SurfaceHit* straight = nullptr);

// The point light's refracted irradiance through a plane, perpendicular to the
// ray (W/mm² per W/sr): the light h1 above the plane, x h2 below, incidence
// cosine cosI, refracted cosine cosT, relative index eta; Fresnel excluded.
// dA⊥/dΩ = (ρ/sinθi)·cosθt·dρ/dθi with ρ = h1·tanθi + h2·tanθt.
double pointRefractedSpreading(double h1, double h2, double cosI, double cosT, double eta);

// Incidence sine on a plane for a point light h1 above it and a point h2 below
// it at horizontal distance d: h1·tanθi + h2·tanθt = d (bisection).
double solveRefractionSine(double h1, double h2, double d, double eta);

}  // namespace tsis
