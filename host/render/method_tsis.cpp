#include "render/method_tsis.h"

#include "util/timer.h"

namespace tsis {

TsisMethod::TsisMethod(ClRuntime& cl) : cl_(cl), sampler_(cl), gatherer_(cl) {}

void TsisMethod::addPasses(FrameGraph& graph, const FrameContext& ctx) {
    const RenderOptions& o = *ctx.options;
    addGlobalPasses(graph, ctx, ctx.profile(o.rdPart), "");
}

void TsisMethod::addGlobalPasses(FrameGraph& graph, const FrameContext& ctx,
                                 const KeyedProfile& profile, const std::string& statPrefix) {
    const int n = ctx.options->samples;
    const auto pyramid = graph.create<Marker>(statPrefix + "pyramid");
    const auto samples = graph.create<Marker>(statPrefix + "samples");
    addImportancePasses(graph, ctx, sampler_, samples_, statPrefix, pyramid, samples);
    graph.addPass(
        statPrefix + "gather",
        [&](FrameGraph::Builder& b) {
            b.read(samples);
            b.read(ctx.points);
            b.write(ctx.radiosity);
        },
        [this, &ctx, n, statPrefix, profile](FrameGraph::Resources& res) {
            Timer t;
            if (table_.update(profile, ctx.maxDistance()))
                res.stats().addStage(statPrefix + "profile_table", t.ms());
            const SurfacePoints& points = res.read(ctx.points);
            cl::Buffer& out = ctx.radiosityBuffer(res, points.count);
            if (points.count > 0) {
                gatherer_.run(points.xyz, points.count, samples_.buffer, n,
                              table_.device(cl_.context()), table_.table().info, out);
                res.setDeviceMs(gatherer_.lastMs());
            }
            res.stats().set(statPrefix + "rd_evaluations", static_cast<double>(points.count) * n);
        });
}

void addImportancePasses(FrameGraph& graph, const FrameContext& ctx, ImportanceSampler& sampler,
                         GrowingBuffer& samples, const std::string& prefix,
                         FrameGraphId<Marker> pyramid, FrameGraphId<Marker> drawn) {
    graph.addPass(
        prefix + "cdf",
        [&](FrameGraph::Builder& b) {
            b.read(ctx.fluxAtlas);
            b.write(pyramid);
        },
        [&sampler, &ctx](FrameGraph::Resources& res) {
            sampler.buildPyramid(res.read(ctx.fluxAtlas).buffer, ctx.atlasResolution);
            res.setDeviceMs(sampler.lastPyramidMs());
        });
    graph.addPass(
        prefix + "sample",
        [&](FrameGraph::Builder& b) {
            b.read(pyramid);
            b.read(ctx.fluxAtlas);
            b.read(ctx.positionAtlas);
            b.write(drawn);
        },
        [&sampler, &samples, &ctx](FrameGraph::Resources& res) {
            const int n = ctx.options->samples;
            sampler.draw(res.read(ctx.fluxAtlas).buffer, res.read(ctx.positionAtlas).buffer,
                         ctx.atlasResolution, n, ctx.options->seed,
                         samples.reserve(ctx.cl->context(), sizeof(TsisSample) * n), ctx.sampleSet);
            res.setDeviceMs(sampler.lastDrawMs());
        });
}

}  // namespace tsis
