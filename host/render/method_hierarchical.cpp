#include "render/method_hierarchical.h"

#include <atomic>

#include "util/parallel.h"
#include "util/timer.h"

namespace tsis {

HierarchicalMethod::HierarchicalMethod(ClRuntime& cl) : cl_(cl) {}

void HierarchicalMethod::addPasses(FrameGraph& graph, FrameContext& ctx) {
    const double spacing = ctx.options->spacingMm > 0 ? ctx.options->spacingMm
                                                      : smallestMeanFreePath(ctx.scene->material);
    graph.addPass({"hierarchical_build", {}, {"hierarchical_tree"}, [this, &ctx, spacing] {
                       build(ctx, spacing);
                   }});
    graph.addPass(
        {"hierarchical_eval", {"hierarchical_tree", "points_cl"}, {"radiosity_cl"}, [this, &ctx] {
             evaluate(ctx);
         }});
}

void HierarchicalMethod::build(FrameContext& ctx, double spacing) {
    // Candidates at half the spacing so the thinned set covers the surface evenly.
    const bool rebuilt = candidates_.update(*ctx.scene, 0.5 * spacing, "hierarchical");
    if (rebuilt) tree_ = FluxOctree(poissonThin(candidates_.points(), spacing));
    ctx.stats->set("hierarchical_spacing_mm", spacing);
    ctx.stats->set("hierarchical_candidates", static_cast<double>(candidates_.points().size()));
    ctx.stats->set("hierarchical_points", static_cast<double>(tree_.sampleCount()));
    ctx.stats->set("hierarchical_nodes", static_cast<double>(tree_.nodeCount()));
    ctx.stats->set("hierarchical_cached", !rebuilt);
}

void HierarchicalMethod::evaluate(FrameContext& ctx) {
    rd_.update(ctx.scene->material, 2.0 * ctx.boundingRadius * 1.001);
    const float epsilon = ctx.options->epsilon;
    const size_t count = static_cast<size_t>(ctx.pointCount);
    std::vector<float> out(count * 4, 0.0f);
    std::atomic<long long> evaluations{0};
    parallelFor(count, 256, [&](size_t begin, size_t end) {
        long long evals = 0;
        for (size_t j = begin; j < end; ++j) {
            const float* p = &ctx.pointsHost[j * 4];
            const glm::vec3 b = tree_.radiosity({p[0], p[1], p[2]}, epsilon, rd_.table(), &evals);
            out[j * 4] = b.x;
            out[j * 4 + 1] = b.y;
            out[j * 4 + 2] = b.z;
        }
        evaluations += evals;
    });
    if (count > 0)
        cl_.queue().enqueueWriteBuffer(ctx.radiosity, CL_TRUE, 0, out.size() * sizeof(float),
                                       out.data());
    ctx.stats->set("hierarchical_epsilon", epsilon);
    ctx.stats->set("rd_evaluations", static_cast<double>(evaluations.load()));
}

}  // namespace tsis
