// --method ltsm: the thesis' local method (3.3.2), "local translucent shadow
// map". Each light's flux map (flux per texel, docs/design.md §2) is filtered around
// xo's projection with L rings of C samples + the centre (--ltsm-rings,
// --ltsm-per-ring; default 4×4+1) placed by the importance of the profile on
// the plane; samples are weighted by the profile at the true 3D distance to the
// surface point in the light's position map. Alone it integrates the full Rd
// (or --rd-part); the hybrid uses it for Rd·Wl. Kernel: kernels/ltsm.cl.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "render/method.h"
#include "render/profile_table_cache.h"
#include "render/profiles.h"
#include "render/ring_pattern.h"

namespace tsis {

class LtsmMethod : public Method {
  public:
    explicit LtsmMethod(ClRuntime& cl);
    const char* name() const override { return "ltsm"; }
    void addPasses(FrameGraph& graph, const FrameContext& ctx) override;
    std::optional<RdPart> missesResidual(const RenderOptions& o) const override { return o.rdPart; }

    // Adds the filter pass for `profile`: writes ctx.radiosity, or adds to
    // what it holds when `accumulate`. Stats: <prefix>ltsm (ms),
    // <prefix>rd_evaluations.
    void addLocalPasses(FrameGraph& graph, const FrameContext& ctx, const KeyedProfile& profile,
                        const std::string& statPrefix, bool accumulate);

    const RingPattern& pattern() const { return pattern_; }

  private:
    void prepare(const FrameContext& ctx, const KeyedProfile& profile,
                 const std::string& statPrefix, FrameStats& stats);

    ClRuntime& cl_;
    cl::Kernel kernel_;
    std::vector<cl::Event> events_;
    ProfileTableCache table_;
    RingPattern pattern_;
    cl::Buffer patternBuffer_;
};

}  // namespace tsis
