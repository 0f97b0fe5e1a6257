#include "render/method_pyramid.h"

#include <algorithm>
#include <cmath>

#include "render/sparse_pixels.h"
#include "render/surface_points.h"
#include "util/hash.h"
#include "util/timer.h"

namespace tsis {

PyramidMethod::PyramidMethod(ClRuntime& cl) : cl_(cl), tree_(cl), interpolation_(cl), atlas_(cl) {}

void PyramidMethod::addPasses(FrameGraph& graph, const FrameContext& ctx) {
    const auto tree = graph.create<Marker>("flux_tree");
    graph.addPass(
        "pyramid_build",
        [&](FrameGraph::Builder& b) {
            b.read(ctx.fluxAtlas);
            b.read(ctx.positionAtlas);
            b.read(ctx.normalAtlas);
            b.write(tree);
        },
        [this, &ctx](FrameGraph::Resources& res) {
            res.setDeviceMs(build(ctx, res.read(ctx.fluxAtlas), res.read(ctx.positionAtlas),
                                  res.read(ctx.normalAtlas), res.stats()));
        });
    graph.addPass(
        "pyramid_gather",
        [&](FrameGraph::Builder& b) {
            b.read(tree);
            b.read(ctx.points);
            if (ctx.options->pyramidCache != PyramidCache::Pixels) b.read(ctx.pointUvs);
            b.write(ctx.radiosity);
        },
        [this, &ctx](FrameGraph::Resources& res) {
            const SurfacePoints& points = res.read(ctx.points);
            res.setDeviceMs(
                gather(ctx, points, ctx.radiosityBuffer(res, points.count), res.stats()));
        });
}

double PyramidMethod::build(const FrameContext& ctx, const AtlasCl& flux, const AtlasCl& position,
                            const AtlasCl& normal, FrameStats& stats) {
    // The leaves' order depends on the positions only: again when the mesh or
    // the atlas resolution changed.
    if (position.version != leavesVersion_) {
        Timer t;
        const size_t texels = static_cast<size_t>(ctx.atlasResolution) * ctx.atlasResolution;
        std::vector<float> positions(texels * 4);
        cl_.queue().enqueueReadBuffer(position.buffer, CL_TRUE, 0, positions.size() * sizeof(float),
                                      positions.data());
        tree_.setLeaves(positions);
        leavesVersion_ = position.version;
        // The mean texel's side, for the grid of B over the atlas.
        size_t covered = 0;
        for (size_t i = 0; i < texels; ++i) covered += positions[i * 4 + 3] > 0 ? 1 : 0;
        texelMm_ = covered > 0 ? std::sqrt(ctx.scene->mesh.surfaceArea() / double(covered)) : 0;
        atlasPositions_ = std::move(positions);
        stats.addStage("pyramid_order", t.ms());
    }
    // The sums change only with the flux (a camera-only frame keeps them).
    const bool current = flux.version == builtFluxVersion_ && leavesVersion_ == builtLeavesVersion_;
    if (!current) {
        // The leaves' positions and areas stay while the geometry atlas does.
        const bool fluxOnly =
            leavesVersion_ == builtLeavesVersion_ && normal.version == builtNormalVersion_;
        tree_.build(flux.buffer, position.buffer, normal.buffer, fluxOnly);
        builtFluxVersion_ = flux.version;
        builtLeavesVersion_ = leavesVersion_;
        builtNormalVersion_ = normal.version;
    }
    stats.set("pyramid_rebuilt", current ? 0.0 : 1.0);
    stats.set("pyramid_leaves", static_cast<double>(tree_.leafTexels().size()));
    stats.set("pyramid_nodes", static_cast<double>(tree_.topology().size()));
    stats.set("pyramid_depth", tree_.depth());
    return current ? 0.0 : tree_.lastBuildMs();
}

double PyramidMethod::gather(const FrameContext& ctx, const SurfacePoints& points,
                             cl::Buffer& radiosity, FrameStats& stats) {
    if (rd_.update(ctx.profile(), ctx.maxDistance())) ++tableVersion_;
    const RenderOptions& o = *ctx.options;
    const double ell = smallestMeanFreePath(*ctx.material);
    // B on the surface: what the node sums, the table and the descent make.
    const uint64_t surfaceKey = Hasher()
                                    .add(builtFluxVersion_)
                                    .add(builtLeavesVersion_)
                                    .add(builtNormalVersion_)
                                    .add(tableVersion_)
                                    .add(o.pyramidEpsilon)
                                    .add(ell)
                                    .digest();
    // Only the camera moved: B on the surface is the last frame's.
    const bool cameraOnly = surfaceKey == lastSurfaceKey_ && ctx.cameraMoved;
    lastSurfaceKey_ = surfaceKey;
    const bool fromAtlas =
        !points.uvs.empty() && (o.pyramidCache == PyramidCache::Texture ||
                                (o.pyramidCache == PyramidCache::Camera && cameraOnly));
    stats.set("pyramid_from_atlas", fromAtlas ? 1.0 : 0.0);
    stats.set("pyramid_epsilon", o.pyramidEpsilon);
    return fromAtlas ? gatherFromAtlas(ctx, points, surfaceKey, ell, radiosity, stats)
                     : gatherAtPixels(ctx, points, ell, radiosity, stats);
}

uint64_t PyramidMethod::copyKey(const FrameContext& ctx) {
    const RenderOptions& o = *ctx.options;
    return Hasher(ctx.lighting)
        .add(ctx.profile().key)
        .add(ctx.maxDistance())
        .add(o.pyramidEpsilon)
        .add(o.pyramidStride)
        .add(smallestMeanFreePath(*ctx.material))
        .add(ctx.atlasResolution)
        .digest();
}

const AtlasRadiosity* PyramidMethod::atlasRadiosity(const FrameContext& ctx) {
    const PyramidCache cache = ctx.options->pyramidCache;
    if (cache == PyramidCache::Pixels || atlasKey_ == 0 || copyKey_ != copyKey(ctx)) return nullptr;
    if (cache == PyramidCache::Camera && !ctx.cameraMoved) return nullptr;
    host_.radiosity = &atlas_.hostValues();
    return &host_;
}

double PyramidMethod::gatherTree(const cl::Buffer& points, const cl::Buffer& order, int count,
                                 float epsilon, double ell, cl::Buffer& out) {
    tree_.gather(points, order, count, epsilon, static_cast<float>(ell), rd_.device(cl_.context()),
                 rd_.table().info, out);
    return tree_.lastGatherMs();
}

double PyramidMethod::gatherAtPixels(const FrameContext& ctx, const SurfacePoints& points,
                                     double ell, cl::Buffer& radiosity, FrameStats& stats) {
    const RenderOptions& o = *ctx.options;
    const uint64_t pointsKey =
        Hasher().addAll(points.pixel).addAll(points.host).add(ctx.width).add(ctx.height).digest();
    const auto [stride, maxCornerMm] =
        sparseGridFor(pixelMm(ctx.scene->camera, ctx.height), ell, o.pyramidStride);
    // The plan follows the points (the camera's G-buffer), not the lights: a
    // frame that moves only a light keeps it, and its buffers on the device
    // (planning is ~1.3 ms of host time at 512², the device idle meanwhile).
    const uint64_t planKey = Hasher(pointsKey).add(stride).add(maxCornerMm).digest();
    const SparsePixels& plan = plan_;
    const bool replan = planKey != planKey_;
    if (replan) {
        plan_ =
            planSparsePixels(points.pixel, points.host, ctx.width, ctx.height, stride, maxCornerMm);
        interpolation_.upload(plan_);
        planKey_ = planKey;
    }
    stats.set("pyramid_plan_reused", replan ? 0.0 : 1.0);
    const std::vector<int>& order = plan.evaluate;
    const double ms = gatherTree(points.xyz, interpolation_.order(), static_cast<int>(order.size()),
                                 o.pyramidEpsilon, ell, radiosity);
    // The rest from the grid, in the same buffer (no trip through the host).
    interpolation_.run(radiosity);
    if (!plan.interpolate.empty()) stats.addStage("pyramid_interpolate", interpolation_.lastMs());
    stats.set("pyramid_stride", stride);
    stats.set("pyramid_evaluated_pixels", static_cast<double>(order.size()));
    stats.set("pyramid_interpolated_pixels", static_cast<double>(plan.interpolate.size()));
    stats.set("rd_evaluations", static_cast<double>(tree_.lastEvaluations()));
    return ms;
}

double PyramidMethod::gatherFromAtlas(const FrameContext& ctx, const SurfacePoints& points,
                                      uint64_t surfaceKey, double ell, cl::Buffer& radiosity,
                                      FrameStats& stats) {
    const RenderOptions& o = *ctx.options;
    // The grid over the atlas by the same rule as the pixels', the texel's
    // side for the pixel's.
    const auto [stride, maxCornerMm] = sparseGridFor(texelMm_, ell, o.pyramidStride);
    // A texel more than a few texels' sides away in space is another surface
    // packed beside the point's chart.
    const auto maxMm =
        static_cast<float>(std::min(kSparseMaxCornerEll * ell, kLookupTexels * texelMm_));
    const uint64_t planKey = Hasher()
                                 .add(leavesVersion_)
                                 .add(ctx.atlasResolution)
                                 .add(stride)
                                 .add(maxCornerMm)
                                 .add(maxMm)
                                 .digest();
    atlas_.plan(atlasPositions_, ctx.atlasResolution, stride, maxCornerMm, maxMm, planKey);
    double ms = 0;
    const uint64_t atlasKey = Hasher(surfaceKey).add(planKey).digest();
    const bool made = atlasKey != atlasKey_;
    if (made) {
        ms += gatherTree(atlas_.points(), atlas_.order(), atlas_.evaluated(), o.pyramidEpsilon, ell,
                         atlas_.values());
        atlas_.interpolate();
        stats.addStage("pyramid_atlas_interpolate", atlas_.lastInterpolateMs());
        stats.set("rd_evaluations", static_cast<double>(tree_.lastEvaluations()));
        atlasKey_ = atlasKey;
        copyKey_ = copyKey(ctx);
        // B itself is read back when a frame first asks (atlasRadiosity).
        host_ = {&atlas_.ringPositions(), nullptr, ctx.atlasResolution, maxMm, planKey, atlasKey};
    }
    const std::vector<int> none = atlas_.lookup(points, maxMm, radiosity);
    stats.addStage("pyramid_atlas_lookup", atlas_.lastLookupMs());
    // The points no texel of their surface is around: gathered at their pixel.
    if (!none.empty()) {
        const size_t bytes = none.size() * sizeof(int);
        cl_.queue().enqueueWriteBuffer(offAtlas_.reserve(cl_.context(), bytes), CL_TRUE, 0, bytes,
                                       none.data());
        ms += gatherTree(points.xyz, offAtlas_.buffer, static_cast<int>(none.size()),
                         o.pyramidEpsilon, ell, radiosity);
    }
    stats.set("pyramid_gathered_off_atlas", static_cast<double>(none.size()));
    stats.set("pyramid_atlas_made", made ? 1.0 : 0.0);
    stats.set("pyramid_stride", stride);
    stats.set("pyramid_evaluated_pixels", made ? static_cast<double>(atlas_.evaluated()) : 0.0);
    stats.set("pyramid_atlas_texels", static_cast<double>(atlas_.covered()));
    return ms;
}

}  // namespace tsis
