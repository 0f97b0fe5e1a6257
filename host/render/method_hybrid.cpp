#include "render/method_hybrid.h"

namespace tsis {

HybridMethod::HybridMethod(ClRuntime& cl) : global_(cl), local_(cl) {}

void HybridMethod::addPasses(FrameGraph& graph, const FrameContext& ctx) {
    const RenderOptions& o = *ctx.options;
    const KeyedProfile global = ctx.profile(RdPart::Global);
    const KeyedProfile local = ctx.profile(RdPart::Local);
    // The global part writes B, the local part adds to it.
    global_.addGlobalPasses(graph, ctx, global, "global_");
    local_.addLocalPasses(graph, ctx, local, "local_", true);
    Json rp = Json::array();
    for (int c = 0; c < 3; ++c) rp.push_back(local.Rp[c]);
    ctx.stats->set("rp", rp);
    ctx.stats->set("rp_k", o.rpK);
}

}  // namespace tsis
