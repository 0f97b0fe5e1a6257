// The prefiltered environment reflection (render/env_reflection.h) on maps
// with known answers, and its albedo table against physics/ggx.h.
#include "render/env_reflection.h"

#include <gtest/gtest.h>

#include "physics/ggx.h"

namespace tsis {
namespace {

std::shared_ptr<const EnvironmentMap> mapOf(int w, int h, float (*radiance)(int x, int y, int h)) {
    std::vector<float> px(static_cast<size_t>(w) * h * 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c)
                px[(static_cast<size_t>(y) * w + x) * 3 + c] = radiance(x, y, h);
    return splitEnvironment("test", w, h, 3, px);
}

// A uniform map prefilters to itself, at every roughness.
TEST(EnvReflection, UniformMapPrefiltersToItself) {
    const auto map = mapOf(64, 32, [](int, int, int) { return 0.25f; });
    for (double r : {0.05, 0.3, 1.0}) {
        const std::vector<float> p = prefilterReflection(*map, r, 32);
        for (size_t i = 0; i < p.size(); i += 4) ASSERT_NEAR(p[i], 0.25f, 1e-5f) << r;
    }
}

// Sky above, black below: a smooth lobe straight up or down sees only one of
// them; one at the horizon sees half of each (the map is symmetric about it);
// a rougher lobe reaches further across.
TEST(EnvReflection, HalfLitMapIsSeenByTheLobeAboutTheMirrorDirection) {
    const auto map = mapOf(128, 64, [](int, int y, int h) { return y < h / 2 ? 1.0f : 0.0f; });
    const int w = 32, h = 16;
    auto at = [&](const std::vector<float>& p, int y) {
        return p[(static_cast<size_t>(y) * w) * 4];
    };
    const std::vector<float> smooth = prefilterReflection(*map, 0.2, w);
    const std::vector<float> rough = prefilterReflection(*map, 0.8, w);
    EXPECT_GT(at(smooth, 0), 0.999f);
    EXPECT_LT(at(smooth, h - 1), 1e-3f);
    EXPECT_NEAR(at(smooth, h / 2) + at(smooth, h / 2 - 1), 1.0f, 1e-3f);
    EXPECT_LT(at(rough, 2), at(smooth, 2));
    EXPECT_GT(at(rough, h - 3), at(smooth, h - 3));
}

// The table holds ggxDirectionalAlbedo at √cos θo = k/(n − 1), per medium's
// η and roughness.
TEST(EnvReflection, AlbedoTableHoldsTheDirectionalAlbedoPerMedium) {
    const std::vector<float> etas = {1.3f, 1.5f}, roughness = {0.4f, 0.8f};
    const std::vector<float> t = reflectionAlbedoTable(etas, roughness);
    const int n = kReflectionAlbedoEntries;
    ASSERT_EQ(t.size(), etas.size() * n * 4);
    for (size_t m = 0; m < etas.size(); ++m)
        for (int k : {1, n / 3, n - 1}) {
            const double s = static_cast<double>(k) / (n - 1);
            EXPECT_NEAR(t[(m * n + k) * 4], ggxDirectionalAlbedo(etas[m], roughness[m], s * s),
                        1e-6);
        }
    EXPECT_GT(t[(n + n - 1) * 4], t[(n - 1) * 4]);  // η 1.5 reflects more than 1.3
}

}  // namespace
}  // namespace tsis
