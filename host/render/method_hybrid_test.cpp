// The hybrid: its split, its agreement with a converged render, determinism.
#include <gtest/gtest.h>

#include <cstdio>

#include "support/render.h"

namespace tsis {
namespace {

// Rd = Rd·Wl + Rd·Wg: tsis with the local and the global profile (same
// samples: same N, seed and flux atlas) adds up to tsis with the full Rd.
TEST(Hybrid, LocalPlusGlobalIsFull) {
    const Scene scene = test::torusScene("skimmilk", 20.0);
    RenderOptions opt = test::smallOptions(40, 256, 400);
    opt.rdPart = RdPart::Full;
    const FrameResult full = test::renderWith(scene, opt, "tsis");
    opt.rdPart = RdPart::Local;
    const FrameResult local = test::renderWith(scene, opt, "tsis");
    opt.rdPart = RdPart::Global;
    const FrameResult global = test::renderWith(scene, opt, "tsis");
    double maxFull = 0, maxDiff = 0, localSum = 0, globalSum = 0;
    for (size_t i = 0; i < full.radiosity.pixels.size(); ++i) {
        const double a = full.radiosity.pixels[i];
        const double b = local.radiosity.pixels[i] + global.radiosity.pixels[i];
        maxFull = std::max(maxFull, std::abs(a));
        maxDiff = std::max(maxDiff, std::abs(a - b));
        localSum += local.radiosity.pixels[i];
        globalSum += global.radiosity.pixels[i];
    }
    std::printf("max |full − (local + global)| = %.3g (max B %.3g); local %.3g, global %.3g\n",
                maxDiff, maxFull, localSum, globalSum);
    ASSERT_GT(maxFull, 0.0);
    // Both parts matter in this scene, so the identity is not trivially met.
    EXPECT_GT(localSum, 0.05 * (localSum + globalSum));
    EXPECT_GT(globalSum, 0.05 * (localSum + globalSum));
    EXPECT_LT(maxDiff, 1e-5 * maxFull);
}

// The hybrid at N = 900 against the ground truth (--method reference) on a
// scene where the local part dominates (40 mm skin1): much closer than tsis at
// the same N.
TEST(Hybrid, CloserToGroundTruthThanTsisAtSameN) {
    const Scene scene = test::torusScene("skin1", 40.0);
    RenderOptions opt = test::smallOptions(48, 512, 900);
    opt.seed = 7;
    const std::vector<double> e = test::errorsAgainstReference(scene, opt, {"hybrid", "tsis"});
    const double hybrid = e[0], tsis = e[1];
    std::printf("40 mm skin1, N = 900: relative RMSE hybrid %.4f, tsis %.4f\n", hybrid, tsis);
    EXPECT_LT(hybrid, 0.12);
    EXPECT_LT(hybrid, 0.7 * tsis);
}

TEST(Hybrid, DeterministicAndReportsBothParts) {
    const Scene scene = test::torusScene("skin2", 10.0);
    const RenderOptions opt = test::smallOptions(32, 128, 256);
    const FrameResult a = test::renderWith(scene, opt, "hybrid");
    const FrameResult b = test::renderWith(scene, opt, "hybrid");
    EXPECT_EQ(a.radiosity.pixels, b.radiosity.pixels);
    EXPECT_EQ(a.rgb8, b.rgb8);
    const std::string stats = a.stats.toJson().dump();
    for (const char* key : {"\"global_gather\"", "\"global_sample\"", "\"local_ltsm\"",
                            "\"local_rd_evaluations\"", "\"global_rd_evaluations\"", "\"rp\""})
        EXPECT_NE(stats.find(key), std::string::npos) << key;
}

}  // namespace
}  // namespace tsis
