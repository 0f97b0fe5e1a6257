#include "scene/environment.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/matrix.hpp>

#include "scene/scene.h"
#include "support/error_of.h"

namespace tsis {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(Environment, LatLongRoundTripsAndFollowsItsConvention) {
    EXPECT_NEAR(latLongDirection(0.5, 0.0).y, 1.0, 1e-12);   // row 0: up
    EXPECT_NEAR(latLongDirection(0.5, 0.5).z, -1.0, 1e-12);  // centre: −z
    EXPECT_NEAR(latLongDirection(0.75, 0.5).x, 1.0, 1e-12);  // a quarter right: +x
    for (double u : {0.1, 0.3, 0.6, 0.9})
        for (double v : {0.05, 0.4, 0.8}) {
            double u2, v2;
            latLongCoordinates(latLongDirection(u, v), u2, v2);
            EXPECT_NEAR(u2, u, 1e-12);
            EXPECT_NEAR(v2, v, 1e-12);
        }
}

// ∫ Y_i Y_j dω = δ_ij by a fine midpoint rule over (θ, φ): a wrong constant
// or a sign slip in shBasis breaks E = Σ T_k L_k.
TEST(Environment, HarmonicsAreOrthonormal) {
    const int nt = 200, np = 400;
    std::array<std::array<double, kEnvShCount>, kEnvShCount> g{};
    for (int i = 0; i < nt; ++i)
        for (int j = 0; j < np; ++j) {
            const double u = (j + 0.5) / np, v = (i + 0.5) / nt;
            const double dw = (2 * kPi / np) * (kPi / nt) * std::sin(kPi * v);
            const ShCoefficients y = shBasis(latLongDirection(u, v));
            for (int a = 0; a < kEnvShCount; ++a)
                for (int b = 0; b < kEnvShCount; ++b) g[a][b] += y[a] * y[b] * dw;
        }
    for (int a = 0; a < kEnvShCount; ++a)
        for (int b = 0; b < kEnvShCount; ++b)
            EXPECT_NEAR(g[a][b], a == b ? 1.0 : 0.0, 2e-3) << a << "," << b;
}

std::vector<float> uniformPixels(int w, int h, float value) {
    return std::vector<float>(static_cast<size_t>(w) * h * 3, value);
}

TEST(Environment, UniformMapHasNoSunAndProjectsToItsMean) {
    auto map = splitEnvironment("u.exr", 64, 32, 3, uniformPixels(64, 32, 0.5f));
    EXPECT_EQ(map->sunIrradiance, glm::dvec3(0.0));
    const auto c = map->project(glm::dmat3(1.0));
    // L_00 = 0.5·√(4π); every other coefficient 0.
    EXPECT_NEAR(c[0].x, 0.5 * std::sqrt(4 * kPi), 2e-3);
    for (int k = 1; k < kEnvShCount; ++k) EXPECT_NEAR(c[k].y, 0.0, 2e-3) << k;
}

// A large map is projected from its averaged copy: the same harmonics as a
// small map of the same sky (here L = 1 + y + x², bands 0–2 exactly).
TEST(Environment, LargeMapProjectsAsItsAverage) {
    auto sky = [](int w, int h) {
        std::vector<float> px(static_cast<size_t>(w) * h * 3);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const glm::dvec3 d = latLongDirection((x + 0.5) / w, (y + 0.5) / h);
                for (int c = 0; c < 3; ++c)
                    px[(static_cast<size_t>(y) * w + x) * 3 + c] =
                        static_cast<float>(1.0 + d.y + d.x * d.x);
            }
        return splitEnvironment("g.exr", w, h, 3, px);
    };
    const auto big = sky(2048, 1024), small = sky(256, 128);
    EXPECT_EQ(big->shWidth, kShMapWidth);
    const auto a = big->project(glm::dmat3(1.0)), b = small->project(glm::dmat3(1.0));
    for (int k = 0; k < kEnvShCount; ++k) EXPECT_NEAR(a[k].x, b[k].x, 2e-3) << k;
    EXPECT_NEAR(a[0].x, (1.0 + 1.0 / 3.0) * std::sqrt(4 * kPi), 5e-3);
}

// One bright texel on a dim sky: it becomes the sun, with its flux, its
// direction, turned with the map, and leaves the residual.
// Turning the coefficients (rotateSh) is projecting the turned map:
// the same numbers to rounding for a map with all 16 coefficients nonzero,
// at any angle, and the round trip is the identity.
TEST(Environment, TurnedCoefficientsAreTheTurnedMapsProjection) {
    const int w = 64, h = 32;
    std::vector<float> px(static_cast<size_t>(w) * h * 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c)
                px[(static_cast<size_t>(y) * w + x) * 3 + c] = static_cast<float>(
                    1.0 + 0.5 * std::sin(3.0 * x / w * 2 * kPi + c) * std::cos(2.0 * y / h * kPi) +
                    0.3 * (x % 7) / 7.0 + 0.2 * (y * y % 5) / 5.0 +
                    0.4 * std::sin(2 * kPi * x / w + 0.3) * y / h +
                    0.25 * std::cos(4 * kPi * x / w) * std::sin(kPi * y / h));
    Environment env;
    env.map = splitEnvironment("turn.hdr", w, h, 3, px);
    double scale = 0;
    for (const glm::dvec3& c : env.map->sh) scale = std::max(scale, glm::length(c));
    for (const glm::dvec3& c : env.map->sh) EXPECT_GT(glm::length(c), 1e-6 * scale);
    for (const double degrees : {0.0, 17.0, 90.0, -135.5, 400.0}) {
        SCOPED_TRACE(degrees);
        env.rotateDegrees = degrees;
        const auto turned = rotateSh(env.map->sh, env.toWorld());
        const auto projected = env.map->project(env.toWorld());
        for (int k = 0; k < kEnvShCount; ++k)
            EXPECT_LT(glm::length(turned[k] - projected[k]), 1e-12 * scale) << k;
        const auto back = rotateSh(turned, glm::transpose(env.toWorld()));
        for (int k = 0; k < kEnvShCount; ++k)
            EXPECT_LT(glm::length(back[k] - env.map->sh[k]), 1e-12 * scale) << k;
    }
}

TEST(Environment, SunIsSplitOffTurnedAndScaled) {
    const int w = 64, h = 32;
    std::vector<float> px = uniformPixels(w, h, 0.01f);
    const int sx = 40, sy = 10;
    for (int c = 0; c < 3; ++c) px[(sy * w + sx) * 3 + c] = 100.0f;
    Scene scene;
    scene.env.map = splitEnvironment("s.hdr", w, h, 3, px);
    const EnvironmentMap& m = *scene.env.map;
    const double theta = kPi * (sy + 0.5) / h;
    const double dw = (2 * kPi / w) * (kPi / h) * std::sin(theta);
    EXPECT_NEAR(m.sunIrradiance.x, 100.0 * dw, 1e-6);
    const glm::dvec3 d = latLongDirection((sx + 0.5) / w, (sy + 0.5) / h);
    EXPECT_NEAR(glm::dot(m.sunDirection, d), 1.0, 1e-9);
    EXPECT_EQ(m.radiance(d), glm::dvec3(0.0));
    scene.env.intensity = 2;
    scene.env.rotateDegrees = 90;
    applyEnvironment(scene);
    applyEnvironment(scene);  // replaces, never adds a second sun
    ASSERT_EQ(scene.lights.size(), 1u);
    const Light& sun = scene.lights[0];
    EXPECT_TRUE(sun.environment);
    EXPECT_NEAR(sun.rgb.x, 200.0 * dw, 1e-5);
    // +90° about +y takes x to −z: the light travels against the turned direction.
    const glm::dvec3 turned(d.z, d.y, -d.x);
    EXPECT_NEAR(glm::dot(-glm::dvec3(sun.vec), turned), 1.0, 1e-6);
    // The residual turns the same way.
    EXPECT_EQ(scene.env.radiance(turned), glm::dvec3(0.0));
    EXPECT_NEAR(scene.env.radiance(glm::dvec3(0, -1, 0)).x, 0.02, 1e-7);
}

TEST(Environment, BadMapsAreOneLineErrors) {
    using test::errorOf;
    EXPECT_NE(errorOf([] {
                  splitEnvironment("a.exr", 30, 30, 3, uniformPixels(30, 30, 1));
              }).find("not a lat-long map"),
              std::string::npos);
    std::vector<float> px = uniformPixels(8, 4, 1);
    px[7] = std::nanf("");
    EXPECT_NE(errorOf([&] { splitEnvironment("a.exr", 8, 4, 3, px); }).find("NaN"),
              std::string::npos);
    px[7] = -1;
    EXPECT_NE(errorOf([&] { splitEnvironment("a.exr", 8, 4, 3, px); }).find("negative"),
              std::string::npos);
    EXPECT_NE(errorOf([] { loadEnvironment("/nonexistent/sky.exr"); }).find("no such file"),
              std::string::npos);
}

// Resampling's tiny negatives (Blender's worlds: thousands, down to −3·10⁻⁶)
// are clamped to 0 with one note giving their count and the lowest, over
// maps of several sizes, channel counts and peaks; one just past the
// tolerance, NaN and ±infinity stay errors naming the pixel.
TEST(Environment, TinyNegativesAreClampedWithOneNote) {
    using test::errorOf;
    for (const int channels : {1, 3, 4})
        for (const float peak : {1e-4f, 1.0f, 5e3f})
            for (const int w : {8, 64}) {
                const int h = w / 2;
                std::vector<float> px(static_cast<size_t>(w) * h * channels, 0.25f * peak);
                px[channels] = peak;  // pixel (1, 0)
                // Pixels (0, 2) and (w − 1, h − 1), channel 0.
                const size_t a = static_cast<size_t>(w) * 2 * channels,
                             b = (static_cast<size_t>(w) * h - 1) * channels;
                px[a] = -1e-6f * peak;
                px[b] = -0.9f * kEnvNegativeTolerance * peak;
                testing::internal::CaptureStderr();
                auto map = splitEnvironment("t.exr", w, h, channels, px);
                const std::string err = testing::internal::GetCapturedStderr();
                const std::string scope = std::to_string(channels) + " ch, peak " +
                                          std::to_string(peak) + ", " + std::to_string(w);
                EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << scope << ": " << err;
                char lowest[32];
                std::snprintf(lowest, sizeof lowest, "%.3g",
                              static_cast<double>(-0.9f * kEnvNegativeTolerance * peak));
                EXPECT_NE(
                    err.find(
                        "tsis: note: --env 't.exr': 2 pixels with negative values clamped to 0 "
                        "(the lowest " +
                        std::string(lowest) + ";"),
                    std::string::npos)
                    << scope << ": " << err;
                for (const float v : map->residual) EXPECT_GE(v, 0.0f) << scope;
                // Past the tolerance: an error naming the pixel, and no note.
                px[b] = -1.1f * kEnvNegativeTolerance * peak;
                testing::internal::CaptureStderr();
                const std::string e =
                    errorOf([&] { splitEnvironment("t.exr", w, h, channels, px); });
                EXPECT_EQ(testing::internal::GetCapturedStderr(), "") << scope;
                EXPECT_NE(e.find(") has a negative value"), std::string::npos) << scope << e;
                EXPECT_NE(
                    e.find("pixel (" + std::to_string(w - 1) + ", " + std::to_string(h - 1) + ")"),
                    std::string::npos)
                    << scope << e;
                for (const float bad : {std::nanf(""), INFINITY, -INFINITY}) {
                    px[b] = bad;
                    const std::string f =
                        errorOf([&] { splitEnvironment("t.exr", w, h, channels, px); });
                    EXPECT_NE(f.find("pixel (" + std::to_string(w - 1) + ", " +
                                     std::to_string(h - 1) + ") has a NaN or infinite value"),
                              std::string::npos)
                        << scope << f;
                }
            }
    // No negative: no note.
    testing::internal::CaptureStderr();
    splitEnvironment("u.exr", 8, 4, 3, uniformPixels(8, 4, 1));
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

}  // namespace
}  // namespace tsis
