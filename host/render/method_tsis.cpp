#include "render/method_tsis.h"

#include <sstream>

#include "util/error.h"
#include "util/timer.h"

namespace tsis {

TsisMethod::TsisMethod(ClRuntime& cl) : cl_(cl), sampler_(cl), gatherer_(cl) {}

void TsisMethod::addPasses(FrameGraph& graph, FrameContext& ctx) {
    const RenderOptions& o = *ctx.options;
    const KeyedProfile profile =
        dipoleProfile(ctx.scene->material, parseRdPart(o.rdPart), o.rpBound, o.rpK);
    addGlobalPasses(graph, ctx, profile.f, profile.key, ctx.radiosity, "radiosity_cl", "");
}

void TsisMethod::addGlobalPasses(FrameGraph& graph, FrameContext& ctx, const RadialProfile& profile,
                                 const std::string& profileKey, cl::Buffer& out,
                                 const std::string& output, const std::string& statPrefix) {
    // Any two surface points are at most the bounding sphere's diameter apart.
    const double rMax = 2.0 * ctx.boundingRadius * 1.001;
    std::ostringstream key;
    key.precision(17);
    key << profileKey << " rmax " << rMax;
    if (key.str() != tableKey_) {
        Timer t;
        tableHost_ = ProfileTable::build(profile, rMax);
        table_ = cl::Buffer(cl_.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                            tableHost_.rgba.size() * sizeof(float), tableHost_.rgba.data());
        tableKey_ = key.str();
        ctx.stats->addStage(statPrefix + "profile_table", t.ms());
    }
    const int n = ctx.options->samples;
    if (n > samplesCapacity_) {
        samples_ = cl::Buffer(cl_.context(), CL_MEM_READ_WRITE, sizeof(TsisSample) * n);
        samplesCapacity_ = n;
    }
    graph.addPass({statPrefix + "cdf", {"flux_atlas_cl"}, {statPrefix + "pyramid"},
                   [this, &ctx, statPrefix] {
                       sampler_.buildPyramid(ctx.fluxAtlas, ctx.atlasResolution);
                       ctx.stats->addStage(statPrefix + "cdf", sampler_.lastPyramidMs());
                   },
                   true});
    graph.addPass({statPrefix + "sample",
                   {statPrefix + "pyramid", "flux_atlas_cl", "position_atlas_cl"},
                   {statPrefix + "samples"},
                   [this, &ctx, n, statPrefix] {
                       sampler_.draw(ctx.fluxAtlas, ctx.positionAtlas, ctx.atlasResolution, n,
                                     ctx.options->seed, samples_, ctx.sampleSet);
                       ctx.stats->addStage(statPrefix + "sample", sampler_.lastDrawMs());
                   },
                   true});
    graph.addPass({statPrefix + "gather", {statPrefix + "samples", "points_cl"}, {output},
                   [this, &ctx, &out, n, statPrefix] {
                       if (ctx.pointCount > 0)
                           gatherer_.run(ctx.points, ctx.pointCount, samples_, n, table_,
                                         tableHost_.info, out);
                       ctx.stats->addStage(statPrefix + "gather",
                                           ctx.pointCount > 0 ? gatherer_.lastMs() : 0.0);
                       ctx.stats->set(statPrefix + "rd_evaluations",
                                      static_cast<double>(ctx.pointCount) * n);
                   },
                   true});
}

}  // namespace tsis
