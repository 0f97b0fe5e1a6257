// Shared by the render tests: one renderer per test program (one GL context),
// small options and scenes, and the error metrics the tests measure with.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <string>
#include <vector>

#include "compare/image_compare.h"
#include "mesh/builtin.h"
#include "physics/dipole.h"
#include "physics/fresnel.h"
#include "physics/material.h"
#include "render/renderer.h"

namespace tsis::test {

inline Renderer& sharedRenderer() {
    static Renderer r;
    return r;
}

inline FrameResult renderWith(const Scene& scene, RenderOptions opt, const std::string& method) {
    opt.method = method;
    opt.keepAovs = true;
    return sharedRenderer().render(scene, opt);
}

// A small frame: size² pixels, the flux atlas and the light maps at
// resolution², N = samples.
// The thesis' model (--model thesis): the methods' tests check how they
// integrate the profile, against its closed forms and the reference; the
// object's transport has its own (volumetric/patch_transfer_test.cpp,
// tests/model_truth_test.cpp).
inline RenderOptions smallOptions(int size, int resolution, int samples = RenderOptions{}.samples) {
    RenderOptions opt;
    opt.transport = Transport::Off;
    opt.width = opt.height = size;
    opt.atlasResolution = resolution;
    opt.lightResolution = resolution;
    opt.samples = samples;
    return opt;
}

// The default torus (thin glowing top, thick bottom), back-lit by one point
// light, seen from the front.
inline Scene torusScene(const char* material, double sizeMm) {
    Scene s;
    s.material = presetMaterial(material);
    s.mesh = builtinDefault();
    normalizeMesh(s.mesh, sizeMm);
    ensureNormals(s.mesh);
    const float d = static_cast<float>(sizeMm);
    const glm::vec3 p = glm::vec3(-0.45f, 0.75f, -1.0f) * (1.3f * d);
    s.lights = {{Light::Type::Point, p, glm::vec3(glm::dot(p, p))}};
    s.camera.eye = glm::normalize(glm::vec3(0.0f, 0.35f, 1.0f)) * (1.6f * d);
    s.camera.fovYDegrees = 40.0f;
    return s;
}

// A 10 mm sphere lit by `light`, seen from the front and a little above.
inline Scene sphereScene(const char* material, const Light& light) {
    Scene s;
    s.material = presetMaterial(material);
    s.mesh = builtinSphere();
    normalizeMesh(s.mesh, 10.0);
    ensureNormals(s.mesh);
    s.lights = {light};
    s.camera.eye = glm::vec3(0, 3, 16);
    return s;
}

// A square plane of half-side halfSideMm at y = 0 under a normal directional
// light, seen straight down from eyeMm above its centre through a window of
// ±viewMm.
inline Scene squarePlaneScene(const char* material, double halfSideMm, double eyeMm,
                              double viewMm) {
    Scene s;
    s.material = presetMaterial(material);
    s.mesh = builtinPlane();
    normalizeMesh(s.mesh, 2.0 * halfSideMm * std::sqrt(2.0));
    ensureNormals(s.mesh);
    s.lights = {{Light::Type::Directional, glm::vec3(0, -1, 0), glm::vec3(1.0f)}};
    s.camera.eye = glm::vec3(0.0f, static_cast<float>(eyeMm), 0.0f);
    s.camera.target = glm::vec3(0);
    s.camera.up = glm::vec3(0, 0, -1);
    s.camera.fovYDegrees = static_cast<float>(2.0 * std::atan(viewMm / eyeMm) * 180.0 / M_PI);
    return s;
}

// An infinite plane under a normal directional light: B = Ft(1)·∫Rd dA. Its
// half-side is reach/σtr of the longest-range channel, so that Rd's missing
// tail is ~e^-reach (< 0.5% at 7.4); the camera sees a 5 mm window at its
// centre, where B is flat.
inline Scene planeScene(const char* material, double reach = 7.4) {
    const Dipole dipole(presetMaterial(material));
    const double sigmaTrMin =
        std::min({dipole.ch[0].sigmaTr, dipole.ch[1].sigmaTr, dipole.ch[2].sigmaTr});
    return squarePlaneScene(material, reach / sigmaTrMin, 30.0, 2.5);
}

inline glm::dvec3 planeClosedForm(const Material& m) {
    return fresnelTransmittance(m.eta, 1.0) * Dipole(m).totalReflectance();
}

// Pixels with coverage.
inline size_t coveredPixels(const FrameResult& f) {
    size_t n = 0;
    for (int y = 0; y < f.height; ++y)
        for (int x = 0; x < f.width; ++x) n += f.coverage.at(x, y, 0) > 0;
    return n;
}

// fn(x, y, position, unit normal) for each covered pixel of f's AOVs.
template <typename F>
void forEachSurfacePixel(const FrameResult& f, F&& fn) {
    for (int y = 0; y < f.height; ++y)
        for (int x = 0; x < f.width; ++x) {
            if (f.coverage.at(x, y, 0) == 0) continue;
            const glm::dvec3 p(f.position.at(x, y, 0), f.position.at(x, y, 1),
                               f.position.at(x, y, 2));
            fn(x, y, p,
               glm::normalize(
                   glm::dvec3(f.normal.at(x, y, 0), f.normal.at(x, y, 1), f.normal.at(x, y, 2))));
        }
}

// Mean of an AOV of `f` (radiosity, radiance) over covered pixels.
inline glm::dvec3 meanCovered(const FrameResult& f, const ImageF& aov) {
    glm::dvec3 sum(0);
    size_t n = 0;
    for (int y = 0; y < f.height; ++y)
        for (int x = 0; x < f.width; ++x)
            if (f.coverage.at(x, y, 0) > 0) {
                for (int c = 0; c < 3; ++c) sum[c] += aov.at(x, y, c);
                ++n;
            }
    return n ? sum / static_cast<double>(n) : sum;
}
inline glm::dvec3 meanRadiosity(const FrameResult& f) {
    return meanCovered(f, f.radiosity);
}

// RMSE over covered pixels and channels of the radiosity, relative to the
// reference's mean (tsis compare's rel_rmse).
inline double relativeRmse(const FrameResult& f, const FrameResult& ref) {
    return compareImages(f.radiosity, ref.radiosity, &ref.coverage, "frame", "reference")
        .metrics.relRmse;
}

// Relative RMSE of each method against the ground truth (--method reference),
// in order, all rendered at `opt` (the reference reads neither N nor the seed).
inline std::vector<double> errorsAgainstReference(const Scene& scene, const RenderOptions& opt,
                                                  const std::vector<std::string>& methods) {
    const FrameResult ref = renderWith(scene, opt, "reference");
    std::vector<double> errors;
    errors.reserve(methods.size());
    for (const std::string& m : methods)
        errors.push_back(relativeRmse(renderWith(scene, opt, m), ref));
    return errors;
}

// B per channel within `tolerance` (relative) of a closed form; prints both.
inline void expectNearClosedForm(const glm::dvec3& got, const glm::dvec3& expected,
                                 double tolerance, const std::string& what) {
    for (int c = 0; c < 3; ++c) {
        const double err = got[c] / expected[c] - 1.0;
        std::printf("%s channel %d: B = %.5f, closed form %.5f, %+.3f%%\n", what.c_str(), c, got[c],
                    expected[c], 100 * err);
        EXPECT_NEAR(err, 0.0, tolerance) << what << " channel " << c;
    }
}

}  // namespace tsis::test
