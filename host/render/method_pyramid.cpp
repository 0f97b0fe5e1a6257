#include "render/method_pyramid.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "render/sparse_pixels.h"
#include "render/surface_points.h"
#include "util/timer.h"

namespace tsis {

PyramidMethod::PyramidMethod(ClRuntime& cl) : cl_(cl), pyramid_(cl) {}

namespace {

// A pixel's size at the target's distance (mm).
double pixelMm(const Camera& camera, int height) {
    return 2.0 * std::tan(glm::radians(double(camera.fovYDegrees)) / 2) *
           glm::length(camera.eye - camera.target) / height;
}

}  // namespace

int PyramidMethod::autoStride(const Camera& camera, int height, double ell) {
    const double pixel = pixelMm(camera, height);
    int stride = 1;
    while (stride < kMaxAutoStride && 2 * stride * pixel <= kGridSpacing * ell) stride *= 2;
    return stride;
}

void PyramidMethod::addPasses(FrameGraph& graph, FrameContext& ctx) {
    graph.addPass({"pyramid_build",
                   {"flux_atlas_cl", "position_atlas_cl", "normal_atlas_cl"},
                   {"flux_pyramid"},
                   [this, &ctx] { build(ctx); },
                   true});
    graph.addPass({"pyramid_gather",
                   {"flux_pyramid", "points_cl"},
                   {"radiosity_cl"},
                   [this, &ctx] { gather(ctx); },
                   true});
}

void PyramidMethod::build(FrameContext& ctx) {
    // The leaves' order depends on the positions only: again when the mesh or
    // the atlas resolution changed.
    if (ctx.geometryVersion != leavesVersion_) {
        Timer t;
        const size_t texels = static_cast<size_t>(ctx.atlasResolution) * ctx.atlasResolution;
        std::vector<float> positions(texels * 4);
        cl_.queue().enqueueReadBuffer(ctx.positionAtlas, CL_TRUE, 0,
                                      positions.size() * sizeof(float), positions.data());
        pyramid_.setLeaves(positions);
        leavesVersion_ = ctx.geometryVersion;
        ctx.stats->addStage("pyramid_order", t.ms());
    }
    // The sums change only with the flux (a camera-only frame keeps them).
    const bool current =
        ctx.fluxKey != 0 && ctx.fluxKey == builtFluxKey_ && leavesVersion_ == builtLeavesVersion_;
    if (!current) {
        pyramid_.build(ctx.fluxAtlas, ctx.positionAtlas, ctx.normalAtlas);
        builtFluxKey_ = ctx.fluxKey;
        builtLeavesVersion_ = leavesVersion_;
    }
    ctx.stats->addStage("pyramid_build", current ? 0.0 : pyramid_.lastBuildMs());
    ctx.stats->set("pyramid_leaves", static_cast<double>(pyramid_.leafTexels().size()));
    ctx.stats->set("pyramid_nodes", static_cast<double>(pyramid_.topology().size()));
    ctx.stats->set("pyramid_depth", pyramid_.depth());
}

void PyramidMethod::gather(FrameContext& ctx) {
    // Any two surface points are at most the bounding sphere's diameter apart.
    rd_.update(ctx.scene->material, 2.0 * ctx.boundingRadius * 1.001);
    const RenderOptions& o = *ctx.options;
    const double ell = smallestMeanFreePath(ctx.scene->material);
    const int stride =
        o.pyramidStride > 0 ? o.pyramidStride : autoStride(ctx.scene->camera, ctx.height, ell);
    // Corners farther than twice a frontal cell's diagonal: a grazing or broken
    // surface, where B changes faster across the cell than the grid assumes.
    const double cellDiagonal = std::sqrt(2.0) * stride * pixelMm(ctx.scene->camera, ctx.height);
    const SparsePixels plan =
        planSparsePixels(ctx.pointPixel, ctx.pointsHost, ctx.width, ctx.height, stride,
                         static_cast<float>(std::min(kMaxCornerDistance * ell, 2 * cellDiagonal)));
    const std::vector<int>& order = plan.evaluate;
    if (!order.empty()) {
        if (orderCapacity_ < order.size()) {
            order_ = cl::Buffer(cl_.context(), CL_MEM_READ_ONLY, order.size() * sizeof(int));
            orderCapacity_ = order.size();
        }
        cl_.queue().enqueueWriteBuffer(order_, CL_FALSE, 0, order.size() * sizeof(int),
                                       order.data());
    }
    pyramid_.gather(ctx.points, order_, static_cast<int>(order.size()), o.pyramidEpsilon,
                    static_cast<float>(ell), rd_.device(cl_.context()), rd_.table().info,
                    ctx.radiosity);
    double ms = pyramid_.lastGatherMs();
    if (!plan.interpolate.empty()) {
        Timer t;
        std::vector<float> rgba(static_cast<size_t>(ctx.pointCount) * 4);
        const size_t bytes = rgba.size() * sizeof(float);
        cl_.queue().enqueueReadBuffer(ctx.radiosity, CL_TRUE, 0, bytes, rgba.data());
        interpolateSparsePixels(plan, rgba);
        cl_.queue().enqueueWriteBuffer(ctx.radiosity, CL_TRUE, 0, bytes, rgba.data());
        ctx.stats->addStage("pyramid_interpolate", t.ms());
    }
    ctx.stats->addStage("pyramid_gather", ms);
    ctx.stats->set("pyramid_epsilon", o.pyramidEpsilon);
    ctx.stats->set("pyramid_stride", stride);
    ctx.stats->set("pyramid_evaluated_pixels", static_cast<double>(order.size()));
    ctx.stats->set("pyramid_interpolated_pixels", static_cast<double>(plan.interpolate.size()));
    ctx.stats->set("rd_evaluations", static_cast<double>(pyramid_.lastEvaluations()));
}

}  // namespace tsis
