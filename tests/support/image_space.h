// Shared by the tsm and lss tests: a small lit scene, its ground truth, and
// the checks every image-space baseline must pass against it.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "support/render.h"

namespace tsis::test {

// A 10 mm sphere lit by a point light from the camera's side (so lss, which
// sees only what the camera sees, is judged where it can work).
inline Scene litSphereScene(const char* material) {
    return sphereScene(material, {Light::Type::Point, glm::vec3(5, 10, 25), glm::vec3(700.0f)});
}

// The reference method when it is registered, else tsis with N = 65536.
inline FrameResult groundTruth(const Scene& scene, RenderOptions opt) {
    const std::vector<std::string> names = methodNames();
    if (std::find(names.begin(), names.end(), "reference") != names.end())
        return renderWith(scene, opt, "reference");
    opt.samples = 1 << 16;
    return renderWith(scene, opt, "tsis");
}

// Finite, non-negative radiosity, and closer to the ground truth than a black
// image (whose relative RMSE is ≥ 1) by a margin.
inline void expectSaneAgainstTruth(const FrameResult& f, const FrameResult& truth,
                                   double maxRelativeRmse, const char* what) {
    size_t covered = 0;
    for (int y = 0; y < f.height; ++y)
        for (int x = 0; x < f.width; ++x) {
            if (f.coverage.at(x, y, 0) <= 0) continue;
            ++covered;
            for (int c = 0; c < 3; ++c) {
                const float v = f.radiosity.at(x, y, c);
                ASSERT_TRUE(std::isfinite(v) && v >= 0.0f)
                    << what << ": pixel (" << x << ", " << y << ") channel " << c << " = " << v;
            }
        }
    ASSERT_GT(covered, 0u) << what;
    const double err = relativeRmse(f, truth);
    std::printf("%s: relative RMSE against the ground truth %.4f\n", what, err);
    EXPECT_LT(err, maxRelativeRmse) << what;
}

// `method` on the skin1 lit sphere (64², maps 512², N = samples) against the
// ground truth.
inline void expectSaneOnLitSphere(const std::string& method, double maxRelativeRmse,
                                  const char* what, int samples = RenderOptions{}.samples) {
    const Scene scene = litSphereScene("skin1");
    RenderOptions opt = smallOptions(64, 512);
    const FrameResult truth = groundTruth(scene, opt);
    opt.samples = samples;
    expectSaneAgainstTruth(renderWith(scene, opt, method), truth, maxRelativeRmse, what);
}

inline bool sameRadiosity(const FrameResult& a, const FrameResult& b) {
    return a.radiosity.pixels == b.radiosity.pixels;
}

}  // namespace tsis::test
