// Deterministic points over a mesh's surface with their exact irradiance E
// (DESIGN §2): the quadrature of `--method reference` and the irradiance
// samples of `--method hierarchical`. Visibility is exact (render/ray_caster.h).
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "mesh/mesh.h"
#include "physics/material.h"
#include "render/scene.h"

namespace tsis {

class Progress;
class RayCaster;

struct SurfacePoint {
    glm::vec3 position{0.0f};    // mm, on the triangle
    glm::vec3 normal{0.0f};      // interpolated vertex normal, unit
    glm::vec3 irradiance{0.0f};  // E per channel
    float area = 0;              // mm² this point stands for
};

// ℓ_min = 1 / max_c σt'(c): the material's smallest mean free path (mm).
double smallestMeanFreePath(const Material& m);

// Each triangle is cut into k² congruent sub-triangles, k = ⌈longest edge /
// spacing⌉, so no sub-triangle edge is longer than `spacing`; one point at each
// sub-triangle's centroid stands for its area (the centroid rule: exact for
// linear integrands, second order otherwise). Order: triangle by triangle.
// The mesh needs normals; irradiance is left 0.
std::vector<SurfacePoint> placeSurfacePoints(const Mesh& mesh, double spacing);

// E(x) of DESIGN §2 summed over the lights, with V(x) = 1 when the segment from
// x + offset·n to the light (a point light's position, or `reach` mm against a
// directional light's direction; reach must exceed the mesh's extent) crosses
// no triangle (V = 1 for a light with shadows off).
glm::dvec3 irradianceAt(const glm::dvec3& x, const glm::dvec3& n, const std::vector<Light>& lights,
                        double eta, const RayCaster& rays, double offset, double reach);

// irradianceAt for every point, on every core.
void computeIrradiance(std::vector<SurfacePoint>& points, const std::vector<Light>& lights,
                       double eta, const RayCaster& rays, double offset, double reach,
                       Progress* progress = nullptr);

// A Poisson-disk subset (a point is kept when no earlier kept point with a
// normal less than 90° away lies closer than `radius`), each dropped point's
// area and flux E·A merged into the nearest such kept point: total area and
// flux are conserved, E of a kept point becomes the area average of its cell.
// Opposite sides of a thin part (normals > 90° apart) never merge.
std::vector<SurfacePoint> poissonThin(const std::vector<SurfacePoint>& points, double radius);

// Points with exact E for a scene, kept while the mesh, the lights, η and the
// spacing stay the same (σs', σa only set the spacing).
class SurfaceSampleCache {
  public:
    // Returns true when it (re)built the points; `label` names the progress line.
    bool update(const Scene& scene, double spacing, const std::string& label);
    const std::vector<SurfacePoint>& points() const { return points_; }
    double lastBuildMs() const { return buildMs_; }

  private:
    uint64_t key_ = 0;
    bool valid_ = false;
    std::vector<SurfacePoint> points_;
    double buildMs_ = 0;
};

}  // namespace tsis
