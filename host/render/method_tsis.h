// --method tsis: texture-space importance sampling (thesis ch. 3.1–3.2).
// N samples drawn from the flux atlas by pyramid descent are shared by every
// pixel: B(xo) = Σ w_i ⊙ Rd(|xo − x_i|) (docs/design.md §2).
#pragma once

#include <functional>

#include "cl/gather.h"
#include "cl/importance_sampler.h"
#include "physics/profile_table.h"
#include "render/method.h"
#include "render/profiles.h"

namespace tsis {

class TsisMethod : public Method {
  public:
    explicit TsisMethod(ClRuntime& cl);
    const char* name() const override { return "tsis"; }
    void addPasses(FrameGraph& graph, FrameContext& ctx) override;

    // Adds cdf, sample and gather passes that write `output` with `profile`
    // (tabulated up to the object's diameter): the full Rd (or --rd-part) for
    // tsis, Rd·Wg for the hybrid's global part.
    void addGlobalPasses(FrameGraph& graph, FrameContext& ctx, const RadialProfile& profile,
                         const std::string& profileKey, cl::Buffer& out,
                         const std::string& output, const std::string& statPrefix);

  private:
    ClRuntime& cl_;
    ImportanceSampler sampler_;
    Gatherer gatherer_;
    cl::Buffer samples_;
    int samplesCapacity_ = 0;
    cl::Buffer table_;
    ProfileTable tableHost_;
    std::string tableKey_;
};

}  // namespace tsis
