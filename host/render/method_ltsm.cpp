#include "render/method_ltsm.h"

#include <sstream>

#include "cl/launch.h"
#include "render/light_map_info.h"
#include "util/error.h"
#include "util/timer.h"

namespace tsis {

namespace {

constexpr size_t kLocal = 64;

}  // namespace

LtsmMethod::LtsmMethod(ClRuntime& cl) : cl_(cl), kernel_(cl.kernel("ltsm.cl", "tsis_ltsm")) {}

void LtsmMethod::addPasses(FrameGraph& graph, FrameContext& ctx) {
    const RenderOptions& o = *ctx.options;
    const KeyedProfile profile =
        dipoleProfile(ctx.scene->material, parseRdPart(o.rdPart), o.rpBound, o.rpK);
    addLocalPasses(graph, ctx, profile, ctx.radiosity, {}, "radiosity_cl", "", false);
}

void LtsmMethod::prepare(FrameContext& ctx, const KeyedProfile& profile,
                         const std::string& statPrefix) {
    const RenderOptions& o = *ctx.options;
    if (o.ltsmRings < 0 || o.ltsmPerRing < 1)
        fail("--ltsm-rings ", o.ltsmRings, " / --ltsm-per-ring ", o.ltsmPerRing,
             ": need L ≥ 0 rings of C ≥ 1 samples");
    // As for tsis: two surface points are at most the bounding sphere's diameter apart.
    const double rMax = 2.0 * ctx.boundingRadius * 1.001;
    std::ostringstream key;
    key.precision(17);
    key << profile.key << " rmax " << rMax << " rings " << o.ltsmRings << 'x' << o.ltsmPerRing;
    if (key.str() == key_) return;
    Timer t;
    tableHost_ = ProfileTable::build(profile.f, rMax);
    table_ = cl::Buffer(cl_.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                        tableHost_.rgba.size() * sizeof(float), tableHost_.rgba.data());
    pattern_ = RingPattern::build(RadialImportance(profile.f, rMax), tableHost_, o.ltsmRings,
                                  o.ltsmPerRing);
    patternBuffer_ =
        cl::Buffer(cl_.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                   pattern_.samples.size() * sizeof(TsisRingSample), pattern_.samples.data());
    key_ = key.str();
    ctx.stats->addStage(statPrefix + "ltsm_pattern", t.ms());
}

void LtsmMethod::addLocalPasses(FrameGraph& graph, FrameContext& ctx, const KeyedProfile& profile,
                                cl::Buffer& out, const std::vector<std::string>& reads,
                                const std::string& output, const std::string& statPrefix,
                                bool accumulate) {
    prepare(ctx, profile, statPrefix);
    std::vector<std::string> in = {"points_cl", "light_maps_cl"};
    in.insert(in.end(), reads.begin(), reads.end());
    graph.addPass(
        {statPrefix + "ltsm",
         in,
         {output},
         [this, &ctx, &out, statPrefix, accumulate] {
             const int n = static_cast<int>(pattern_.samples.size());
             const size_t lights = ctx.lightFlux.size();
             TSIS_CHECK_EQ(lights, ctx.lights->size());
             events_.clear();
             if (ctx.pointCount > 0) {
                 for (size_t l = 0; l < lights; ++l) {
                     setKernelArgs(kernel_, ctx.points, ctx.pointCount,
                                   lightMapInfo((*ctx.lights)[l], ctx.lightResolution),
                                   ctx.lightFlux[l], ctx.lightPosition[l], patternBuffer_, n, table_,
                                   tableHost_.info, (accumulate || l > 0) ? 1 : 0, out);
                     events_.emplace_back();
                     enqueue1D(cl_.queue(), kernel_, static_cast<size_t>(ctx.pointCount), kLocal,
                               &events_.back());
                 }
             }
             ctx.stats->addStage(statPrefix + "ltsm", eventMilliseconds(events_));
             ctx.stats->set(statPrefix + "rd_evaluations",
                            static_cast<double>(ctx.pointCount) * n * static_cast<double>(lights));
             ctx.stats->set(statPrefix + "ltsm_samples", n);
         },
         true});
}

}  // namespace tsis
