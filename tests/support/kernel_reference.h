// Host double-precision versions of the helpers the kernels share
// (kernels/light_map.h), written from their formulas, for the kernel tests
// that compare every output value of a kernel with a host sum. Inputs are the
// same floats the kernel reads; the arithmetic is double. (kernels/hash.h is
// integer arithmetic, exact on both sides: the tests include it as it is.)
//
// Discrete choices (which texel, which table cell) are where float and double
// can part on an unlucky input. The reference counts every such choice that
// falls within a margin of its boundary (Conditioning); a test asserts there
// were none, so a mismatch it reports is the kernel's, never the test's.
#pragma once

#include <CL/cl_platform.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <random>
#include <vector>

#include "hash.h"
#include "light_map.h"
#include "tsis_shared.h"

namespace tsis::test {

// Discrete decisions taken closer than `margin` to their boundary.
struct Conditioning {
    double margin = 1e-4;
    int close = 0;

    // floor(x), noting an x within the margin of an integer.
    double floor(double x) {
        const double f = std::floor(x);
        if (x - f < margin || f + 1.0 - x < margin) ++close;
        return f;
    }
    // a < b, noting a within the margin (relative to |b|) of b.
    bool less(double a, double b) {
        if (std::abs(a - b) < margin * std::max(std::abs(b), 1.0)) ++close;
        return a < b;
    }
};

// Y(rgb) with the Rec. 709 weights of tsis_shared.h.
inline double luminance(const glm::dvec3& c) {
    return double(TSIS_LUMA_R) * c.x + double(TSIS_LUMA_G) * c.y + double(TSIS_LUMA_B) * c.z;
}

inline glm::dvec3 xyz(const cl_float4& v) {
    return {v.s[0], v.s[1], v.s[2]};
}

// A light's map as the kernels read it: a perspective view from `eye`
// towards the origin (a point light, fov 50°) or an orthographic one along
// -eye of half-width `halfWidth` mm (a directional light), res² texels.
inline TsisLightMapInfo lightMap(const glm::vec3& eye, bool perspective, int res,
                                 float halfWidth = 3.0f) {
    const glm::mat4 view = glm::lookAt(eye, glm::vec3(0.0f), glm::vec3(0, 1, 0));
    const float fov = glm::radians(50.0f);
    const glm::mat4 proj =
        perspective ? glm::perspective(fov, 1.0f, 0.1f, 100.0f)
                    : glm::ortho(-halfWidth, halfWidth, -halfWidth, halfWidth, 0.1f, 100.0f);
    const glm::mat4 viewProj = proj * view;
    TsisLightMapInfo info{};
    const float* m = glm::value_ptr(viewProj);
    for (int i = 0; i < 16; ++i) info.view_proj[i] = m[i];
    info.res = res;
    info.tau_per_w =
        perspective ? 2.0f * std::tan(0.5f * fov) / float(res) : 2.0f * halfWidth / float(res);
    return info;
}

// tsis_light_project: continuous texel coordinates (x, y) and clip w of p.
inline glm::dvec3 project(const TsisLightMapInfo& l, const glm::dvec3& p) {
    const float* m = l.view_proj;
    const double cx = m[0] * p.x + m[4] * p.y + m[8] * p.z + m[12];
    const double cy = m[1] * p.x + m[5] * p.y + m[9] * p.z + m[13];
    const double cw = m[3] * p.x + m[7] * p.y + m[11] * p.z + m[15];
    const double s = 0.5 * l.res / cw;
    return {cx * s + 0.5 * l.res, cy * s + 0.5 * l.res, cw};
}

// tsis_light_texel: the texel containing (x, y), or -1 off the map.
inline int texel(const TsisLightMapInfo& l, double x, double y, Conditioning& cond) {
    const double fx = cond.floor(x), fy = cond.floor(y);
    if (!(fx >= 0 && fy >= 0 && fx < l.res && fy < l.res)) return -1;
    return int(fy) * l.res + int(fx);
}

// tsis_light_bilinear: the flux at (x, y), a bilinear mix of the four texels
// around it, and the luminance-weighted sum of their positions (w = weight).
// Continuous in (x, y) (a texel's weight is 0 on the boundary it leaves), so
// no choice in it needs conditioning.
struct LitPoint {
    glm::dvec3 flux{0.0};
    glm::dvec4 point{0.0};
};
inline LitPoint bilinear(const TsisLightMapInfo& l, const std::vector<cl_float4>& flux,
                         const std::vector<cl_float4>& position, size_t offset, double x,
                         double y) {
    const double fx = std::floor(x - 0.5), fy = std::floor(y - 0.5);
    const double tx = x - 0.5 - fx, ty = y - 0.5 - fy;
    LitPoint lit;
    for (int k = 0; k < 4; ++k) {
        const double w = ((k & 1) ? tx : 1.0 - tx) * ((k & 2) ? ty : 1.0 - ty);
        // The texel centre's own coordinates: never near a boundary.
        Conditioning exact{0.0};
        const int t = texel(l, fx + (k & 1) + 0.5, fy + (k >> 1) + 0.5, exact);
        if (t < 0 || w <= 0.0) continue;
        const glm::dvec3 f = xyz(flux[offset + size_t(t)]);
        const double lum = w * luminance(f);
        lit.flux += w * f;
        lit.point += glm::dvec4(lum * xyz(position[offset + size_t(t)]), lum);
    }
    return lit;
}

// A light's flux and position maps over the plane z ≈ 0 seen from +z by
// lightMap(eye on the +z axis, orthographic): texel (i, j) holds the surface
// point under its centre, jittered by up to a fifth of a texel and lifted by
// up to 0.05 mm, and random flux; `empty` of the texels got no light (flux
// and position 0). `lights` maps back to back.
struct LightMaps {
    std::vector<cl_float4> flux, position;
};
inline LightMaps planeLightMaps(const TsisLightMapInfo& l, int lights, uint32_t seed,
                                double empty) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const size_t per = size_t(l.res) * size_t(l.res);
    LightMaps maps;
    maps.flux.assign(per * size_t(lights), {{0, 0, 0, 0}});
    maps.position.assign(per * size_t(lights), {{0, 0, 0, 0}});
    const float texelMm = l.tau_per_w;
    const float half = 0.5f * texelMm * float(l.res);
    for (size_t g = 0; g < maps.flux.size(); ++g) {
        if (u(rng) < empty) continue;
        const size_t t = g % per;
        const float x = (float(t % size_t(l.res)) + 0.3f + 0.4f * u(rng)) * texelMm - half;
        const float y = (float(t / size_t(l.res)) + 0.3f + 0.4f * u(rng)) * texelMm - half;
        maps.position[g] = {{x, y, 0.05f * u(rng), 1.0f}};
        maps.flux[g] = {{0.1f + u(rng), 0.1f + u(rng), 0.1f + u(rng), 1.0f}};
    }
    return maps;
}

}  // namespace tsis::test
