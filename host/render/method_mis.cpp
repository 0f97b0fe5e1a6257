#include "render/method_mis.h"

#include <cmath>
#include <numbers>

#include "cl/launch.h"
#include "render/light_map_info.h"
#include "render/method_tsis.h"
#include "render/profiles.h"
#include "render/radial_importance.h"
#include "util/error.h"
#include "util/timer.h"

namespace tsis {

MisMethod::MisMethod(ClRuntime& cl)
    : cl_(cl),
      sampler_(cl),
      texels_(cl.kernel("mis.cl", "tsis_mis_texels")),
      prepare_(cl.kernel("mis.cl", "tsis_mis_prepare")),
      gather_(cl.kernel("mis.cl", "tsis_mis_gather")) {}

void MisMethod::prepareTables(const FrameContext& ctx, FrameStats& stats) {
    const KeyedProfile rd = ctx.profile();
    const double rMax = ctx.maxDistance();
    Timer t;
    if (!table_.update(rd, rMax)) return;
    // Radii at equal steps of the importance's cdf: a draw picks a segment
    // uniformly and a radius linearly inside it.
    const std::vector<float> radii = RadialImportance(rd.f, rMax).inverseTable(kSegments);
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
                        radii.size() * sizeof(float), const_cast<float*>(radii.data()));
    q_ = cl::Buffer(cl_.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                    q.size() * sizeof(float), q.data());
    info_.segments = kSegments;
    info_.q_size = kQBins;
    info_.q_inv_step = static_cast<float>(kQBins / rMax);
    stats.addStage("mis_tables", t.ms());
}

// The lights' maps back to back (one buffer each, so one kernel sees all of
// them) and their texels' irradiance and area.
void MisMethod::prepareMaps(const FrameContext& ctx, const LightMapsCl& maps) {
    const size_t lights = maps.flux.size();
    TSIS_CHECK_EQ(lights, maps.views->size());
    const int res = ctx.lightResolution;
    const size_t per = static_cast<size_t>(res) * res * sizeof(cl_float4);
    cl::Buffer& flux = flux_.reserve(cl_.context(), per * lights);
    cl::Buffer& position = position_.reserve(cl_.context(), per * lights);
    cl::Buffer& irradiance = irradiance_.reserve(cl_.context(), per * lights);
    std::vector<TsisLightMapInfo> infos;
    for (size_t l = 0; l < lights; ++l) infos.push_back(lightMapInfo((*maps.views)[l], res));
    lightInfos_ = cl::Buffer(cl_.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                             infos.size() * sizeof(TsisLightMapInfo), infos.data());
    info_.lights = static_cast<int>(lights);
    info_.res = res;
    cl::CommandQueue& q = cl_.queue();
    mapEvents_.clear();
    for (size_t l = 0; l < lights; ++l) {
        mapEvents_.emplace_back();
        q.enqueueCopyBuffer(maps.flux[l], flux, 0, l * per, per, nullptr, &mapEvents_.back());
        mapEvents_.emplace_back();
        q.enqueueCopyBuffer(maps.position[l], position, 0, l * per, per, nullptr,
                            &mapEvents_.back());
    }
    setKernelArgs(texels_, flux, position, info_, irradiance);
    mapEvents_.emplace_back();
    enqueue1D(q, texels_, lights * static_cast<size_t>(res) * res, kLocalSize, &mapEvents_.back());
}

void MisMethod::gather(const FrameContext& ctx, const SurfacePoints& points, cl::Buffer& out) {
    const int n = ctx.options->samples;
    cl::CommandQueue& q = cl_.queue();
    gatherEvents_.clear();
    // N p_T(x) = N Y(E(x)) / ΣY.
    const double sumY = sampler_.totalLuminance();
    info_.n_tex = n;
    info_.n_dist = ctx.options->misDistanceSamples;
    info_.tex_scale = sumY > 0.0 ? static_cast<float>(n / sumY) : 0.0f;
    info_.seed = frameSeed(ctx);
    const size_t count = static_cast<size_t>(n), lights = ctx.scene->lights.size();
    cl::Buffer& seen = seen_.reserve(cl_.context(), sizeof(cl_float4) * count * lights);
    cl::Buffer& texDensity = texDensity_.reserve(cl_.context(), sizeof(float) * count);
    setKernelArgs(prepare_, samples_.buffer, info_, lightInfos_, position_.buffer,
                  irradiance_.buffer, seen, texDensity);
    gatherEvents_.emplace_back();
    enqueue1D(q, prepare_, static_cast<size_t>(n), kLocalSize, &gatherEvents_.back());
    if (points.count == 0) return;
    setKernelArgs(gather_, points.xyz, points.count, info_, samples_.buffer, seen, texDensity,
                  lightInfos_, flux_.buffer, position_.buffer, irradiance_.buffer, radii_, q_,
                  table_.device(cl_.context()), table_.table().info, out);
    gatherEvents_.emplace_back();
    enqueue1D(q, gather_, static_cast<size_t>(points.count), kLocalSize, &gatherEvents_.back());
}

void MisMethod::addPasses(FrameGraph& graph, const FrameContext& ctx) {
    const int n = ctx.options->samples;
    const auto pyramid = graph.create<Marker>("mis_pyramid");
    const auto samples = graph.create<Marker>("mis_samples");
    const auto maps = graph.create<Marker>("mis_maps");
    addImportancePasses(graph, ctx, sampler_, samples_, "mis_", pyramid, samples);
    graph.addPass(
        "mis_light_maps",
        [&](FrameGraph::Builder& b) {
            b.read(ctx.lightMaps);
            b.write(maps);
        },
        [this, &ctx](FrameGraph::Resources& res) {
            prepareMaps(ctx, res.read(ctx.lightMaps));
            res.setDeviceMs(eventMilliseconds(mapEvents_));
        });
    graph.addPass(
        "mis_gather",
        [&](FrameGraph::Builder& b) {
            b.read(samples);
            b.read(maps);
            b.read(ctx.points);
            b.write(ctx.radiosity);
        },
        [this, &ctx, n](FrameGraph::Resources& res) {
            prepareTables(ctx, res.stats());
            const SurfacePoints& points = res.read(ctx.points);
            gather(ctx, points, ctx.radiosityBuffer(res, points.count));
            res.setDeviceMs(eventMilliseconds(gatherEvents_));
            const double perPoint = n + static_cast<double>(ctx.options->misDistanceSamples) *
                                            static_cast<double>(ctx.scene->lights.size());
            res.stats().set("rd_evaluations", points.count * perPoint);
        });
}

}  // namespace tsis
