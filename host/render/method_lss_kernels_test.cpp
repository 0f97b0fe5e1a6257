// kernels/lss.cl against host double versions: the per-pixel surface
// (position, E times the pixel's surface area) and the image-space gather
// B(xo) = 1/M Σ_k E(x_k)·Rd(|xo − x_k|)·A(x_k) / (p(r_k)·s_o²), for both
// lane widths of the gather (kernels/lss.cl, host/render/method_lss.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "render/method_lss.h"
#include "support/analytic_table.h"
#include "support/cl_fixture.h"
#include "support/kernel_reference.h"

namespace tsis {
namespace {

using test::ClTest;
using test::Conditioning;

constexpr int kWidth = 12, kHeight = 10;

// The camera at (0, 0, 20) looking down −z, fov 40°.
TsisCamera camera() {
    Camera c;
    c.eye = glm::vec3(0, 0, 20);
    c.target = glm::vec3(0);
    c.up = glm::vec3(0, 1, 0);
    c.fovYDegrees = 40.0f;
    return LssMethod::camera(c, kHeight);
}

// A G-buffer of a bumpy surface under the camera, the four corners uncovered.
struct GBuffer {
    std::vector<cl_float4> position, normal, irradiance;
};
GBuffer gbuffer(const TsisCamera& cam, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    GBuffer g;
    const float pixelMm = 20.0f * cam.pixel_angle;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const bool corner = (x == 0 || x == kWidth - 1) && (y == 0 || y == kHeight - 1);
            const float px = (float(x) + 0.5f - 0.5f * kWidth) * pixelMm;
            const float py = (float(y) + 0.5f - 0.5f * kHeight) * pixelMm;
            g.position.push_back(
                {{px, py, std::sin(0.3f * px) * std::cos(0.2f * py), corner ? 0.0f : 1.0f}});
            // Unnormalised (the kernel normalises), one of them nearly edge-on.
            const float tilt = x == 5 && y == 5 ? 20.0f : u(rng);
            g.normal.push_back({{tilt, 0.5f * u(rng), 1.5f, 0.0f}});
            g.irradiance.push_back({{u(rng), u(rng), u(rng), 0.0f}});
        }
    return g;
}

class LssKernelTest : public ClTest, public ::testing::WithParamInterface<int> {
  protected:
    cl::Kernel prepare = rt.kernel("lss.cl", "tsis_lss_prepare");
    cl::Kernel gather =
        rt.kernel("lss.cl", "tsis_lss_gather", "-DTSIS_LSS_LANES=" + std::to_string(GetParam()));
};

// pos = (x, 1) where covered, ea = E·d³ / (ρ·max(|n̂·ω|, min_cos)); zeros where
// not. Tolerance 1e-6 relative (a handful of float operations).
TEST_P(LssKernelTest, PrepareGivesPositionAndIrradianceTimesArea) {
    const TsisCamera cam = camera();
    const GBuffer g = gbuffer(cam, 1);
    const int pixels = kWidth * kHeight;
    cl::Buffer pos = buffer(pixels * sizeof(cl_float4)), ea = buffer(pixels * sizeof(cl_float4));
    run(prepare, pixels, upload(g.position), upload(g.normal), upload(g.irradiance), pixels, cam,
        pos, ea);
    const std::vector<cl_float4> p = download<cl_float4>(pos, pixels),
                                 e = download<cl_float4>(ea, pixels);
    const glm::dvec3 eye(cam.ex, cam.ey, cam.ez), view(cam.fx, cam.fy, cam.fz);
    int clamped = 0;
    for (int i = 0; i < pixels; ++i) {
        if (!(g.position[i].s[3] > 0.0f)) {
            for (int c = 0; c < 4; ++c) EXPECT_EQ(p[i].s[c] + e[i].s[c], 0.0f) << i;
            continue;
        }
        const glm::dvec3 v = test::xyz(g.position[i]) - eye;
        const double rho = glm::length(v), d = glm::dot(v, view);
        const double cosine = std::abs(glm::dot(glm::normalize(test::xyz(g.normal[i])), v / rho));
        clamped += cosine < cam.min_cos;
        const double area = d * d * d / (rho * std::max(cosine, double(cam.min_cos)));
        for (int c = 0; c < 3; ++c) {
            EXPECT_EQ(p[i].s[c], g.position[i].s[c]) << i;
            const double want = g.irradiance[i].s[c] * area;
            EXPECT_NEAR(e[i].s[c], want, 1e-6 * want) << i << " channel " << c;
        }
        EXPECT_EQ(p[i].s[3], 1.0f) << i;
        EXPECT_EQ(e[i].s[3], 0.0f) << i;
    }
    EXPECT_EQ(clamped, 1) << "the edge-on pixel is clamped to min_cos";
}

// The gather on prepared surface values against its sum in double (samples
// on another medium's pixels add nothing): M = 20
// samples (not a multiple of 8: the last vector is partial), an 8-cell radius
// table, every covered pixel. Tolerance per value: 1e-5 of Σ|terms| (float
// products summed over M; the sample radius and position move by rounding).
TEST_P(LssKernelTest, GatherMatchesHostDoubleSum) {
    const TsisCamera cam = camera();
    const GBuffer g = gbuffer(cam, 2);
    const int m = 20, entries = 8;
    const uint32_t seed = 3;
    // The surface as prepare leaves it; E·A made up (prepare is tested above).
    std::vector<cl_float4> pos(g.position.size()), ea(g.position.size());
    std::vector<int> pixels;
    for (size_t i = 0; i < pos.size(); ++i) {
        const bool covered = g.position[i].s[3] > 0.0f;
        // Two media (tags 1, 2: mesh/media.h), the right third of the image the second.
        const float tag = i % kWidth >= 2 * kWidth / 3 ? 2.0f : 1.0f;
        pos[i] = covered
                     ? cl_float4{{g.position[i].s[0], g.position[i].s[1], g.position[i].s[2], tag}}
                     : cl_float4{{0, 0, 0, 0}};
        ea[i] = covered ? cl_float4{{g.irradiance[i].s[0] * 900, g.irradiance[i].s[1] * 700,
                                     g.irradiance[i].s[2] * 800, 0}}
                        : cl_float4{{0, 0, 0, 0}};
        if (covered) pixels.push_back(int(i));
    }
    std::vector<float> radii;
    for (int k = 0; k <= entries; ++k) radii.push_back(0.4f * std::pow(float(k), 1.5f));
    std::vector<cl_float2> dirs(24, cl_float2{{0, 0}});
    for (int k = 0; k < m; ++k) dirs[size_t(k)] = {{std::cos(2.4f * k), std::sin(2.4f * k)}};
    const ProfileTable t = test::analyticTable(10.0);

    // Host: the formula of kernels/lss.cl in double.
    Conditioning cond{3e-5};
    const glm::dvec3 eye(cam.ex, cam.ey, cam.ez), view(cam.fx, cam.fy, cam.fz);
    std::vector<glm::dvec3> want(pixels.size(), glm::dvec3(0.0)), mag = want;
    for (size_t j = 0; j < pixels.size(); ++j) {
        const int pix = pixels[j];
        const int row = pix / kWidth, column = pix % kWidth;
        const double px = column + 0.5, py = row + 0.5;
        const glm::dvec3 xo = test::xyz(pos[size_t(pix)]);
        const double depth = glm::dot(xo - eye, view);
        const double perMm = 1.0 / (depth * cam.pixel_angle);
        const uint32_t h1 = tsis_hash(uint32_t(pix) ^ tsis_hash(seed));
        const uint32_t h2 = tsis_hash(h1 + 0x9e3779b9U);
        const double xi = tsis_hash_unit(h1), phi = 2.0 * M_PI * tsis_hash_unit(h2);
        const double norm = entries * 2.0 * M_PI / (m * depth * depth);
        for (int k = 0; k < m; ++k) {
            const double tk = (k + xi) * entries / m;
            const int i = std::min(int(cond.floor(tk)), entries - 1);
            const double r0 = radii[size_t(i)], r1 = radii[size_t(i) + 1];
            const double r = r0 + (tk - i) * (r1 - r0);
            const double dx = dirs[size_t(k)].s[0], dy = dirs[size_t(k)].s[1];
            const double sx =
                cond.floor(px + (std::cos(phi) * dx - std::sin(phi) * dy) * r * perMm);
            const double sy =
                cond.floor(py + (std::sin(phi) * dx + std::cos(phi) * dy) * r * perMm);
            if (!(sx >= 0 && sx < kWidth && sy >= 0 && sy < kHeight)) continue;
            const size_t q = size_t(sy) * kWidth + size_t(sx);
            if (pos[q].s[3] != pos[size_t(pix)].s[3]) continue;  // another medium: no light
            const double dist = glm::length(test::xyz(pos[q]) - xo);
            for (int c = 0; c < 3; ++c) {
                const double term = (r1 - r0) * r * test::lookup(t, dist, c) * ea[q].s[c] * norm;
                want[j][c] += term;
                mag[j][c] += std::abs(term);
            }
        }
    }
    ASSERT_EQ(cond.close, 0) << "a sample on a pixel or radius-cell boundary: choose another seed";

    const TsisCamera kcam = cam;
    cl::Buffer out = buffer(pixels.size() * sizeof(cl_float4));
    run(gather, pixels.size(), upload(pixels), int(pixels.size()), upload(pos), upload(ea), kWidth,
        kHeight, upload(dirs), m, upload(radii), entries, upload(t.rgba), t.info, kcam,
        cl_uint(seed), out);
    const std::vector<cl_float4> got = download<cl_float4>(out, pixels.size());
    int lit = 0;
    for (size_t j = 0; j < pixels.size(); ++j) {
        for (int c = 0; c < 3; ++c)
            ASSERT_NEAR(got[j].s[c], want[j][c], 1e-5 * mag[j][c] + 1e-12)
                << "pixel " << pixels[j] << " channel " << c;
        EXPECT_EQ(got[j].s[3], 0.0f);
        lit += want[j].x > 0.0;
    }
    EXPECT_EQ(lit, int(pixels.size())) << "every pixel gathers something (its own neighbourhood)";
}

INSTANTIATE_TEST_SUITE_P(Lanes, LssKernelTest, ::testing::Values(1, 8),
                         [](const auto& info) { return "lanes" + std::to_string(info.param); });

}  // namespace
}  // namespace tsis
