#include "render/method_hybrid.h"

#include "util/error.h"

namespace tsis {

HybridMethod::HybridMethod(ClRuntime& cl) : global_(cl), local_(cl) {}

void HybridMethod::addPasses(FrameGraph& graph, FrameContext& ctx) {
    const RenderOptions& o = *ctx.options;
    if (parseRdPart(o.rdPart) != RdPart::Full)
        fail("--rd-part applies to tsis and ltsm; the hybrid always splits the full Rd");
    const Material& m = ctx.scene->material;
    const KeyedProfile global = dipoleProfile(m, RdPart::Global, o.rpBound, o.rpK);
    const KeyedProfile local = dipoleProfile(m, RdPart::Local, o.rpBound, o.rpK);
    global_.addGlobalPasses(graph, ctx, global.f, global.key, ctx.radiosity, "global_radiosity_cl",
                            "global_");
    local_.addLocalPasses(graph, ctx, local, ctx.radiosity, {"global_radiosity_cl"}, "radiosity_cl",
                          "local_", true);
    Json rp = Json::array();
    for (int c = 0; c < 3; ++c) rp.push_back(local.Rp[c]);
    ctx.stats->set("rp", rp);
    ctx.stats->set("rp_k", o.rpK);
}

}  // namespace tsis
