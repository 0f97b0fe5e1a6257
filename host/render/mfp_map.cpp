#include "render/mfp_map.h"

#include <algorithm>
#include <cmath>

#include "render/albedo_atlas.h"
#include "render/albedo_inversion.h"
#include "util/error.h"

namespace tsis {

namespace {

double scaleOf(const glm::dvec3& texel) {
    return (texel.x + texel.y + texel.z) / 3.0;
}

}  // namespace

std::vector<MfpStep> mfpSteps(const ImageF& map, const std::string& mapName,
                              const Material& medium) {
    double lo = HUGE_VAL, hi = 0;
    for (int y = 0; y < map.height; ++y)
        for (int x = 0; x < map.width; ++x) {
            glm::dvec3 t(0.0);
            for (int c = 0; c < 3; ++c) t[c] = map.at(x, y, std::min(c, map.channels - 1));
            const double s = scaleOf(t);
            if (!(std::isfinite(s) && s > 0))
                fail("mean free path map '", mapName, "': texel (", x, ", ", y, ") scales by ", s,
                     "; it must be finite and > 0");
            lo = std::min(lo, s), hi = std::max(hi, s);
        }
    TSIS_CHECK(hi > 0);
    const int count =
        hi > lo
            ? std::min(kMaxMfpSteps, 1 + static_cast<int>(std::ceil(
                                             std::log(hi / lo) / std::log(kMfpStepRatio) - 1e-9)))
            : 1;
    std::vector<MfpStep> steps;
    for (int k = 0; k < count; ++k) {
        const double s = count == 1 ? lo : lo * std::pow(hi / lo, double(k) / (count - 1));
        MfpStep step{s, medium};
        step.medium.sigmaSPrime /= s;
        step.medium.sigmaA /= s;
        if (const std::string p = meanFreePathProblem(meanFreePathOf(step.medium)); !p.empty())
            fail("mean free path map '", mapName, "': its scale ", s, " on material '", medium.name,
                 "': ", p);
        steps.push_back(step);
    }
    return steps;
}

size_t mfpStepAt(const ObjectMaterial& o, const glm::vec2& tc) {
    const std::vector<MfpStep>& steps = o.mfpSteps;
    if (steps.size() < 2 || !o.mfpMap) return 0;
    const double s = scaleOf(sampleTexture(o.mfpMap->image, tc));
    const double x = (steps.size() - 1) * std::log(s / steps.front().scale) /
                     std::log(steps.back().scale / steps.front().scale);
    return static_cast<size_t>(std::clamp(std::lround(x), 0L, long(steps.size() - 1)));
}

}  // namespace tsis
