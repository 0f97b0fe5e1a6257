// The whole frame against physics: the plane's closed form, the estimator's
// convergence rate.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "mesh/builtin.h"
#include "physics/dipole.h"
#include "physics/fresnel.h"
#include "render/renderer.h"

namespace tsis {
namespace {

Renderer& renderer() {
    static Renderer r;
    return r;
}

// Mean radiosity over covered pixels.
glm::dvec3 meanRadiosity(const FrameResult& f) {
    glm::dvec3 sum(0);
    size_t n = 0;
    for (int y = 0; y < f.height; ++y)
        for (int x = 0; x < f.width; ++x)
            if (f.coverage.at(x, y, 0) > 0) {
                for (int c = 0; c < 3; ++c) sum[c] += f.radiosity.at(x, y, c);
                ++n;
            }
    return n ? sum / static_cast<double>(n) : sum;
}

// An infinite plane under uniform irradiance E has B = E · Ft(1) · ∫Rd dA.
// The plane is made large enough (half-side ≥ 7.4/σtr) that the missing tail
// of Rd is < 0.5%; the camera looks straight down at a 5 mm window at its
// centre, where B is flat, so the average over pixels is the centre value.
void checkPlane(const char* materialName, double tolerance) {
    Scene scene;
    scene.material = presetMaterial(materialName);
    Dipole dipole(scene.material);
    double sigmaTrMin =
        std::min({dipole.ch[0].sigmaTr, dipole.ch[1].sigmaTr, dipole.ch[2].sigmaTr});
    double halfSide = 7.4 / sigmaTrMin;
    scene.mesh = builtinPlane();
    normalizeMesh(scene.mesh, 2.0 * halfSide * std::sqrt(2.0));
    ensureNormals(scene.mesh);
    scene.lights = {{Light::Type::Directional, glm::vec3(0, -1, 0), glm::vec3(1.0f)}};
    scene.camera.eye = glm::vec3(0, 30, 0);
    scene.camera.target = glm::vec3(0);
    scene.camera.up = glm::vec3(0, 0, -1);
    scene.camera.fovYDegrees = static_cast<float>(2.0 * std::atan(2.5 / 30.0) * 180.0 / M_PI);
    RenderOptions opt;
    opt.width = opt.height = 48;
    opt.samples = 1 << 18;
    opt.atlasResolution = 1024;
    opt.keepAovs = true;
    FrameResult f = renderer().render(scene, opt);
    glm::dvec3 got = meanRadiosity(f);
    glm::dvec3 expected = fresnelTransmittance(scene.material.eta, 1.0) * dipole.totalReflectance();
    for (int c = 0; c < 3; ++c) {
        double err = got[c] / expected[c] - 1.0;
        std::printf("plane %s channel %d: B = %.5f, closed form %.5f, error %+.3f%%\n",
                    materialName, c, got[c], expected[c], 100 * err);
        EXPECT_NEAR(err, 0.0, tolerance) << materialName << " channel " << c;
    }
}

TEST(RenderPhysics, PlaneMarbleMatchesClosedForm) {
    checkPlane("marble", 0.02);
}
TEST(RenderPhysics, PlaneSkin1MatchesClosedForm) {
    checkPlane("skin1", 0.02);
}

// RMSE against a high-N render falls as N^-1/2 (or faster: the low-discrepancy
// u stratifies the samples). Fit of log RMSE on log N over 64 … 4096.
TEST(RenderPhysics, ErrorFallsAsInverseSqrtN) {
    Scene scene;
    scene.material = presetMaterial("skimmilk");
    scene.mesh = builtinSphere();
    normalizeMesh(scene.mesh, 10.0);
    ensureNormals(scene.mesh);
    scene.lights = {{Light::Type::Point, glm::vec3(-8, 10, -6), glm::vec3(200.0f)}};
    scene.camera.eye = glm::vec3(0, 3, 16);
    RenderOptions opt;
    opt.width = opt.height = 64;
    opt.atlasResolution = 512;
    opt.keepAovs = true;
    opt.samples = 1 << 16;
    std::vector<float> ref = renderer().render(scene, opt).radiosity.pixels;
    double refMean = 0;
    for (float v : ref) refMean += v;
    refMean /= static_cast<double>(ref.size());
    std::vector<double> logN, logE;
    for (int n : {64, 256, 1024, 4096}) {
        double mse = 0;
        const int seeds = 4;
        for (int s = 0; s < seeds; ++s) {
            opt.samples = n;
            opt.seed = 100 + s;
            std::vector<float> img = renderer().render(scene, opt).radiosity.pixels;
            for (size_t i = 0; i < img.size(); ++i) mse += (img[i] - ref[i]) * (img[i] - ref[i]);
        }
        double rel = std::sqrt(mse / (seeds * static_cast<double>(ref.size()))) / refMean;
        std::printf("N = %5d: relative RMSE %.4f\n", n, rel);
        logN.push_back(std::log(n));
        logE.push_back(std::log(rel));
    }
    double mx = 0, my = 0;
    for (size_t i = 0; i < logN.size(); ++i) mx += logN[i], my += logE[i];
    mx /= logN.size();
    my /= logN.size();
    double sxy = 0, sxx = 0;
    for (size_t i = 0; i < logN.size(); ++i)
        sxy += (logN[i] - mx) * (logE[i] - my), sxx += (logN[i] - mx) * (logN[i] - mx);
    double slope = sxy / sxx;
    std::printf("convergence slope d log RMSE / d log N = %.3f\n", slope);
    EXPECT_LT(slope, -0.4);
    EXPECT_GT(slope, -1.3);
}

}  // namespace
}  // namespace tsis
