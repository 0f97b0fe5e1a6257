// `tsis render --method volumetric` through the binary: bad budgets as
// one-line errors, the same bytes for a seed, and the error against a
// many-path render falling as 1/√spp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "compare/image_compare.h"
#include "image/image_io.h"
#include "support/tsis_cli.h"

namespace tsis::test {
namespace {

// A small, quick scene: a 5 mm skin1 sphere lit from the front-left.
const std::string kScene =
    "render --method volumetric --mesh builtin:sphere --size-mm 5 --material skin1 "
    "--light point:-10,5,15:300,300,300 --width 20 --height 20 --atlas-res 64 --light-res 256 ";

TEST(VolumetricCli, BadBudgetsAreOneLineErrors) {
    for (const char* bad : {"--spp 0", "--spp abc", "--spp 2000000", "--time -1", "--time x"}) {
        RunResult r = runTsis(kScene + bad + " -o /dev/null");
        EXPECT_NE(r.exitCode, 0) << bad;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << bad << ": " << r.err;
        EXPECT_NE(r.err.find(std::string(bad).substr(0, 5)), std::string::npos) << r.err;
    }
}

ImageF render(const ScratchDir& dir, const std::string& name, const std::string& options) {
    RunResult r =
        runTsis(kScene + options + " -o /dev/null --aov " + dir.file(name), "TSIS_PROGRESS=0");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return readImageF(dir.file(name + "/radiance.exr"));
}

TEST(VolumetricCli, SameSeedSameImageAndErrorFallsAsInverseSqrtSpp) {
    ScratchDir dir;
    const ImageF a = render(dir, "a", "--spp 4 --seed 3");
    const ImageF b = render(dir, "b", "--spp 4 --seed 3");
    EXPECT_EQ(a.pixels, b.pixels);
    const ImageF coverage = readImageF(dir.file("a/coverage.exr"));
    // Independent seeds: e(N)² = σ²/N + σ²/N_truth; 4 and 64 paths against 512.
    const ImageF truth = render(dir, "truth", "--spp 512 --seed 100");
    auto err = [&](const ImageF& img) {
        return compareImages(img, truth, &coverage, "volumetric", "truth").metrics.relRmse;
    };
    const double e4 = err(a), e64 = err(render(dir, "c", "--spp 64 --seed 7"));
    const double expected = std::sqrt((1.0 / 4 + 1.0 / 512) / (1.0 / 64 + 1.0 / 512));  // 3.6
    EXPECT_GT(e4, 0.0);
    EXPECT_NEAR(e4 / e64, expected, 0.25 * expected) << "e4 " << e4 << " e64 " << e64;
}

}  // namespace
}  // namespace tsis::test
