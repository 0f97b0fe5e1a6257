// The whole frame against physics: the plane's closed form, the estimator's
// convergence rate.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "physics/better_dipole.h"
#include "support/render.h"
#include "volumetric/mc_profile.h"

namespace tsis {
namespace {

// An infinite plane under uniform irradiance E has B = E · Ft(1) · ∫Rd dA
// (test::planeScene: the camera looks straight down at a 5 mm window at its
// centre, where B is flat, so the average over pixels is the centre value).
void checkPlane(const char* materialName, double tolerance) {
    const Scene scene = test::planeScene(materialName);
    const FrameResult f = test::renderWith(scene, test::smallOptions(48, 1024, 1 << 18), "tsis");
    test::expectNearClosedForm(test::meanRadiosity(f), test::planeClosedForm(scene.material),
                               tolerance, std::string("plane ") + materialName);
}

TEST(RenderPhysics, PlaneMarbleMatchesClosedForm) {
    checkPlane("marble", 0.02);
}
TEST(RenderPhysics, PlaneSkin1MatchesClosedForm) {
    checkPlane("skin1", 0.02);
}

// The better dipole through a whole frame with the normalised exit term: B is
// the better dipole's closed form, and L = Ft(η, cosθo)/(cπ)·B, whose exitance
// is B (physics/fresnel_test.cpp). The camera looks straight down (cosθo ≈ 1).
TEST(RenderPhysics, PlaneBetterDipoleNormalizedExit) {
    const Scene scene = test::planeScene("marble");
    RenderOptions opt = test::smallOptions(48, 1024, 1 << 18);
    opt.profile = ProfileModel::BetterDipole;
    opt.exit = ExitTerm::Normalized;
    opt.specular = false;  // the subsurface term alone
    const FrameResult f = test::renderWith(scene, opt, "tsis");
    const Material& m = scene.material;
    const double ft = fresnelTransmittance(m.eta, 1.0);
    glm::dvec3 closed;
    for (int c = 0; c < 3; ++c)
        closed[c] =
            ft * BetterDipoleChannel(m.sigmaSPrime[c], m.sigmaA[c], m.eta).totalReflectance();
    const glm::dvec3 b = test::meanRadiosity(f);
    test::expectNearClosedForm(b, closed, 0.02, "plane better dipole");
    const glm::dvec3 l = test::meanCovered(f, f.radiance);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(l[c] / b[c] * M_PI / ft, normalizedExitScale(m.eta), 2e-3) << c;
}

// --profile mc through a whole frame: B of the plane is Ft·R of the Monte
// Carlo's own walks (few paths and a private cache folder for the test).
TEST(RenderPhysics, PlaneMonteCarloProfile) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("tsis_render_mc_" + std::to_string(::getpid()));
    ::setenv("TSIS_CACHE_DIR", dir.c_str(), 1);
    ::setenv("TSIS_MC_PROFILE_PATHS", "100000", 1);
    const Scene scene = test::planeScene("skin1");
    RenderOptions opt = test::smallOptions(48, 1024, 1 << 18);
    opt.profile = ProfileModel::Mc;
    const FrameResult f = test::renderWith(scene, opt, "tsis");
    const Material& m = scene.material;
    const McProfileInput in = mcProfileInput(m.sigmaSPrime, m.sigmaA, m.eta);
    bool loaded = false;
    const McProfile mc = mcProfileFromDisk(in, &loaded);
    ::unsetenv("TSIS_MC_PROFILE_PATHS");
    ::unsetenv("TSIS_CACHE_DIR");
    std::filesystem::remove_all(dir);
    EXPECT_TRUE(loaded);  // the frame stored it
    test::expectNearClosedForm(test::meanRadiosity(f),
                               fresnelTransmittance(m.eta, 1.0) * mc.reflectance, 0.03, "plane mc");
}

// RMSE against a high-N render falls as N^-1/2 (or faster: the low-discrepancy
// u stratifies the samples). Fit of log RMSE on log N over 64 … 4096.
TEST(RenderPhysics, ErrorFallsAsInverseSqrtN) {
    const Scene scene = test::sphereScene(
        "skimmilk", {Light::Type::Point, glm::vec3(-8, 10, -6), glm::vec3(200.0f)});
    RenderOptions opt;
    opt.width = opt.height = 64;
    opt.atlasResolution = 512;
    opt.samples = 1 << 16;
    std::vector<float> ref = test::renderWith(scene, opt, "tsis").radiosity.pixels;
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
            std::vector<float> img = test::renderWith(scene, opt, "tsis").radiosity.pixels;
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
