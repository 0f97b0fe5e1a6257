// --method hierarchical: Jensen & Buhler 2002 (docs/design.md §4).
//
// Irradiance samples spread over the surface at about the mean free path: the
// dense points of the reference at half the spacing (exact E, ray-cast
// visibility) thinned to a Poisson-disk set of radius s (render/surface_points.h),
// s = ℓ_min = 1/max σt' by default (`--spacing MM` overrides). The samples go
// into an octree of flux, flux-weighted position and area (render/flux_octree.h);
// each pixel traverses it with J&B's criterion ΔA/|x − p|² < ε (`--epsilon`,
// default 0.05: smaller is slower and closer to the exact sum), Rd per channel
// from the same table as the reference, on every host core.
// Samples and tree are rebuilt only when the mesh, lights, η or s change.
#pragma once

#include "render/flux_octree.h"
#include "render/method.h"
#include "render/profile_table_cache.h"
#include "render/surface_points.h"

namespace tsis {

class HierarchicalMethod : public Method {
  public:
    explicit HierarchicalMethod(ClRuntime& cl);
    const char* name() const override { return "hierarchical"; }
    void addPasses(FrameGraph& graph, const FrameContext& ctx) override;

  private:
    void build(const FrameContext& ctx, double spacing, FrameStats& stats);
    void evaluate(const FrameContext& ctx, const SurfacePoints& points, cl::Buffer& radiosity,
                  FrameStats& stats);

    ClRuntime& cl_;
    SurfaceSampleCache candidates_;
    std::vector<FluxOctree> trees_;  // one per medium (mesh/media.h): light never crosses
    ProfileTableCache rd_;
};

}  // namespace tsis
