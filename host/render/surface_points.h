// Deterministic points over a mesh's surface with their exact irradiance E
// (docs/design.md §2): the quadrature of `--method reference` and the irradiance
// samples of `--method hierarchical`. Visibility is exact (render/ray_caster.h).
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "mesh/media.h"
#include "mesh/mesh.h"
#include "physics/material.h"
#include "scene/scene.h"

namespace tsis {

class Cancel;
class Progress;
class RayCaster;
struct AlbedoAtlas;

struct SurfacePoint {
    glm::vec3 position{0.0f};    // mm, on the triangle
    glm::vec3 normal{0.0f};      // interpolated vertex normal, unit
    glm::vec3 irradiance{0.0f};  // E per channel
    float area = 0;              // mm² this point stands for
    uint32_t medium = 0;         // its solid (mesh/media.h)
};

// ℓ_min = 1 / max_c σt'(c): the material's smallest mean free path (mm).
double smallestMeanFreePath(const Material& m);

// Each triangle is cut into k² congruent sub-triangles, k = ⌈longest edge /
// spacing⌉, so no sub-triangle edge is longer than `spacing`; one point at each
// sub-triangle's centroid stands for its area (the centroid rule: exact for
// linear integrands, second order otherwise). Order: triangle by triangle.
// The mesh needs normals; irradiance is left 0.
std::vector<SurfacePoint> placeSurfacePoints(const Mesh& mesh, double spacing);
// How many points placeSurfacePoints makes (Σ k²), without making them.
uint64_t surfacePointCount(const Mesh& mesh, double spacing);

// E(x) of docs/design.md §2 summed over the lights, with V(x) = 1 when the segment from
// x + offset·n to the light (a point light's position, or `reach` mm against a
// directional light's direction; reach must exceed the mesh's extent) crosses
// no triangle (V = 1 for a light with shadows off).
glm::dvec3 irradianceAt(const glm::dvec3& x, const glm::dvec3& n, const std::vector<Light>& lights,
                        double eta, const RayCaster& rays, double offset, double reach);

// The points of placeSurfacePoints with exact E, on every core. A sub-triangle
// that a shadow edge crosses (its corners and centroid are not hidden from the
// same lights), and every sub-triangle touching it, integrates E adaptively
// (cut 4×4 where the edge runs, two levels deep: edges resolved to
// spacing/16) and its point moves to the centroid of luminous flux, on the same
// triangle: the first moment of the flux is kept, so the sum stays second
// order across shadow edges. Rays: one per light and lattice vertex or
// centroid, a few dozen more per sub-triangle on a shadow edge.
// media: findMedia(mesh); etaOfMedium: η of each medium (one value serves
// them all).
std::vector<SurfacePoint> sampleSurface(const Mesh& mesh, double spacing,
                                        const std::vector<Light>& lights, const Media& media,
                                        const std::vector<double>& etaOfMedium,
                                        const RayCaster& rays, double offset, double reach,
                                        Progress* progress = nullptr, Cancel* cancel = nullptr);
// E of sampleSurface's points (in its order, every light and the environment
// added) times the albedo factor at each (the light that enters,
// render/albedo_atlas.h).
void scaleByAlbedo(std::vector<SurfacePoint>& points, const Mesh& mesh, double spacing,
                   const AlbedoAtlas& albedo);

// Poisson-disk thinning: greedily in order, a point becomes a seed when no
// earlier seed with a normal less than 90° away lies closer than `radius`;
// every point then joins the nearest such seed's cell. One point per cell, at
// the cell's centroid weighted by the luminance of the flux E·A (by area where
// dark), with the cell's area, the area-average E and the mean normal: total
// area, flux and the first moment of luminous flux are conserved. Opposite
// sides of a thin part (normals > 90° apart) never share a cell.
std::vector<SurfacePoint> poissonThin(const std::vector<SurfacePoint>& points, double radius);

// Points with exact E for a scene, kept while the mesh, the lights, η and the
// spacing stay the same (σs', σa only set the spacing).
class SurfaceSampleCache {
  public:
    // Returns true when it (re)built the points; `label` names the progress line.
    // With `albedo`, E carries its entry factor (scaleByAlbedo). `cancel`
    // (null: none) stops the build with tsis::Cancelled, the points kept.
    bool update(const Scene& scene, double spacing, const std::string& label,
                const AlbedoAtlas* albedo = nullptr, Cancel* cancel = nullptr);
    // True when update() would keep the points it has.
    bool holds(const Scene& scene, double spacing, const AlbedoAtlas* albedo = nullptr) const;
    const std::vector<SurfacePoint>& points() const { return points_; }
    double lastBuildMs() const { return buildMs_; }

  private:
    static uint64_t keyOf(const Scene& scene, double spacing, const AlbedoAtlas* albedo);
    uint64_t key_ = 0;
    bool valid_ = false;
    std::vector<SurfacePoint> points_;
    double buildMs_ = 0;
};

}  // namespace tsis
