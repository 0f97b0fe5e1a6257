// --method pyramid: error-bounded integration over the texture-space flux
// pyramid (beyond the thesis; cl/flux_pyramid.h, kernels/flux_pyramid.cl).
//
// The thesis draws N samples from the flux atlas' sum pyramid; Jensen &
// Buhler sum an octree of irradiance samples top-down, using a node whole
// when it is small as seen from the point. This method does the second on the
// first's structure: the pyramid's 2×2 blocks of atlas texels are the nodes
// (flux, area, flux-weighted position, a radius bounding the block in 3D),
// built on the device each time the flux atlas changes, and every group of 8
// neighbouring pixels descends it with the criterion
// max(radius², area/π) < ε·(d² + ℓ²), ℓ the smallest mean free path. No
// random numbers (the same image for any --seed), no Rp or K to tune, and the
// error falls with ε (--pyramid-epsilon) at a cost that grows like 1/ε.
#pragma once

#include "cl/flux_pyramid.h"
#include "render/dipole_table.h"
#include "render/method.h"

namespace tsis {

class PyramidMethod : public Method {
  public:
    explicit PyramidMethod(ClRuntime& cl);
    const char* name() const override { return "pyramid"; }
    void addPasses(FrameGraph& graph, FrameContext& ctx) override;

  private:
    ClRuntime& cl_;
    FluxPyramid pyramid_;
    DipoleTable rd_;
    cl::Buffer table_;
    cl::Buffer order_;  // the covered pixels in tiles (FluxPyramid::tileOrder)
    size_t orderCapacity_ = 0;
};

}  // namespace tsis
