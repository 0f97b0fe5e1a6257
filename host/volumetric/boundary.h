// The object's surface as the random walks see it: first hits along rays, with
// the flat facet's outward normal (the smooth dielectric boundary refracts at
// the geometric normal: the transport of the mesh as it is, faceted).
#pragma once

#include <glm/vec3.hpp>
#include <limits>
#include <span>

namespace tsis {

struct SurfaceHit {
    double t = 0;
    glm::dvec3 position{0.0};
    glm::dvec3 normal{0.0};  // outward unit normal of the facet's plane
    int facet = -1;
    double u = 0, v = 0;  // barycentric coordinates of vertices 1 and 2 (meshes)
};

class Boundary {
  public:
    virtual ~Boundary() = default;
    // The first surface point origin + t·dir (dir unit) with 0 < t < tMax.
    virtual bool intersect(const glm::dvec3& origin, const glm::dvec3& dir, double tMax,
                           SurfaceHit& hit) const = 0;
    // Offset that moves a point off the surface before the next ray leaves it
    // (mm): above the ray caster's rounding, far below a mean free path.
    virtual double epsilon() const = 0;

    // Facets, for boundaries made of them (meshes): the next-event connection
    // through the boundary enumerates the facets around the one it settled on,
    // since light refracted by several facets can reach the same interior point
    // (refracted_light.h). Analytic boundaries have none.
    // A facet's vertices and outward unit normal; false without facets.
    virtual bool facet(int /*facet*/, glm::dvec3 (&/*v*/)[3], glm::dvec3& /*normal*/) const {
        return false;
    }
    // The facets sharing a vertex with `facet` (welded by position).
    virtual std::span<const int> facetNeighbours(int /*facet*/) const { return {}; }
};

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Two hits on one plane (coplanar facets count as one: a flat part of a mesh).
bool samePlane(const SurfaceHit& a, const SurfaceHit& b, double epsilon);

// The half-space y < 0 (the semi-infinite slab, surface normal +y).
class HalfSpace : public Boundary {
  public:
    bool intersect(const glm::dvec3& origin, const glm::dvec3& dir, double tMax,
                   SurfaceHit& hit) const override;
    double epsilon() const override { return 1e-9; }
};

}  // namespace tsis
