// --method hybrid (thesis 3.3, docs/design.md §4): Rd = Rd·Wl + Rd·Wg. The global part
// by texture-space importance sampling (tsis, N shared samples), the local
// part by the light-view ring filter (ltsm); both land in the frame's
// radiosity, local added to global. Options: --rp-bound (Rp from the
// importance Rd·2πr), --rp-k (K), --samples, --ltsm-rings, --ltsm-per-ring.
// Stats: global_* and local_* stages.
#pragma once

#include "render/method.h"
#include "render/method_ltsm.h"
#include "render/method_tsis.h"

namespace tsis {

class HybridMethod : public Method {
  public:
    explicit HybridMethod(ClRuntime& cl);
    const char* name() const override { return "hybrid"; }
    void addPasses(FrameGraph& graph, const FrameContext& ctx) override;
    // The global half reads the flux atlas, residual and all; the local half
    // only the lights' views.
    std::optional<RdPart> missesResidual(const RenderOptions&) const override {
        return RdPart::Local;
    }

  private:
    TsisMethod global_;
    LtsmMethod local_;
};

}  // namespace tsis
