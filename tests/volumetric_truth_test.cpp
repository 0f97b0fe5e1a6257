// `tsis render --method volumetric` against the stored truth of
// tests/validation/ (issue 24 item 2): the two spheres' radiance by the light
// tracer, `build/bench/bench_physical --truth`, the camera walk's independent
// twin (it connects in the opposite direction, from the medium to the eye).
// The mean over the interior pixels must agree within 3σ per channel, the
// per-pixel difference must be what the two images' noise explains.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "compare/image_compare.h"
#include "image/image_io.h"
#include "support/tsis_cli.h"

namespace tsis::test {
namespace {

const std::string kValidation = std::string(TSIS_SOURCE_DIR) + "/tests/validation/";

class VolumetricTruth : public testing::TestWithParam<const char*> {};

TEST_P(VolumetricTruth, MeanAndPixelsAgreeWithTheLightTracer) {
    const std::string name = GetParam();
    const nlohmann::json truth =
        nlohmann::json::parse(readFile(kValidation + "truth.json")).at(name);
    std::string args;
    for (const auto& a : truth.at("args")) args += " " + a.get<std::string>();
    // Two seeds: the camera walk's own per-pixel noise from their difference.
    ScratchDir dir;
    ImageF img[2];
    for (int s = 0; s < 2; ++s) {
        const std::string aov = dir.file("s" + std::to_string(s));
        // The subsurface term at the pixels' centres: the truth's (no surface
        // reflection, one sample a pixel).
        const RunResult r =
            runTsis("render --no-specular --aa 1 --method volumetric --spp 8 --seed " +
                        std::to_string(s + 1) + args + " -o /dev/null --aov " + aov,
                    "TSIS_PROGRESS=0");
        ASSERT_EQ(r.exitCode, 0) << r.err;
        img[s] = readImageF(aov + "/radiance.exr");
    }
    const std::vector<char> mask = interiorPixels(readImageF(dir.file("s0/coverage.exr")));
    const ImageF ref = readImageF(kValidation + "truth_" + name.substr(6) + ".exr");
    const ImageF refErr = readImageF(kValidation + "truth_" + name.substr(6) + "_stderr.exr");
    for (int c = 0; c < 3; ++c) {
        double sum = 0, noise = 0, sq = 0, expectedSq = 0, refSum = 0;
        int n = 0;
        for (int y = 0; y < ref.height; ++y)
            for (int x = 0; x < ref.width; ++x) {
                if (!mask[static_cast<size_t>(y) * ref.width + x]) continue;
                const double a = img[0].at(x, y, c), b = img[1].at(x, y, c);
                const double mean = 0.5 * (a + b), t = ref.at(x, y, c), te = refErr.at(x, y, c);
                const double var = 0.25 * (a - b) * (a - b);  // of the two seeds' mean
                sum += mean;
                noise += var;
                refSum += t;
                sq += (mean - t) * (mean - t);
                expectedSq += var + te * te;
                ++n;
            }
        ASSERT_GT(n, 300);
        const double mean = sum / n, meanErr = std::sqrt(noise) / n;
        const double truthMean = truth.at("interior_mean")[c].get<double>();
        const double truthErr = truth.at("interior_mean_error")[c].get<double>();
        EXPECT_NEAR(refSum / n, truthMean, 1e-4 * truthMean) << "the mask is the truth's";
        EXPECT_NEAR(mean, truthMean, 3 * std::hypot(meanErr, truthErr))
            << name << " channel " << c << ": volumetric " << mean << " ± " << meanErr << ", truth "
            << truthMean << " ± " << truthErr;
        // Per pixel: the RMSE is the noise of both images (within 25%).
        EXPECT_LT(std::sqrt(sq / n), 1.25 * std::sqrt(expectedSq / n)) << name << " channel " << c;
    }
}

INSTANTIATE_TEST_SUITE_P(Spheres, VolumetricTruth,
                         testing::Values("truth_marble_sphere_10mm", "truth_skin1_sphere_30mm"));

}  // namespace
}  // namespace tsis::test
