// Shared by the render tests: one renderer per test program (one GL context),
// small scenes, and the error metric the sweep uses.
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <string>

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

// An infinite plane under a normal directional light: B = Ft(1)·∫Rd dA. Large
// enough (half-side 7.4/σtr) that Rd's missing tail is < 0.5%; the camera sees
// a 5 mm window at its centre, where B is flat.
inline Scene planeScene(const char* material) {
    Scene s;
    s.material = presetMaterial(material);
    const Dipole dipole(s.material);
    const double sigmaTrMin =
        std::min({dipole.ch[0].sigmaTr, dipole.ch[1].sigmaTr, dipole.ch[2].sigmaTr});
    const double halfSide = 7.4 / sigmaTrMin;
    s.mesh = builtinPlane();
    normalizeMesh(s.mesh, 2.0 * halfSide * std::sqrt(2.0));
    ensureNormals(s.mesh);
    s.lights = {{Light::Type::Directional, glm::vec3(0, -1, 0), glm::vec3(1.0f)}};
    s.camera.eye = glm::vec3(0, 30, 0);
    s.camera.target = glm::vec3(0);
    s.camera.up = glm::vec3(0, 0, -1);
    s.camera.fovYDegrees = static_cast<float>(2.0 * std::atan(2.5 / 30.0) * 180.0 / M_PI);
    return s;
}

inline glm::dvec3 planeClosedForm(const Material& m) {
    return fresnelTransmittance(m.eta, 1.0) * Dipole(m).totalReflectance();
}

// Mean radiosity over covered pixels.
inline glm::dvec3 meanRadiosity(const FrameResult& f) {
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

// RMSE over covered pixels and channels of the radiosity, relative to the
// reference's mean.
inline double relativeRmse(const FrameResult& f, const FrameResult& ref) {
    double se = 0, sum = 0;
    size_t n = 0;
    for (int y = 0; y < ref.height; ++y)
        for (int x = 0; x < ref.width; ++x)
            if (ref.coverage.at(x, y, 0) > 0)
                for (int c = 0; c < 3; ++c) {
                    const double d = f.radiosity.at(x, y, c) - ref.radiosity.at(x, y, c);
                    se += d * d;
                    sum += ref.radiosity.at(x, y, c);
                    ++n;
                }
    return n && sum > 0 ? std::sqrt(se / n) / (sum / n) : 0.0;
}

}  // namespace tsis::test
