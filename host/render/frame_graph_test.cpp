#include "render/frame_graph.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace tsis {
namespace {

// a → b → image; c writes something nobody reads.
struct Chain {
    FrameGraph graph;
    FrameGraphId<int> a, b, unused;
    FrameGraphId<std::string> image;
    std::vector<std::string> ran;

    Chain() {
        a = graph.create<int>("a");
        b = graph.create<int>("b");
        unused = graph.create<int>("unused");
        image = graph.create<std::string>("image");
        graph.addPass(
            "make_a", [&](FrameGraph::Builder& builder) { builder.write(a); },
            [&](FrameGraph::Resources& res) {
                ran.push_back("make_a");
                res.write(a) = 20;
            });
        graph.addPass(
            "make_unused", [&](FrameGraph::Builder& builder) { builder.write(unused); },
            [&](FrameGraph::Resources& res) {
                ran.push_back("make_unused");
                res.write(unused) = 1;
            });
        graph.addPass(
            "make_b",
            [&](FrameGraph::Builder& builder) {
                builder.read(a);
                builder.write(b);
            },
            [&](FrameGraph::Resources& res) {
                ran.push_back("make_b");
                res.write(b) = res.read(a) + 1;
            });
        graph.addPass(
            "make_image",
            [&](FrameGraph::Builder& builder) {
                builder.read(b);
                builder.write(image);
            },
            [&](FrameGraph::Resources& res) {
                ran.push_back("make_image");
                res.write(image) = "b=" + std::to_string(res.read(b));
            });
    }
};

TEST(FrameGraph, RunsWhatTheOutputNeedsInOrderAndCullsTheRest) {
    Chain c;
    FrameStats stats;
    c.graph.execute(stats, c.image);
    EXPECT_EQ(c.ran, (std::vector<std::string>{"make_a", "make_b", "make_image"}));
    EXPECT_EQ(c.graph.executed(), c.ran);
    EXPECT_EQ(c.graph.get(c.image), "b=21");
    EXPECT_EQ(c.graph.get(c.unused), 0) << "culled: never written";
    EXPECT_TRUE(c.graph.isRead(c.a));
    EXPECT_FALSE(c.graph.isRead(c.unused));
    EXPECT_FALSE(c.graph.isRead(c.image)) << "an output nobody reads";
}

// --stats' "graph": every pass with what it reads and writes, culled or not.
TEST(FrameGraph, DescribesItsPassesReadsWritesAndCulling) {
    Chain c;
    FrameStats stats;
    c.graph.execute(stats, c.image);
    const Json g = c.graph.describe();
    ASSERT_EQ(g.size(), 4u);
    EXPECT_EQ(g[1]["name"], "make_unused");
    EXPECT_EQ(g[1]["culled"], true);
    EXPECT_EQ(g[2]["name"], "make_b");
    EXPECT_EQ(g[2]["reads"], Json::array({"a"}));
    EXPECT_EQ(g[2]["writes"], Json::array({"b"}));
    EXPECT_EQ(g[2]["culled"], false);
}

TEST(FrameGraph, RecordsOneStagePerPassRunWithDeviceTimeAndBytes) {
    FrameGraph graph;
    const auto x = graph.create<int>("x");
    graph.addPass(
        "upload", [&](FrameGraph::Builder& b) { b.write(x); },
        [&](FrameGraph::Resources& res) {
            res.addBytes(1000);
            res.addBytes(24);
            res.setDeviceMs(7.5);
            res.write(x) = 1;
        });
    FrameStats stats;
    graph.execute(stats, x);
    ASSERT_EQ(stats.stages.size(), 1u);
    EXPECT_EQ(stats.stages[0].name, "upload");
    EXPECT_EQ(stats.stages[0].ms, 7.5);
    EXPECT_EQ(stats.stages[0].bytes, 1024);
    EXPECT_GE(stats.stages[0].cpuMs, 0.0) << "the process' CPU time over the pass";
}

TEST(FrameGraph, ImportedResourcesCountAsWrittenAndKeepTheirValue) {
    FrameGraph graph;
    int kept = 5;
    const auto in = graph.import("kept", kept);
    const auto out = graph.create<int>("out");
    graph.addPass(
        "double",
        [&](FrameGraph::Builder& b) {
            b.read(in);
            b.write(out);
        },
        [&](FrameGraph::Resources& res) { res.write(out) = 2 * res.read(in); });
    FrameStats stats;
    graph.execute(stats, out);
    EXPECT_EQ(graph.get(out), 10);
}

using FrameGraphDeathTest = ::testing::Test;

TEST(FrameGraphDeathTest, ReadingWhatNoEarlierPassWritesIsABug) {
    EXPECT_DEATH(
        {
            FrameGraph graph;
            const auto never = graph.create<int>("never");
            const auto out = graph.create<int>("out");
            graph.addPass(
                "reader",
                [&](FrameGraph::Builder& b) {
                    b.read(never);
                    b.write(out);
                },
                [](FrameGraph::Resources&) {});
            FrameStats stats;
            graph.execute(stats, out);
        },
        "pass 'reader' reads 'never' which no earlier pass writes");
}

TEST(FrameGraphDeathTest, ReadingAfterTheWriterIsOrderedByAddition) {
    // The writer added after the reader does not count: passes run in order.
    EXPECT_DEATH(
        {
            FrameGraph graph;
            const auto x = graph.create<int>("x");
            const auto out = graph.create<int>("out");
            graph.addPass(
                "reader",
                [&](FrameGraph::Builder& b) {
                    b.read(x);
                    b.write(out);
                },
                [](FrameGraph::Resources&) {});
            graph.addPass(
                "late_writer", [&](FrameGraph::Builder& b) { b.write(x); },
                [](FrameGraph::Resources&) {});
            FrameStats stats;
            graph.execute(stats, out);
        },
        "reads 'x' which no earlier pass writes");
}

TEST(FrameGraphDeathTest, ResolvingAnUndeclaredResourceIsABug) {
    EXPECT_DEATH(
        {
            FrameGraph graph;
            const auto x = graph.create<int>("x");
            const auto out = graph.create<int>("out");
            graph.addPass(
                "sneaky", [&](FrameGraph::Builder& b) { b.write(out); },
                [&](FrameGraph::Resources& res) { res.write(out) = res.read(x); });
            FrameStats stats;
            graph.execute(stats, out);
        },
        "pass 'sneaky' reads 'x' without declaring it");
}

TEST(FrameGraphDeathTest, AnOutputNothingWritesIsABug) {
    EXPECT_DEATH(
        {
            FrameGraph graph;
            const auto out = graph.create<int>("lonely");
            FrameStats stats;
            graph.execute(stats, out);
        },
        "nothing writes output 'lonely'");
}

}  // namespace
}  // namespace tsis
