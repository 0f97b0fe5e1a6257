#include "render/method_mis.h"

#include <cmath>
#include <numbers>

#include "cl/launch.h"
#include "render/light_map_info.h"
#include "render/profiles.h"
#include "render/radial_importance.h"
#include "util/error.h"
#include "util/timer.h"

namespace tsis {

namespace {

constexpr size_t kLocal = 64;

}  // namespace

MisMethod::MisMethod(ClRuntime& cl)
    : cl_(cl),
      sampler_(cl),
      texels_(cl.kernel("mis.cl", "tsis_mis_texels")),
      prepare_(cl.kernel("mis.cl", "tsis_mis_prepare")),
      gather_(cl.kernel("mis.cl", "tsis_mis_gather")) {}

void MisMethod::prepareTables(FrameContext& ctx) {
    const RenderOptions& o = *ctx.options;
    if (parseRdPart(o.rdPart) != RdPart::Full)
        fail("--rd-part applies to tsis and ltsm; mis integrates the full Rd");
    const KeyedProfile rd = dipoleProfile(ctx.scene->material, RdPart::Full, o.rpBound, o.rpK);
    const double rMax = 2.0 * ctx.boundingRadius * 1.001;
    const std::string key = rd.key + " rmax " + std::to_string(rMax);
    if (key == tableKey_) return;
    Timer t;
    tableHost_ = ProfileTable::build(rd.f, rMax);
    table_ = cl::Buffer(cl_.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                        tableHost_.rgba.size() * sizeof(float), tableHost_.rgba.data());
    // Radii at equal steps of the importance's cdf: a draw picks a segment
    // uniformly and a radius linearly inside it.
    const RadialImportance importance(rd.f, rMax);
    std::vector<float> radii(kSegments + 1);
    for (int k = 0; k <= kSegments; ++k)
        radii[static_cast<size_t>(k)] =
            static_cast<float>(importance.inverse(double(k) / kSegments));
    // That sampler's density per mm² of plane, at the centres of uniform bins.
    std::vector<float> q(kQBins, 0.0f);
    size_t seg = 0;
    for (int b = 0; b < kQBins; ++b) {
        const double r = (b + 0.5) * rMax / kQBins;
        while (seg + 1 < kSegments && r >= radii[seg + 1]) ++seg;
        const double dr = radii[seg + 1] - radii[seg];
        if (dr > 0.0 && r < radii[kSegments])
            q[static_cast<size_t>(b)] =
                static_cast<float>(1.0 / (kSegments * dr * 2.0 * std::numbers::pi * r));
    }
    radii_ = cl::Buffer(cl_.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                        radii.size() * sizeof(float), radii.data());
    q_ = cl::Buffer(cl_.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                    q.size() * sizeof(float), q.data());
    info_.segments = kSegments;
    info_.q_size = kQBins;
    info_.q_inv_step = static_cast<float>(kQBins / rMax);
    tableKey_ = key;
    ctx.stats->addStage("mis_tables", t.ms());
}

// The lights' maps back to back (one buffer each, so one kernel sees all of
// them) and their texels' irradiance and area.
void MisMethod::prepareMaps(FrameContext& ctx) {
    const size_t lights = ctx.lightFlux.size();
    TSIS_CHECK_EQ(lights, ctx.lights->size());
    const int res = ctx.lightResolution;
    const size_t per = static_cast<size_t>(res) * res * sizeof(cl_float4);
    if (mapBytes_ < per * lights) {
        mapBytes_ = per * lights;
        flux_ = cl::Buffer(cl_.context(), CL_MEM_READ_WRITE, mapBytes_);
        position_ = cl::Buffer(cl_.context(), CL_MEM_READ_WRITE, mapBytes_);
        irradiance_ = cl::Buffer(cl_.context(), CL_MEM_READ_WRITE, mapBytes_);
    }
    std::vector<TsisLightMapInfo> infos;
    for (size_t l = 0; l < lights; ++l) infos.push_back(lightMapInfo((*ctx.lights)[l], res));
    lightInfos_ = cl::Buffer(cl_.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                             infos.size() * sizeof(TsisLightMapInfo), infos.data());
    info_.lights = static_cast<int>(lights);
    info_.res = res;
    cl::CommandQueue& q = cl_.queue();
    mapEvents_.clear();
    for (size_t l = 0; l < lights; ++l) {
        mapEvents_.emplace_back();
        q.enqueueCopyBuffer(ctx.lightFlux[l], flux_, 0, l * per, per, nullptr, &mapEvents_.back());
        mapEvents_.emplace_back();
        q.enqueueCopyBuffer(ctx.lightPosition[l], position_, 0, l * per, per, nullptr,
                            &mapEvents_.back());
    }
    setKernelArgs(texels_, flux_, position_, info_, irradiance_);
    mapEvents_.emplace_back();
    enqueue1D(q, texels_, lights * static_cast<size_t>(res) * res, kLocal, &mapEvents_.back());
}

void MisMethod::gather(FrameContext& ctx) {
    const int n = ctx.options->samples;
    cl::CommandQueue& q = cl_.queue();
    gatherEvents_.clear();
    // N p_T(x) = N Y(E(x)) / ΣY.
    const double sumY = sampler_.totalLuminance();
    info_.n_tex = n;
    info_.n_dist = ctx.options->misDistanceSamples;
    info_.tex_scale = sumY > 0.0 ? static_cast<float>(n / sumY) : 0.0f;
    info_.seed = frameSeed(ctx);
    setKernelArgs(prepare_, samples_, info_, lightInfos_, position_, irradiance_, seen_, texDensity_);
    gatherEvents_.emplace_back();
    enqueue1D(q, prepare_, static_cast<size_t>(n), kLocal, &gatherEvents_.back());
    if (ctx.pointCount == 0) return;
    setKernelArgs(gather_, ctx.points, ctx.pointCount, info_, samples_, seen_, texDensity_, lightInfos_,
                  flux_, position_, irradiance_, radii_, q_, table_, tableHost_.info, ctx.radiosity);
    gatherEvents_.emplace_back();
    enqueue1D(q, gather_, static_cast<size_t>(ctx.pointCount), kLocal, &gatherEvents_.back());
}

void MisMethod::addPasses(FrameGraph& graph, FrameContext& ctx) {
    prepareTables(ctx);
    const int n = ctx.options->samples;
    const size_t lights = ctx.scene->lights.size();
    if (n > samplesCapacity_ || lights > seenLights_) {
        const size_t count = static_cast<size_t>(n);
        samples_ = cl::Buffer(cl_.context(), CL_MEM_READ_WRITE, sizeof(TsisSample) * count);
        seen_ = cl::Buffer(cl_.context(), CL_MEM_READ_WRITE, sizeof(cl_float4) * count * lights);
        texDensity_ = cl::Buffer(cl_.context(), CL_MEM_READ_WRITE, sizeof(float) * count);
        samplesCapacity_ = n;
        seenLights_ = lights;
    }
    graph.addPass({"mis_cdf",
                   {"flux_atlas_cl"},
                   {"mis_pyramid"},
                   [this, &ctx] {
                       sampler_.buildPyramid(ctx.fluxAtlas, ctx.atlasResolution);
                       ctx.stats->addStage("mis_cdf", sampler_.lastPyramidMs());
                   },
                   true});
    graph.addPass({"mis_sample",
                   {"mis_pyramid", "flux_atlas_cl", "position_atlas_cl"},
                   {"mis_samples"},
                   [this, &ctx, n] {
                       sampler_.draw(ctx.fluxAtlas, ctx.positionAtlas, ctx.atlasResolution, n,
                                     ctx.options->seed, samples_, ctx.sampleSet);
                       ctx.stats->addStage("mis_sample", sampler_.lastDrawMs());
                   },
                   true});
    graph.addPass({"mis_light_maps",
                   {"light_maps_cl"},
                   {"mis_maps"},
                   [this, &ctx] {
                       prepareMaps(ctx);
                       ctx.stats->addStage("mis_light_maps", eventMilliseconds(mapEvents_));
                   },
                   true});
    graph.addPass({"mis_gather",
                   {"mis_samples", "mis_maps", "points_cl"},
                   {"radiosity_cl"},
                   [this, &ctx, n] {
                       gather(ctx);
                       ctx.stats->addStage("mis_gather", eventMilliseconds(gatherEvents_));
                       const double perPoint =
                           n + static_cast<double>(ctx.options->misDistanceSamples) *
                                   static_cast<double>(ctx.lights->size());
                       ctx.stats->set("rd_evaluations", ctx.pointCount * perPoint);
                   },
                   true});
}

}  // namespace tsis
