#include "render/ray_caster.h"

#include <gtest/gtest.h>

namespace tsis {
namespace {

// A unit square in the xz-plane at y = 0 (two triangles) plus a degenerate one.
Mesh square() {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}, {2, 0, 0}};
    m.triangles = {{0, 2, 1}, {0, 3, 2}, {0, 1, 4}};
    return m;
}

TEST(RayCaster, SegmentsThroughTheSquareAreBlockedOthersClear) {
    const RayCaster rays(square());
    EXPECT_EQ(rays.triangleCount(), 2u) << "the degenerate triangle is skipped";
    EXPECT_FALSE(rays.segmentClear({0.3, 1, 0.6}, {0.3, -1, 0.6}));
    EXPECT_FALSE(rays.segmentClear({0.9, 1, 0.9}, {0.1, -1, 0.2}));   // slanted
    EXPECT_TRUE(rays.segmentClear({1.5, 1, 0.5}, {1.5, -1, 0.5}));    // beside it
    EXPECT_TRUE(rays.segmentClear({0.5, 1, 0.5}, {0.5, 1e-3, 0.5}));  // stops short
    EXPECT_TRUE(rays.segmentClear({0.5, 1e-4, 0.5}, {0.5, 5, 0.5}));  // leaves upwards
    EXPECT_TRUE(rays.segmentClear({0.5, 1, 0.5}, {0.5, 1, 0.5}));     // a point
}

TEST(RayCaster, EmptyMeshBlocksNothing) {
    const RayCaster rays(Mesh{});
    EXPECT_TRUE(rays.segmentClear({0, 1, 0}, {0, -1, 0}));
}

}  // namespace
}  // namespace tsis
