#include "render/method_volumetric.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <glm/geometric.hpp>
#include <string>
#include <vector>

#include "physics/fresnel.h"
#include "render/frame_keys.h"
#include "util/error.h"
#include "util/parallel.h"
#include "util/progress.h"
#include "util/timer.h"
#include "volumetric/camera_walk.h"
#include "volumetric/light_trace.h"

namespace tsis {

VolumetricMethod::VolumetricMethod(ClRuntime& cl) : cl_(cl) {}

void VolumetricMethod::addPasses(FrameGraph& graph, const FrameContext& ctx) {
    graph.addPass(
        "volumetric",
        [&](FrameGraph::Builder& b) {
            b.read(ctx.points);
            b.write(ctx.radiosity);
        },
        [this, &ctx](FrameGraph::Resources& res) {
            const SurfacePoints& points = res.read(ctx.points);
            render(ctx, points, ctx.radiosityBuffer(res, points.count), res.stats());
        });
}

void VolumetricMethod::render(const FrameContext& ctx, const SurfacePoints& points,
                              cl::Buffer& radiosity, FrameStats& stats) {
    Timer timer;
    const Scene& scene = *ctx.scene;
    const uint64_t key = meshHash(scene.mesh);
    if (!boundary_ || key != meshKey_) {
        boundary_ = std::make_unique<MeshBoundary>(scene.mesh);
        meshKey_ = key;
    }
    WalkScene walk{boundary_.get(), Medium(*ctx.material), scene.lights, glm::dvec3(0.0)};
    if (ctx.options->maxScatterings > 0) walk.maxScatterings = ctx.options->maxScatterings;
    walk.minScatterings = ctx.options->minScatterings;
    // --env: its sun is among the lights; paths that leave read the rest.
    if (scene.env)
        walk.environment = [&scene](const glm::dvec3& d) { return scene.env.radiance(d); };
    const size_t count = static_cast<size_t>(points.count);
    const glm::dvec3 eye(ctx.eye);

    // The camera ray of each covered pixel, through its G-buffer point.
    std::vector<SurfaceHit> hits(count);
    std::vector<char> seen(count, 0);
    parallelFor(count, 256, [&](size_t begin, size_t end) {
        for (size_t k = begin; k < end; ++k) {
            const float* p = &points.host[k * 4];
            const glm::dvec3 dir = glm::normalize(glm::dvec3(p[0], p[1], p[2]) - eye);
            seen[k] = boundary_->intersect(eye, dir, kInfinity, hits[k]) &&
                      glm::dot(hits[k].normal, dir) < 0;
        }
    });

    const RenderOptions& o = *ctx.options;
    // Pass s draws its own streams (below): at most 2^20 passes in all.
    const int spp = std::min(o.spp > 0 ? o.spp : (o.timeSeconds > 0 ? (1 << 20) : kDefaultSpp),
                             (1 << 20) - o.sppOffset);
    const uint64_t seed = frameSeed(ctx);
    std::vector<glm::dvec3> sum(count, glm::dvec3(0.0));
    std::atomic<long long> vertices{0}, nee{0}, unsettled{0};
    auto tally = [&](const WalkCounters& c) {
        vertices += c.vertices;
        nee += c.nee;
        unsettled += c.neeUnsettled;
    };
    const bool timed = o.timeSeconds > 0;
    Progress progress("volumetric: " + std::to_string(count) + " pixels",
                      timed ? static_cast<long long>(o.timeSeconds * 1000) : spp);
    // --estimator light: each pass traces as many photons as there are
    // covered pixels, in ranges whose connections are summed in range order
    // (the same bytes for any thread count).
    const bool photons = o.estimator == VolumetricEstimator::Light;
    if (photons && scene.env)
        fail(
            "--env with --method volumetric needs --estimator camera (photons leave only the "
            "point and directional lights)");
    const size_t perPass = std::max<size_t>(count, 1);
    std::vector<size_t> pixelOf(count);  // row 0 at the top, as the light tracer's
    for (size_t k = 0; k < count; ++k) {
        const int p = points.pixel[k], x = p % ctx.width, y = p / ctx.width;
        pixelOf[k] = static_cast<size_t>(ctx.height - 1 - y) * ctx.width + x;
    }
    Pinhole pinhole;
    pinhole.eye = eye;
    pinhole.target = glm::dvec3(scene.camera.target);
    pinhole.up = glm::dvec3(scene.camera.up);
    pinhole.fovYDegrees = scene.camera.fovYDegrees;
    pinhole.width = ctx.width;
    pinhole.height = ctx.height;
    auto lightPass = [&](uint64_t s) {
        constexpr size_t kRange = 1024;
        const size_t ranges = (perPass + kRange - 1) / kRange;
        std::vector<std::vector<std::pair<int, glm::dvec3>>> added(ranges);
        parallelFor(ranges, 1, [&](size_t begin, size_t end) {
            WalkCounters c;
            for (size_t r = begin; r < end && !ctx.stopping(); ++r) {
                const size_t first = r * kRange, n = std::min(kRange, perPass - first);
                traceLight(
                    walk, pinhole, ctx.boundingRadius, s * perPass + first, n, seed,
                    [&, r](int pixel, const glm::dvec3& l) { added[r].emplace_back(pixel, l); }, c);
            }
            tally(c);
        });
        std::vector<glm::dvec3> image(static_cast<size_t>(ctx.width) * ctx.height, glm::dvec3(0.0));
        for (const auto& range : added)
            for (const auto& [pixel, l] : range) image[static_cast<size_t>(pixel)] += l;
        for (size_t k = 0; k < count; ++k)
            sum[k] += image[pixelOf[k]] / static_cast<double>(perPass);
    };
    int done = 0;
    while (done < spp) {
        const uint64_t s = static_cast<uint64_t>(o.sppOffset) + static_cast<uint64_t>(done);
        if (photons)
            lightPass(s);
        else
            parallelFor(count, 64, [&](size_t begin, size_t end) {
                if (ctx.stopping()) return;  // the pass is dropped below
                WalkCounters c;
                for (size_t k = begin; k < end; ++k) {
                    if (!seen[k]) continue;
                    // Seeded by pixel, not by point: a run over a material's
                    // points alone draws what the whole frame's would there.
                    Rng rng(seed, (static_cast<uint64_t>(points.pixel[k]) << 20u) | s);
                    const glm::dvec3 toEye = glm::normalize(eye - hits[k].position);
                    sum[k] += exitantRadiance(walk, hits[k], toEye, rng, c);
                }
                tally(c);
            });
        ctx.checkCancel();
        ++done;
        const double seconds = timer.ms() / 1000.0;
        progress.update(timed ? static_cast<long long>(std::min(seconds, o.timeSeconds) * 1000)
                              : done);
        if (timed && seconds >= o.timeSeconds) break;
    }
    progress.finish();

    // B_eq: what the composite's exit term (either) turns into the volumetric radiance.
    const double eta = ctx.material->eta;
    const double exit = exitScale(o.exit, eta);
    std::vector<float> out(count * 4, 0.0f);
    for (size_t k = 0; k < count; ++k) {
        if (!seen[k]) continue;
        const glm::dvec3 toEye = glm::normalize(eye - hits[k].position);
        const double ft = fresnelTransmittance(
                              eta, std::abs(glm::dot(boundary_->shadingNormal(hits[k]), toEye))) *
                          exit;
        const glm::dvec3 b =
            ft > 0 ? sum[k] / static_cast<double>(done) * (M_PI / ft) : glm::dvec3(0.0);
        for (int c = 0; c < 3; ++c) out[k * 4 + static_cast<size_t>(c)] = static_cast<float>(b[c]);
    }
    if (count > 0)
        cl_.queue().enqueueWriteBuffer(radiosity, CL_TRUE, 0, out.size() * sizeof(float),
                                       out.data());
    stats.set("volumetric_spp", done);
    if (photons) stats.set("volumetric_photons", static_cast<double>(perPass) * done);
    stats.set("volumetric_vertices", static_cast<double>(vertices.load()));
    stats.set("volumetric_nee", static_cast<double>(nee.load()));
    stats.set("volumetric_nee_unsettled", static_cast<double>(unsettled.load()));
    stats.set("rd_evaluations", 0.0);
}

}  // namespace tsis
