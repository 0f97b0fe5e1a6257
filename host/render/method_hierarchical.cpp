#include "render/method_hierarchical.h"

#include <algorithm>
#include <atomic>
#include <vector>

#include "util/parallel.h"
#include "util/timer.h"

namespace tsis {

HierarchicalMethod::HierarchicalMethod(ClRuntime& cl) : cl_(cl) {}

void HierarchicalMethod::addPasses(FrameGraph& graph, const FrameContext& ctx) {
    const double spacing =
        ctx.options->spacingMm > 0 ? ctx.options->spacingMm : smallestMeanFreePath(*ctx.material);
    const auto tree = graph.create<Marker>("hierarchical_tree");
    graph.addPass(
        "hierarchical_build", [&](FrameGraph::Builder& b) { b.write(tree); },
        [this, &ctx, spacing](FrameGraph::Resources& res) { build(ctx, spacing, res.stats()); });
    graph.addPass(
        "hierarchical_eval",
        [&](FrameGraph::Builder& b) {
            b.read(tree);
            b.read(ctx.points);
            b.write(ctx.radiosity);
        },
        [this, &ctx](FrameGraph::Resources& res) {
            const SurfacePoints& points = res.read(ctx.points);
            evaluate(ctx, points, ctx.radiosityBuffer(res, points.count), res.stats());
        });
}

void HierarchicalMethod::build(const FrameContext& ctx, double spacing, FrameStats& stats) {
    // Candidates at half the spacing so the thinned set covers the surface evenly.
    const bool rebuilt =
        candidates_.update(*ctx.scene, 0.5 * spacing, "hierarchical", ctx.albedo, ctx.cancel);
    if (rebuilt) {
        std::vector<std::vector<SurfacePoint>> byMedium;
        for (const SurfacePoint& s : poissonThin(candidates_.points(), spacing)) {
            if (s.medium >= byMedium.size()) byMedium.resize(s.medium + 1);
            byMedium[s.medium].push_back(s);
        }
        trees_.clear();
        for (const std::vector<SurfacePoint>& samples : byMedium) trees_.emplace_back(samples);
    }
    size_t samples = 0, nodes = 0;
    for (const FluxOctree& t : trees_) {
        samples += t.sampleCount();
        nodes += t.nodeCount();
    }
    stats.set("hierarchical_spacing_mm", spacing);
    stats.set("hierarchical_candidates", static_cast<double>(candidates_.points().size()));
    stats.set("hierarchical_points", static_cast<double>(samples));
    stats.set("hierarchical_nodes", static_cast<double>(nodes));
    stats.set("hierarchical_cached", !rebuilt);
}

void HierarchicalMethod::evaluate(const FrameContext& ctx, const SurfacePoints& points,
                                  cl::Buffer& radiosity, FrameStats& stats) {
    rd_.update(ctx.profile(), ctx.maxDistance());
    const float epsilon = ctx.options->epsilon;
    const size_t count = static_cast<size_t>(points.count);
    std::vector<float> out(count * 4, 0.0f);
    std::atomic<long long> evaluations{0};
    parallelFor(count, 256, [&](size_t begin, size_t end) {
        long long evals = 0;
        for (size_t j = begin; j < end; ++j) {
            const float* p = &points.host[j * 4];
            // The exit point's medium from its tag, 1 + medium (mesh/media.h).
            const size_t medium = static_cast<size_t>(std::max(p[3] - 1.0f, 0.0f));
            if (medium >= trees_.size()) continue;
            const glm::vec3 b =
                trees_[medium].radiosity({p[0], p[1], p[2]}, epsilon, rd_.table(), &evals);
            out[j * 4] = b.x;
            out[j * 4 + 1] = b.y;
            out[j * 4 + 2] = b.z;
        }
        evaluations += evals;
    });
    if (count > 0)
        cl_.queue().enqueueWriteBuffer(radiosity, CL_TRUE, 0, out.size() * sizeof(float),
                                       out.data());
    stats.set("hierarchical_epsilon", epsilon);
    stats.set("rd_evaluations", static_cast<double>(evaluations.load()));
}

}  // namespace tsis
