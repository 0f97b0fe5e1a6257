#include "render/method_ltsm.h"

#include "cl/launch.h"
#include "render/light_map_info.h"
#include "util/error.h"
#include "util/timer.h"

namespace tsis {

LtsmMethod::LtsmMethod(ClRuntime& cl) : cl_(cl), kernel_(cl.kernel("ltsm.cl", "tsis_ltsm")) {}

void LtsmMethod::addPasses(FrameGraph& graph, const FrameContext& ctx) {
    const RenderOptions& o = *ctx.options;
    addLocalPasses(graph, ctx, ctx.profile(o.rdPart), "", false);
}

void LtsmMethod::prepare(const FrameContext& ctx, const KeyedProfile& profile,
                         const std::string& statPrefix, FrameStats& stats) {
    const RenderOptions& o = *ctx.options;
    Timer t;
    const std::string rings = exactKey("rings", {double(o.ltsmRings), double(o.ltsmPerRing)});
    if (!table_.update(profile, ctx.maxDistance(), rings)) return;
    pattern_ = RingPattern::build(RadialImportance(profile.f, ctx.maxDistance()), table_.table(),
                                  o.ltsmRings, o.ltsmPerRing);
    patternBuffer_ =
        cl::Buffer(cl_.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                   pattern_.samples.size() * sizeof(TsisRingSample), pattern_.samples.data());
    stats.addStage(statPrefix + "ltsm_pattern", t.ms());
}

void LtsmMethod::addLocalPasses(FrameGraph& graph, const FrameContext& ctx,
                                const KeyedProfile& profile, const std::string& statPrefix,
                                bool accumulate) {
    graph.addPass(
        statPrefix + "ltsm",
        [&](FrameGraph::Builder& b) {
            b.read(ctx.points);
            b.read(ctx.lightMaps);
            if (accumulate) b.read(ctx.radiosity);
            b.write(ctx.radiosity);
        },
        [this, &ctx, profile, statPrefix, accumulate](FrameGraph::Resources& res) {
            prepare(ctx, profile, statPrefix, res.stats());
            const SurfacePoints& points = res.read(ctx.points);
            const LightMapsCl& maps = res.read(ctx.lightMaps);
            cl::Buffer& out = ctx.radiosityBuffer(res, points.count);
            const int n = static_cast<int>(pattern_.samples.size());
            const size_t lights = maps.flux.size();
            TSIS_CHECK_EQ(lights, maps.views->size());
            events_.clear();
            if (points.count > 0) {
                for (size_t l = 0; l < lights; ++l) {
                    setKernelArgs(kernel_, points.xyz, points.count,
                                  lightMapInfo((*maps.views)[l], ctx.lightResolution), maps.flux[l],
                                  maps.position[l], patternBuffer_, n, table_.device(cl_.context()),
                                  table_.table().info, (accumulate || l > 0) ? 1 : 0, out);
                    events_.emplace_back();
                    enqueue1D(cl_.queue(), kernel_, static_cast<size_t>(points.count), kLocalSize,
                              &events_.back());
                }
            }
            res.setDeviceMs(eventMilliseconds(events_));
            res.stats().set(statPrefix + "rd_evaluations",
                            static_cast<double>(points.count) * n * static_cast<double>(lights));
            res.stats().set(statPrefix + "ltsm_samples", n);
        });
}

}  // namespace tsis
