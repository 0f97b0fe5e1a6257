// The reference's cost bound (no GL or CL: the estimate makes no point).
#include "render/method_reference.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "mesh/builtin.h"
#include "support/error_of.h"

namespace tsis {
namespace {

using ::testing::HasSubstr;

Mesh sphere() {
    Mesh m = builtinMesh("sphere");
    normalizeMesh(m, 10.0);
    ensureNormals(m);
    return m;
}

TEST(ReferenceCost, EstimateMatchesThePointsMade) {
    const Mesh m = sphere();
    const ReferenceCost c = ReferenceMethod::estimate(m, 0.1, 64 * 64);
    EXPECT_EQ(c.points, placeSurfacePoints(m, 0.1).size());
    EXPECT_EQ(c.evaluations, double(c.points) * 64 * 64);
    EXPECT_GT(c.bytes, double(c.points) * sizeof(SurfacePoint));
    EXPECT_TRUE(c.withinBounds());
    EXPECT_NO_THROW(ReferenceMethod::checkCost(c, false));
}

// The run: --spacing 0.002 on the 10 mm sphere at 512².
TEST(ReferenceCost, TooFineASpacingIsRefusedWithTheEstimateUnlessForced) {
    const ReferenceCost c = ReferenceMethod::estimate(sphere(), 0.002, 512.0 * 512.0);
    EXPECT_FALSE(c.withinBounds());
    const std::string msg = test::errorOf([&] { ReferenceMethod::checkCost(c, false); });
    EXPECT_THAT(msg, HasSubstr("M surface points"));
    EXPECT_THAT(msg, HasSubstr("GB"));
    EXPECT_THAT(msg, HasSubstr("--force"));
    testing::internal::CaptureStderr();
    EXPECT_NO_THROW(ReferenceMethod::checkCost(c, true));
    EXPECT_THAT(testing::internal::GetCapturedStderr(), HasSubstr("tsis: note: reference: "));
}

}  // namespace
}  // namespace tsis
