#include "render/method_reference.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "mesh/media.h"
#include "util/error.h"
#include "util/note.h"
#include "util/progress.h"
#include "util/timer.h"

namespace tsis {

namespace {

// Rd evaluations per gather call: small enough for the progress line to move
// (≈ 0.2 s each on a 2-core PoCL device), large enough to keep the device busy.
constexpr double kEvaluationsPerChunk = 1 << 28;

}  // namespace

ReferenceMethod::ReferenceMethod(ClRuntime& cl) : cl_(cl), gatherer_(cl) {}

double ReferenceMethod::defaultSpacing(const Material& m) {
    return 0.5 * smallestMeanFreePath(m);
}

std::string ReferenceCost::describe() const {
    char s[256];
    // 0.56 G evaluations/s: bench_kernels on a 2-core PoCL device (docs/guide/performance.md).
    std::snprintf(s, sizeof s,
                  "%.3g M surface points (%.2g GB), %.2g Rd evaluations per frame (%.2g h at "
                  "0.56 G/s)",
                  points / 1e6, bytes / 1e9, evaluations, evaluations / 0.56e9 / 3600);
    return s;
}

ReferenceCost ReferenceMethod::estimate(const Mesh& mesh, double spacing, double pixels) {
    ReferenceCost c;
    c.points = surfacePointCount(mesh, spacing);
    // A SurfacePoint and a TsisSample on the host, the sample again on the device.
    c.bytes = double(c.points) * double(sizeof(SurfacePoint) + 2 * sizeof(TsisSample));
    c.evaluations = double(c.points) * pixels;
    return c;
}

void ReferenceMethod::checkCost(const ReferenceCost& cost, bool force) {
    if (cost.withinBounds()) return;
    if (!force)
        fail("reference: ", cost.describe(), "; more than the bounds of ",
             kMaxReferencePoints / 1e6, " M points and ", kMaxReferenceEvaluations,
             " evaluations (use a larger --spacing, a smaller image, or --force)");
    emitNote("reference: " + cost.describe() + " (--force)");
}

void ReferenceMethod::addPasses(FrameGraph& graph, const FrameContext& ctx) {
    const double spacing =
        ctx.options->spacingMm > 0 ? ctx.options->spacingMm : defaultSpacing(*ctx.material);
    const auto samples = graph.create<Marker>("reference_samples");
    graph.addPass(
        "reference_points", [&](FrameGraph::Builder& b) { b.write(samples); },
        [this, &ctx, spacing](FrameGraph::Resources& res) {
            if (!points_.holds(*ctx.scene, spacing, ctx.albedo))
                checkCost(estimate(ctx.scene->mesh, spacing,
                                   double(ctx.options->width) * ctx.options->height),
                          ctx.options->force);
            const bool built =
                points_.update(*ctx.scene, spacing, "reference", ctx.albedo, ctx.cancel);
            const std::vector<SurfacePoint>& pts = points_.points();
            if (built) {
                // At least one (zero) sample: a CL buffer cannot be empty.
                std::vector<TsisSample> s(std::max<size_t>(1, pts.size()), TsisSample{});
                for (size_t i = 0; i < pts.size(); ++i) {
                    const glm::vec3 w = pts[i].irradiance * pts[i].area;
                    s[i] = {pts[i].position.x,
                            pts[i].position.y,
                            pts[i].position.z,
                            -1.0f,
                            w.x,
                            w.y,
                            w.z,
                            mediumTag(pts[i].medium)};
                }
                samples_ = cl::Buffer(cl_.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                                      s.size() * sizeof(TsisSample), s.data());
            }
            res.stats().set("reference_spacing_mm", spacing);
            res.stats().set("reference_point_count", static_cast<double>(pts.size()));
            res.stats().set("reference_points_cached", !built);
        });
    graph.addPass(
        "reference_gather",
        [&](FrameGraph::Builder& b) {
            b.read(samples);
            b.read(ctx.points);
            b.write(ctx.radiosity);
        },
        [this, &ctx](FrameGraph::Resources& res) {
            const SurfacePoints& points = res.read(ctx.points);
            cl::Buffer& out = ctx.radiosityBuffer(res, points.count);
            res.stats().set("rd_evaluations",
                            static_cast<double>(points.count) * points_.points().size());
            if (points.count > 0) res.setDeviceMs(gather(ctx, points, out));
        });
}

double ReferenceMethod::gather(const FrameContext& ctx, const SurfacePoints& points,
                               cl::Buffer& radiosity) {
    rd_.update(ctx.profile(), ctx.maxDistance());
    const cl::Buffer& table = rd_.device(cl_.context());
    const int n = static_cast<int>(points_.points().size());
    const int count = points.count;
    // Output points in chunks (sub-buffers, so the origin must be aligned as the
    // device asks) to show progress and keep each kernel run short.
    const size_t alignPoints =
        std::max<size_t>(1, cl_.device().getInfo<CL_DEVICE_MEM_BASE_ADDR_ALIGN>() / 8 / 16);
    size_t chunk = static_cast<size_t>(kEvaluationsPerChunk / std::max(1, n));
    const size_t unit = std::max<size_t>(alignPoints, 256);
    chunk = std::max(unit, chunk / unit * unit);
    Progress progress(
        "reference: gather " + std::to_string(count) + " pixels × " + std::to_string(n) + " points",
        count);
    double ms = 0;
    cl::Buffer xyz = points.xyz;  // a handle: createSubBuffer is not const
    for (size_t begin = 0; begin < static_cast<size_t>(count); begin += chunk) {
        const size_t len = std::min(chunk, static_cast<size_t>(count) - begin);
        const cl_buffer_region region{begin * 16, len * 16};
        cl::Buffer in =
            xyz.createSubBuffer(CL_MEM_READ_WRITE, CL_BUFFER_CREATE_TYPE_REGION, &region);
        cl::Buffer out =
            radiosity.createSubBuffer(CL_MEM_READ_WRITE, CL_BUFFER_CREATE_TYPE_REGION, &region);
        gatherer_.run(in, static_cast<int>(len), samples_, n, table, rd_.table().info, out);
        ms += gatherer_.lastMs();  // waits for the chunk
        ctx.checkCancel();
        progress.update(static_cast<long long>(begin) + static_cast<long long>(len));
    }
    progress.finish();
    return ms;
}

}  // namespace tsis
