#include "render/method_pyramid.h"

#include "render/surface_points.h"

namespace tsis {

PyramidMethod::PyramidMethod(ClRuntime& cl) : cl_(cl), pyramid_(cl) {}

void PyramidMethod::addPasses(FrameGraph& graph, FrameContext& ctx) {
    graph.addPass({"pyramid_build",
                   {"flux_atlas_cl", "position_atlas_cl", "normal_atlas_cl"},
                   {"flux_pyramid"},
                   [this, &ctx] {
                       pyramid_.build(ctx.fluxAtlas, ctx.positionAtlas, ctx.normalAtlas,
                                      ctx.atlasResolution);
                       ctx.stats->addStage("pyramid_build", pyramid_.lastBuildMs());
                   },
                   true});
    graph.addPass(
        {"pyramid_gather",
         {"flux_pyramid", "points_cl"},
         {"radiosity_cl"},
         [this, &ctx] {
             // Any two surface points are at most the bounding sphere's diameter apart.
             if (rd_.update(ctx.scene->material, 2.0 * ctx.boundingRadius * 1.001))
                 table_ = cl::Buffer(cl_.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                                     rd_.table().rgba.size() * sizeof(float),
                                     const_cast<float*>(rd_.table().rgba.data()));
             const float epsilon = ctx.options->pyramidEpsilon;
             const float ell = static_cast<float>(smallestMeanFreePath(ctx.scene->material));
             const std::vector<int> order = FluxPyramid::tileOrder(ctx.pointPixel, ctx.width);
             if (!order.empty()) {
                 if (orderCapacity_ < order.size()) {
                     order_ =
                         cl::Buffer(cl_.context(), CL_MEM_READ_ONLY, order.size() * sizeof(int));
                     orderCapacity_ = order.size();
                 }
                 cl_.queue().enqueueWriteBuffer(order_, CL_FALSE, 0, order.size() * sizeof(int),
                                                order.data());
             }
             pyramid_.gather(ctx.points, order_, ctx.pointCount, epsilon, ell, table_,
                             rd_.table().info, ctx.radiosity);
             ctx.stats->addStage("pyramid_gather", pyramid_.lastGatherMs());
             ctx.stats->set("pyramid_epsilon", epsilon);
             ctx.stats->set("rd_evaluations", static_cast<double>(pyramid_.lastEvaluations()));
         },
         true});
}

}  // namespace tsis
