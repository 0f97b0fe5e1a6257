// --method tsm: Translucent Shadow Maps (Dachsbacher & Stamminger 2003; the
// thesis' text swaps the authors, docs/design.md §3). The light-view flux and position
// maps, filtered around xo's projection into each light's map by a fixed
// pattern of 21 taps. Kernel: kernels/tsm.cl; the pattern: method_tsm.cpp.
#pragma once

#include <vector>

#include "render/method.h"
#include "render/radial_importance.h"
#include "tsis_shared.h"

namespace tsis {

class TsmMethod : public Method {
  public:
    static constexpr int kRings = 4;  // ring 0 is the centre disk
    // Ring edges in units of the filter radius R.
    static constexpr double kRingEdges[kRings + 1] = {0.0, 0.125, 0.25, 0.5, 1.0};

    explicit TsmMethod(ClRuntime& cl);
    const char* name() const override { return "tsm"; }
    void addPasses(FrameGraph& graph, const FrameContext& ctx) override;
    std::optional<RdPart> missesResidual(const RenderOptions&) const override {
        return RdPart::Full;
    }

    // The 21 taps (offsets and footprints in units of R; footprints sum to π).
    static std::vector<TsisTsmTap> pattern();
    // R (mm) = transportLengths / σtr of the widest channel, at most `limit`.
    static double filterRadiusMm(const Material& m, double transportLengths, double limit);
    // Mean of Rd(√(ρ² + z²)) over the annulus a ≤ ρ ≤ b of a plane at distance z,
    // from the radial mass: (M(√(b²+z²)) − M(√(a²+z²))) / (π(b² − a²)), since
    // ρ dρ = s ds for s = √(ρ² + z²).
    static glm::dvec3 annulusMean(const RadialImportance& rd, double a, double b, double z);

  private:
    void updateTables(const FrameContext& ctx);
    // Each returns its device milliseconds.
    double buildPyramids(const FrameContext& ctx, const LightMapsCl& maps);
    double filter(const FrameContext& ctx, const LightMapsCl& maps, const SurfacePoints& points,
                  cl::Buffer& out, FrameStats& stats);

    ClRuntime& cl_;
    cl::Kernel level0_, reduce_, filter_;
    cl::Buffer taps_, rings_, levels_;
    std::vector<cl::Buffer> F_, P_;  // per light: flux sums, luminance-weighted positions
    TsisTableInfo ringInfo_{};
    double radiusMm_ = 0;
    std::string tableKey_;
    std::vector<cl_int4> levelsHost_;  // first cell, width, height, 0 per level
    size_t pyramidBytes_ = 0;
};

}  // namespace tsis
