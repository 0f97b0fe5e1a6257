#include "render/truth_check.h"

#include <algorithm>
#include <cmath>

#include "util/error.h"

namespace tsis {

TruthCheck pooledError(const ImageF& model, const ImageF& a, const ImageF& b,
                       const ImageF& coverage) {
    TSIS_CHECK(model.width == a.width && model.height == a.height && a.width == b.width &&
               a.height == b.height && coverage.width == a.width);
    double num = 0, den = 0, noise = 0;
    TruthCheck t;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            if (coverage.at(x, y, 0) <= 0.5f) continue;
            ++t.pixels;
            for (int c = 0; c < 3; ++c) {
                const double truth = 0.5 * (a.at(x, y, c) + b.at(x, y, c));
                const double d = model.at(x, y, c) - truth,
                             e = 0.5 * (a.at(x, y, c) - b.at(x, y, c));
                num += d * d;
                den += truth * truth;
                noise += e * e;
            }
        }
    if (!(den > 0)) return t;
    t.relRmse = std::sqrt(num / den);
    t.noise = std::sqrt(noise / den);
    t.subtracted = std::sqrt(std::max(0.0, t.relRmse * t.relRmse - t.noise * t.noise));
    return t;
}

TruthCheck truthCheck(Renderer& renderer, const Scene& scene, RenderOptions options,
                      double seconds) {
    if (options.method == "volumetric") fail("--truth-check: the method is volumetric already");
    options.keepAovs = true;
    options.specular = false;  // the truth has no surface reflection
    options.aa = 1;
    options.progressive = false;
    const FrameResult model = renderer.render(scene, options);
    RenderOptions vol = options;
    vol.method = "volumetric";
    vol.spp = 0;
    vol.timeSeconds = std::max(seconds / 2, 1e-3);
    FrameResult half[2];
    for (int s = 0; s < 2; ++s) {
        vol.seed = options.seed * 2 + static_cast<uint32_t>(s) + 1;
        half[s] = renderer.render(scene, vol);
    }
    TruthCheck t = pooledError(model.radiance, half[0].radiance, half[1].radiance, model.coverage);
    t.seconds = seconds;
    return t;
}

}  // namespace tsis
