// The environment's residual (scene/environment.h: the map without its sun)
// on the surface, with visibility by rays against the mesh (Embree):
//  * EnvTransfer, for the flux atlas: per atlas texel, once per mesh, atlas
//    resolution and η, the transfer T_k = ∫ V·Ft(η, n·ω)·max(0, n·ω)·Y_k(ω) dω
//    on 16 spherical harmonics (bands 0…3); each frame E = Σ_k T_k·L_k with L_k
//    the turned, scaled residual's coefficients — turning the map costs one
//    projection and one dot product per texel, no ray (Sloan et al. 2002).
//  * addEnvironmentIrradiance, for reference and hierarchical: E at each
//    surface point by Monte Carlo over the residual itself (no harmonics).
// Both draw stratified cosine-weighted directions (visibleDirections).
// docs/design.md §12.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "mesh/mesh.h"
#include "render/surface_points.h"
#include "scene/environment.h"

namespace tsis {

class MeshBoundary;

// Calls f(ω, cosθ) for each of strata² cosine-weighted directions about n
// (one per stratum, jittered by `seed`) that leave x + offset·n without
// meeting the mesh; each stands for π/strata² of ∫ … cosθ dω.
void visibleDirections(const MeshBoundary& mesh, const glm::dvec3& x, const glm::dvec3& n,
                       double offset, int strata, uint32_t seed,
                       const std::function<void(const glm::dvec3&, double)>& f);

class EnvTransfer {
  public:
    EnvTransfer();
    ~EnvTransfer();
    // Rebuilds the transfer when the key (mesh, resolution, η) changed, from
    // the geometry atlas read back (RGBA, GL order: position w = coverage,
    // normal w = area). Returns true when it rebuilt.
    bool update(uint64_t key, const Mesh& mesh, int resolution, double eta,
                const std::vector<float>& positions, const std::vector<float>& normals);
    // E of the residual per texel (RGBA, GL order, resolution²), ≥ 0.
    std::vector<float> irradiance(const Environment& env) const;
    uint64_t key() const { return key_; }
    size_t texels() const { return texels_.size(); }
    size_t tracedTexels() const { return traced_; }  // texels whose own rays were cast

  private:
    uint64_t key_ = 0;
    int resolution_ = 0;
    size_t traced_ = 0;
    std::vector<uint32_t> texels_;     // covered texel indices
    std::vector<uint32_t> ownerSlot_;  // per covered texel: the traced texel whose rays it uses
    std::vector<float> transfer_;      // kEnvShCount per traced texel
};

// Strata per side of the transfer's directions (144 rays a traced texel), and
// the side of the atlas blocks whose texels share one traced texel's rays.
constexpr int kTransferStrata = 12;
constexpr int kTransferBlock = 4;
// Strata per side of the reference's directions (1024 rays a point).
constexpr int kReferenceEnvStrata = 32;

// Adds the residual's E (exact visibility, kReferenceEnvStrata² rays) to each point.
void addEnvironmentIrradiance(std::vector<SurfacePoint>& points, const Scene& scene, double offset);

}  // namespace tsis
