// --method mis (beyond the thesis, docs/design.md §6): one unbiased estimator for both
// regimes, with no Rp or K to tune. B(xo) = ∫ E(x) Rd(|xo − x|) dA(x) is
// sampled two ways, densities in the surface-area measure:
//
//   T, irradiance-driven: the N texture-space samples of tsis (--samples).
//     Texel i of the flux atlas with p_i = Y(Φ_i)/ΣY; as an area density
//     p_T(x) = p_i / A_i = Y(E(x)) / ΣY, since Φ_i = E·A_i. Its estimate
//     f/p_T is tsis' w_i·Rd.
//   D_l, distance-driven, per pixel and light l (--mis-distance n): a point
//     on the plane through xo perpendicular to the light's axis, at radius r
//     drawn from the importance of Rd on the plane (RadialImportance, K
//     equal-probability segments, linear inside: density q per mm² of plane,
//     known exactly for each draw), taken to the surface through the light's
//     map: texel t holds Φ_l(t) = E_l(x)·A_l(t) and covers τ² of the plane
//     (τ = texel size at xo's depth), so p_l(x) = q·τ²/A_l(t) and light l's
//     share of the integrand gives E_l·Rd/p_l = Φ_l(t)·Rd/(q τ²): no area
//     needed.
//
// One weight c(x) ∈ [0, 1] splits the integrand: T integrates c·E·Rd, and
// D_l integrates (1 − c)·E_l·Rd, which sums over the lights to (1 − c)·E·Rd.
// The total is unbiased for any c (a function of x for a given xo); c is the
// balance heuristic N p_T / (N p_T + Σ_l n p_l), with the densities taken from
// the light maps (E_l = Φ_l/A_l, A_l from neighbouring texels' positions,
// "lit by l" when x is within two texel sizes of the map's surface there).
// Errors in those estimates cost variance, never bias. Kernels: kernels/mis.cl.
#pragma once

#include <vector>

#include "cl/importance_sampler.h"
#include "mis_shared.h"
#include "render/method.h"
#include "render/profile_table_cache.h"

namespace tsis {

class MisMethod : public Method {
  public:
    static constexpr int kSegments = 256;  // the radius sampler's segments
    static constexpr int kQBins = 4096;    // the density table used in the weights

    explicit MisMethod(ClRuntime& cl);
    const char* name() const override { return "mis"; }
    void addPasses(FrameGraph& graph, const FrameContext& ctx) override;

  private:
    void prepareTables(const FrameContext& ctx, FrameStats& stats);
    void prepareMaps(const FrameContext& ctx, const LightMapsCl& maps);
    void gather(const FrameContext& ctx, const SurfacePoints& points, cl::Buffer& out);

    ClRuntime& cl_;
    ImportanceSampler sampler_;
    cl::Kernel texels_, prepare_, gather_;
    TsisMisInfo info_{};
    ProfileTableCache table_;
    cl::Buffer radii_, q_;
    GrowingBuffer samples_, seen_, texDensity_;
    cl::Buffer lightInfos_;
    GrowingBuffer flux_, position_, irradiance_;  // every light's maps back to back
    std::vector<cl::Event> mapEvents_, gatherEvents_;
};

}  // namespace tsis
