// --method lss: local subsurface scattering in image space (Mertens et al.
// 2003; the thesis' "LSS", whose text swaps the authors, docs/design.md §3). Irradiance
// from the camera's G-buffer, an importance-sampled disk on the image plane per
// pixel; --samples is the number of samples per pixel. Kernel: kernels/lss.cl.
#pragma once

#include <vector>

#include "render/method.h"
#include "render/profile_table_cache.h"
#include "render/radial_importance.h"
#include "tsis_shared.h"

namespace tsis {

class LssMethod : public Method {
  public:
    // Intervals of the sampled radius' inverse CDF (RadialImportance::inverseTable).
    static constexpr int kRadiusEntries = 4096;
    // |n·view| below this counts as this in a pixel's surface area 1/|n·view|:
    // a pixel seen at more than ~78° is a sliver whose E and position are
    // unreliable, and unclamped it would weigh up to thousands of pixels.
    static constexpr float kMinCos = 0.2f;

    // Samples of a pixel processed together in the kernel: 1 (scalar) or 8
    // (float8 lanes). Measured on PoCL (256², default scene, same results to
    // 3e-7): 8 lanes ran the gather 2–3× faster than the scalar loop.
    static constexpr int kDefaultLanes = 8;
    explicit LssMethod(ClRuntime& cl, int lanes = kDefaultLanes);
    const char* name() const override { return "lss"; }
    void addPasses(FrameGraph& graph, const FrameContext& ctx) override;

    // The camera as the kernels read it.
    static TsisCamera camera(const Camera& camera, int height);

    // The radii: RadialImportance::inverseTable(kRadiusEntries) of Rd (the
    // mean over channels of each one's normalised Rd·2πr, so every channel
    // gets a third of the samples and Rd_c / p ≤ 3·∫Rd_c in all of them). The
    // kernel draws r by linear interpolation in u, whose density per mm² of
    // the plane is exactly p(r) = 1 / (entries·(r_{k+1} − r_k)·2πr) in cell k,
    // and weights by that: unbiased at any table size.

  private:
    void updateTables(const FrameContext& ctx);

    ClRuntime& cl_;
    cl::Kernel prepare_, gather_;
    GrowingBuffer pos_, ea_, pixels_;
    cl::Buffer dirs_, radii_;
    int dirsCount_ = 0;
    ProfileTableCache table_;
};

}  // namespace tsis
