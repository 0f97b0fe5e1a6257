#include "render/env_reflection.h"

#include <algorithm>
#include <cmath>

#include "physics/ggx.h"
#include "util/error.h"
#include "util/parallel.h"

namespace tsis {

namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

double ladderRoughness(int k) {
    const double x = static_cast<double>(k) / (kRoughnessLadderSteps - 1);
    return kMinRoughness + (1.0 - kMinRoughness) * x * x;
}

std::vector<float> prefilterReflection(const EnvironmentMap& map, double roughness, int width) {
    const int height = width / 2;
    // The source: the residual averaged down to at most 256 × 128 (its
    // 1.4° texels are finer than the grid we write).
    const int sw = map.shWidth, sh = map.shHeight;
    std::vector<glm::dvec3> dir(static_cast<size_t>(sw) * sh);
    std::vector<double> solidAngle(dir.size());
    for (int y = 0; y < sh; ++y)
        for (int x = 0; x < sw; ++x) {
            const size_t i = static_cast<size_t>(y) * sw + x;
            dir[i] = latLongDirection((x + 0.5) / sw, (y + 0.5) / sh);
            solidAngle[i] = (2.0 * kPi / sw) * (kPi / sh) * std::sin(kPi * (y + 0.5) / sh);
        }
    const double alpha = ggxAlpha(roughness);
    std::vector<float> out(static_cast<size_t>(width) * height * 4, 0.0f);
    parallelFor(static_cast<size_t>(width) * height, 64, [&](size_t begin, size_t end) {
        for (size_t o = begin; o < end; ++o) {
            const int x = static_cast<int>(o % width), y = static_cast<int>(o / width);
            const glm::dvec3 r = latLongDirection((x + 0.5) / width, (y + 0.5) / height);
            glm::dvec3 sum(0.0);
            double weight = 0;
            for (size_t i = 0; i < dir.size(); ++i) {
                const double cosL = glm::dot(r, dir[i]);
                if (cosL <= 0) continue;
                // r·h with h = (l + r)/|l + r|: √((1 + r·l)/2).
                const double w = ggxD(alpha, std::sqrt(0.5 * (1.0 + cosL))) * cosL * solidAngle[i];
                const float* p = &map.shResidual[i * 3];
                sum += w * glm::dvec3(p[0], p[1], p[2]);
                weight += w;
            }
            // A lobe narrower than the source's texels may weigh none of them.
            const glm::dvec3 l = weight > 0 ? sum / weight : map.radiance(r);
            for (int c = 0; c < 3; ++c)
                out[o * 4 + static_cast<size_t>(c)] = static_cast<float>(l[c]);
            out[o * 4 + 3] = 1.0f;
        }
    });
    return out;
}

std::vector<float> reflectionAlbedoTable(const std::vector<float>& etaOfMedium,
                                         const std::vector<float>& roughnessOfMedium) {
    TSIS_CHECK_EQ(etaOfMedium.size(), roughnessOfMedium.size());
    const int n = kReflectionAlbedoEntries;
    std::vector<float> out(etaOfMedium.size() * n * 4);
    parallelFor(etaOfMedium.size() * n, 8, [&](size_t begin, size_t end) {
        for (size_t k = begin; k < end; ++k) {
            const double s = static_cast<double>(k % n) / (n - 1);
            const float a = static_cast<float>(ggxDirectionalAlbedo(
                etaOfMedium[k / n], roughnessOfMedium[k / n], std::max(s * s, 1e-4)));
            std::fill_n(&out[k * 4], 4, a);
        }
    });
    return out;
}

}  // namespace tsis
