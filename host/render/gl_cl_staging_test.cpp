#include "render/gl_cl_staging.h"

#include <gtest/gtest.h>

namespace tsis {
namespace {

// The radiosity is a resource the graph creates each frame, not an imported
// one that counts as written: a method whose passes forget to write it stops
// the frame at the graph's check, which names it, before any pass runs.
TEST(GlClStagingDeathTest, AMethodThatForgetsTheRadiosityIsACheckNamingIt) {
    EXPECT_DEATH(
        {
            FrameGraph graph;
            FrameContext ctx;
            GlClStaging staging;
            staging.declare(graph, ctx);
            graph.addPass(
                "points", [&](FrameGraph::Builder& b) { b.write(ctx.points); },
                [](FrameGraph::Resources&) {});
            // The forgetful method: reads the points, writes only its own table.
            const auto table = graph.create<Marker>("table");
            graph.addPass(
                "forgetful",
                [&](FrameGraph::Builder& b) {
                    b.read(ctx.points);
                    b.write(table);
                },
                [](FrameGraph::Resources&) {});
            const std::vector<FrameContext> runs{ctx};
            const auto image = staging.addReadback(graph, runs, {});
            FrameStats stats;
            graph.execute(stats, image);
        },
        "pass 'read_radiosity' reads 'radiosity_cl' which no earlier pass writes");
}

}  // namespace
}  // namespace tsis
