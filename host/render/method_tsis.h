// --method tsis: texture-space importance sampling (thesis ch. 3.1–3.2).
// N samples drawn from the flux atlas by pyramid descent are shared by every
// pixel: B(xo) = Σ w_i ⊙ Rd(|xo − x_i|) (docs/design.md §2).
#pragma once

#include <functional>

#include "cl/gather.h"
#include "cl/importance_sampler.h"
#include "render/method.h"
#include "render/profile_table_cache.h"
#include "render/profiles.h"

namespace tsis {

class TsisMethod : public Method {
  public:
    explicit TsisMethod(ClRuntime& cl);
    const char* name() const override { return "tsis"; }
    void addPasses(FrameGraph& graph, const FrameContext& ctx) override;

    // Adds cdf, sample and gather passes that write ctx.radiosity with
    // `profile` (tabulated up to the object's diameter): the full Rd (or
    // --rd-part) for tsis, Rd·Wg for the hybrid's global part.
    void addGlobalPasses(FrameGraph& graph, const FrameContext& ctx, const KeyedProfile& profile,
                         const std::string& statPrefix);

  private:
    ClRuntime& cl_;
    ImportanceSampler sampler_;
    Gatherer gatherer_;
    GrowingBuffer samples_;
    ProfileTableCache table_;
};

// The importance-sampling passes tsis and mis share: <prefix>cdf builds the
// flux atlas' CDF pyramid (writes `pyramid`), <prefix>sample draws
// ctx.options->samples samples from it into `samples` (writes `drawn`).
void addImportancePasses(FrameGraph& graph, const FrameContext& ctx, ImportanceSampler& sampler,
                         GrowingBuffer& samples, const std::string& prefix,
                         FrameGraphId<Marker> pyramid, FrameGraphId<Marker> drawn);

}  // namespace tsis
