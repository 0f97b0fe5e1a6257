#include "render/raster_passes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <utility>

#include "physics/ggx.h"
#include "scene/environment.h"
#include "support/render.h"

namespace tsis {
namespace {

// A marble sphere under a directional light from the camera's side.
Scene frontLitSphere(glm::vec3 travel) {
    return test::sphereScene("marble",
                             {Light::Type::Directional, glm::normalize(travel), glm::vec3(1.0f)});
}

// The frame with the GGX lobe and without it (--no-specular), else alike.
std::pair<FrameResult, FrameResult> withAndWithoutLobe(const Scene& scene, RenderOptions opt) {
    opt.specular = true;
    FrameResult with = test::renderWith(scene, opt, "pyramid");
    opt.specular = false;
    return {std::move(with), test::renderWith(scene, opt, "pyramid")};
}

// The shader's GGX lobe (gl/shaders/common.glsl) on rendered pixels against
// the double-precision one (physics/ggx.h): the frame with the lobe minus the
// frame without it is f·E·cosθi at each pixel's position and normal (the
// radiosity, a display-only change apart, is the same). Unshadowed: V = 1.
TEST(Composite, GlslLobeMatchesTheHostLobeOnRenderedPixels) {
    Scene scene = frontLitSphere({0.3f, -0.4f, -1.0f});
    scene.lights[0].shadows = false;
    RenderOptions opt = test::smallOptions(128, 256);
    opt.aa = 1;
    for (float roughness : {0.2f, 0.3f, 0.6f, 1.0f}) {
        SCOPED_TRACE(roughness);
        opt.roughness = roughness;
        // Named references, not a structured binding: the pixel lambdas capture them.
        const std::pair<FrameResult, FrameResult> frames = withAndWithoutLobe(scene, opt);
        const FrameResult &with = frames.first, &without = frames.second;
        ASSERT_EQ(with.radiosity.pixels, without.radiosity.pixels);
        const glm::dvec3 l = -glm::dvec3(scene.lights[0].vec);
        const glm::dvec3 eye(scene.camera.eye);
        double maxExpected = 0, worst = 0;
        int checked = 0;
        for (int pass = 0; pass < 2; ++pass)
            test::forEachSurfacePixel(
                with, [&](int x, int y, const glm::dvec3& p, const glm::dvec3& n) {
                    const glm::dvec3 v = glm::normalize(eye - p);
                    const double cosI = glm::dot(n, l);
                    if (cosI <= 0 || glm::dot(n, v) <= 0) return;
                    // The surface's frame: n = +z.
                    const glm::dvec3 t = glm::normalize(glm::cross(
                        n, std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
                    const glm::dvec3 b = glm::cross(n, t);
                    auto local = [&](glm::dvec3 w) {
                        return glm::dvec3(glm::dot(w, t), glm::dot(w, b), glm::dot(w, n));
                    };
                    const double expected =
                        ggxBrdf(scene.material.eta, roughness, local(l), local(v)) * cosI;
                    if (pass == 0) {
                        maxExpected = std::max(maxExpected, expected);
                        return;
                    }
                    if (expected < 0.02 * maxExpected) return;
                    for (int c = 0; c < 3; ++c) {
                        const double got = with.radiance.at(x, y, c) - without.radiance.at(x, y, c);
                        worst = std::max(worst, std::abs(got - expected) / expected);
                    }
                    ++checked;
                });
        EXPECT_GT(checked, 30);
        EXPECT_LT(worst, 1e-3) << checked << " pixels";  // measured 1.6e-4 at most
    }
}

// The environment's reflection (render/env_reflection.h) on rendered pixels:
// under a uniform sky of radiance L and no light, the frame with the lobe
// minus the frame without it is L · ggxDirectionalAlbedo(η, R, cos θo) at each
// pixel's position and normal (radiance, before exposure), at two roughnesses.
TEST(Composite, UniformEnvironmentReflectsTheLobesDirectionalAlbedo) {
    Scene scene = frontLitSphere({0.0f, 0.0f, -1.0f});
    scene.lights[0].rgb = glm::vec3(0.0f);  // a frame needs a light: a dark one
    const float radiance = 0.2f;
    scene.env.map = splitEnvironment("white", 32, 16, 3, std::vector<float>(32 * 16 * 3, radiance));
    scene.env.intensity = 1.5;
    scene.env.rotateDegrees = 40;  // turning a uniform sky changes nothing
    RenderOptions opt = test::smallOptions(64, 128);
    opt.aa = 1;
    const double l = radiance * scene.env.intensity;
    for (float roughness : {0.3f, 0.7f}) {
        SCOPED_TRACE(roughness);
        opt.roughness = roughness;
        // Named references, not a structured binding: the pixel lambdas capture them.
        const std::pair<FrameResult, FrameResult> frames = withAndWithoutLobe(scene, opt);
        const FrameResult &with = frames.first, &without = frames.second;
        const glm::dvec3 eye(scene.camera.eye);
        double worst = 0, minCos = 1;
        int checked = 0;
        test::forEachSurfacePixel(with, [&](int x, int y, const glm::dvec3& p,
                                            const glm::dvec3& n) {
            const double cosO = std::abs(glm::dot(n, glm::normalize(eye - p)));
            const double expected = l * ggxDirectionalAlbedo(scene.material.eta, roughness, cosO);
            for (int c = 0; c < 3; ++c) {
                const double got = with.radiance.at(x, y, c) - without.radiance.at(x, y, c);
                worst = std::max(worst, std::abs(got - expected) / expected);
            }
            minCos = std::min(minCos, cosO);
            ++checked;
        });
        EXPECT_GT(checked, 500);
        EXPECT_LT(minCos, 0.2);  // the rim, where the albedo turns fastest, is among them
        // Measured 1.4e-3 at R 0.3, 2.7e-4 at R 0.7 (788 pixels, cos θo ≥ 0.13).
        EXPECT_LT(worst, 0.01) << checked << " pixels";
    }
}

// The fixed exposure shows the light's strength (× 1000: brighter); the
// auto exposure takes it back out (each frame's own log-average).
TEST(Composite, FixedExposureShowsTheLightsStrength) {
    Scene dim = frontLitSphere({0.3f, -0.4f, -1.0f}), bright = dim;
    dim.lights[0].rgb = glm::vec3(0.01f);
    bright.lights[0].rgb = glm::vec3(10.0f);
    RenderOptions opt = test::smallOptions(48, 256);
    auto mean = [](const FrameResult& f) {
        double s = 0;
        for (uint8_t v : f.rgb8) s += v;
        return s / static_cast<double>(f.rgb8.size());
    };
    const double fixedDim = mean(test::renderWith(dim, opt, "pyramid"));
    const double fixedBright = mean(test::renderWith(bright, opt, "pyramid"));
    EXPECT_GT(fixedBright, fixedDim + 30);
    opt.autoExposure = true;
    const double autoDim = mean(test::renderWith(dim, opt, "pyramid"));
    const double autoBright = mean(test::renderWith(bright, opt, "pyramid"));
    EXPECT_NEAR(autoBright, autoDim, 0.5);
}

// The log-average summed on the GPU side (resolve.frag, reduce.frag) equals
// the host's over the frame's radiance, with the fixed exposure (where it is
// only reported) and the auto one (where it sets the exposure). At 1× a
// pixel's radiance has alpha > 0 exactly where it is covered.
TEST(Composite, GpuLogAverageEqualsTheHostOne) {
    const Scene scene = frontLitSphere({0.3f, -0.4f, -1.0f});
    RenderOptions opt = test::smallOptions(48, 256);
    opt.aa = 1;
    for (bool autoExposure : {false, true}) {
        SCOPED_TRACE(autoExposure);
        opt.autoExposure = autoExposure;
        const FrameResult f = test::renderWith(scene, opt, "pyramid");
        std::vector<float> rgba;
        for (size_t i = 0; i < f.coverage.pixels.size(); ++i)
            rgba.insert(rgba.end(), {f.radiance.pixels[3 * i], f.radiance.pixels[3 * i + 1],
                                     f.radiance.pixels[3 * i + 2], f.coverage.pixels[i]});
        const float host = logAverageLuminance(rgba);
        EXPECT_NEAR(f.lavg, host, 1e-3 * host);
    }
}

TEST(Composite, ExposureScale) {
    RenderOptions o;
    o.exposure = 2.5f;
    EXPECT_FLOAT_EQ(exposureScale(o, 0.01f), std::exp2(2.5f));
    EXPECT_FLOAT_EQ(exposureScale(o, 100.0f), std::exp2(2.5f));
    o.autoExposure = true;
    o.key = 0.18f;
    EXPECT_FLOAT_EQ(exposureScale(o, 0.02f), 9.0f);
}

// --aa: the silhouette pixels come closer to the 4×4-sample image than the
// one-sample ones do (the staircase goes), at no cost to the interior.
TEST(Composite, SupersampledSilhouettesApproachTheFinelySampledImage) {
    const Scene scene = frontLitSphere({0.3f, -0.4f, -1.0f});
    RenderOptions opt = test::smallOptions(64, 256);
    FrameResult f[3];
    const int aa[3] = {1, 2, 4};
    for (int i = 0; i < 3; ++i) {
        opt.aa = aa[i];
        f[i] = test::renderWith(scene, opt, "pyramid");
    }
    // Silhouette pixels: a covered pixel next to an uncovered one, or the reverse.
    const ImageF& cov = f[0].coverage;
    double err[2] = {0, 0}, interior[2] = {0, 0};
    int edges = 0;
    for (int y = 1; y + 1 < cov.height; ++y)
        for (int x = 1; x + 1 < cov.width; ++x) {
            const float c = cov.at(x, y, 0);
            const bool edge = cov.at(x - 1, y, 0) != c || cov.at(x + 1, y, 0) != c ||
                              cov.at(x, y - 1, 0) != c || cov.at(x, y + 1, 0) != c;
            edges += edge;
            for (int i = 0; i < 2; ++i)
                for (int ch = 0; ch < 3; ++ch) {
                    const size_t k = (static_cast<size_t>(y) * cov.width + x) * 3 + ch;
                    const double d = double(f[i].rgb8[k]) - double(f[2].rgb8[k]);
                    (edge ? err : interior)[i] += d * d;
                }
        }
    ASSERT_GT(edges, 50);
    EXPECT_LT(err[1], 0.3 * err[0]) << "silhouette squared error, 2×2 against 1×1 samples";
    // The interior: the same surface, at most a level or two of difference.
    EXPECT_LT(interior[1], interior[0] + 1e-9 + 4.0 * cov.width * cov.height);
}

// --aa-method fxaa: the silhouette pixels come closer to the 4×4-sample
// image than the one-sample ones do, over light directions, and the rest
// stays the one-sample image: of the pixels whose 5×5 neighbourhood is all
// covered or all uncovered, only the few the composite marks as another
// surface's neighbour (as it does for --aa's samples) may move, by a few
// levels.
TEST(Composite, FxaaSmoothsTheSilhouettesAlone) {
    for (const glm::vec3 light : {glm::vec3(0.3f, -0.4f, -1.0f), glm::vec3(-0.8f, 0.2f, -0.5f)}) {
        SCOPED_TRACE(light.x);
        const Scene scene = frontLitSphere(light);
        RenderOptions opt = test::smallOptions(64, 256);
        opt.aa = 1;
        const FrameResult one = test::renderWith(scene, opt, "pyramid");
        opt.aa = 4;
        const FrameResult fine = test::renderWith(scene, opt, "pyramid");
        opt.aaMethod = AaMethod::Fxaa;  // --aa not read
        const FrameResult fxaa = test::renderWith(scene, opt, "pyramid");
        const ImageF& cov = one.coverage;
        auto covered = [&](int x, int y) {
            return cov.at(std::clamp(x, 0, cov.width - 1), std::clamp(y, 0, cov.height - 1), 0);
        };
        double err[2] = {0, 0};
        int edges = 0, uniformValues = 0, moved = 0;
        for (int y = 0; y < cov.height; ++y)
            for (int x = 0; x < cov.width; ++x) {
                bool uniform = true, edge = false;
                for (int dy = -2; dy <= 2; ++dy)
                    for (int dx = -2; dx <= 2; ++dx) {
                        uniform = uniform && covered(x + dx, y + dy) == covered(x, y);
                        if (std::abs(dx) + std::abs(dy) == 1)
                            edge = edge || covered(x + dx, y + dy) != covered(x, y);
                    }
                edges += edge;
                for (int ch = 0; ch < 3; ++ch) {
                    const size_t k = (static_cast<size_t>(y) * cov.width + x) * 3 + ch;
                    if (uniform) {
                        const int d = int(fxaa.rgb8[k]) - int(one.rgb8[k]);
                        EXPECT_LE(std::abs(d), 8) << x << " " << y;
                        ++uniformValues;
                        moved += d != 0;
                    }
                    if (!edge) continue;
                    for (int i = 0; i < 2; ++i) {
                        const double d = double((i ? fxaa : one).rgb8[k]) - double(fine.rgb8[k]);
                        err[i] += d * d;
                    }
                }
            }
        ASSERT_GT(edges, 50);
        ASSERT_GT(uniformValues, 3 * 64 * 64 / 2);
        EXPECT_LT(moved, uniformValues / 100);
        EXPECT_LT(err[1], 0.6 * err[0]) << "silhouette squared error, FXAA against 1×1 samples";
    }
}

// The composite's targets that are not cleared (the samples' G-buffer, the
// centres' radiance, the tone map's) hold an earlier frame's pixels where the
// object no longer is: a frame drawn after another view, another size of
// object and with the light elsewhere is the same, byte for byte, as that
// frame drawn by a fresh renderer; so is that view drawn again at --aa 1
// (the same coverage, no pixel supersampled: the tone map keeps its
// background while the coverage and the supersampled pixels stay).
TEST(Composite, UnclearedTargetsLeaveNoEarlierFrameBehind) {
    Scene torus = test::torusScene("marble", 10.0);
    Scene before = torus;
    before.camera.eye = glm::vec3(-4, 9, 9);
    normalizeMesh(before.mesh, 14.0);
    before.lights[0].vec = glm::vec3(10, -5, 8);
    RenderOptions opt = test::smallOptions(96, 256);
    opt.method = "pyramid";
    for (int aa : {2, 3}) {
        SCOPED_TRACE(aa);
        opt.aa = aa;
        for (bool autoExposure : {false, true}) {
            opt.autoExposure = autoExposure;
            Renderer fresh, reused;
            reused.render(before, opt);
            const FrameResult a = fresh.render(torus, opt), b = reused.render(torus, opt);
            EXPECT_EQ(a.rgb8, b.rgb8);
            EXPECT_EQ(a.lavg, b.lavg);
            // Then at --aa 1, where no pixel is supersampled.
            RenderOptions one = opt;
            one.aa = 1;
            const FrameResult c = Renderer().render(torus, one), d = reused.render(torus, one);
            EXPECT_EQ(c.rgb8, d.rgb8);
            EXPECT_EQ(c.lavg, d.lavg);
        }
    }
}

// --aa-method fxaa reads the centres' marks, made when the G-buffer changes
// and kept while only the lights do: a renderer that drew another view, then
// this view, then this view under a moved light draws that last frame as a
// fresh renderer does, byte for byte (with the display straight from the
// centres and through the tone map's pass).
TEST(Composite, FxaaKeepsTheMarksWhileOnlyTheLightMoves) {
    Scene scene = test::torusScene("marble", 10.0);
    Scene other = scene;
    other.camera.eye = glm::vec3(-4, 9, 9);
    RenderOptions opt = test::smallOptions(96, 256);
    opt.method = "pyramid";
    opt.aaMethod = AaMethod::Fxaa;
    for (bool autoExposure : {false, true}) {
        SCOPED_TRACE(autoExposure);
        opt.autoExposure = autoExposure;
        Renderer reused;
        reused.render(other, opt);
        reused.render(scene, opt);
        Scene moved = scene;
        moved.lights[0].vec = glm::vec3(10, -5, 8);
        const FrameResult a = Renderer().render(moved, opt), b = reused.render(moved, opt);
        EXPECT_EQ(b.stats.number("lighting_reused"), 0.0);  // the light views drawn again
        EXPECT_EQ(a.rgb8, b.rgb8);
    }
}

}  // namespace
}  // namespace tsis
