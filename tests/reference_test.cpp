// The ground truth: --method reference against an independent double-precision
// sum and the plane's closed form, and its convergence in the sample spacing.
// (--method hierarchical against it: hierarchical_test.cpp.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>

#include "render/method_reference.h"
#include "support/render.h"

namespace tsis {
namespace {

// Flat vertex normals and planar UVs: the methods here read neither the atlas
// nor the UVs, but the GL mesh upload wants them.
void addTriangle(Mesh& m, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    const uint32_t i = static_cast<uint32_t>(m.positions.size());
    const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
    for (const glm::vec3& p : {a, b, c}) {
        m.positions.push_back(p);
        m.normals.push_back(n);
        m.uvs.emplace_back(0.5f + p.x / 20, 0.5f + p.z / 20);
    }
    m.triangles.emplace_back(i, i + 1, i + 2);
}

// B(xo) = ∫ E(x) Rd(|xo − x|) dA written out in double, with visibility by
// geometry instead of rays: a point light over a ground plane and one
// floating triangle casts the triangle's projection S onto the ground, so
// B = Σ_triangles ∫ E₀ Rd − ∫_S E₀ Rd with E₀ the unshadowed irradiance: smooth
// integrands only, summed by the centroid rule at a quarter of the reference's
// spacing, with the analytic Rd.
struct BruteForce {
    struct Q {
        glm::dvec3 x, e;
        double area;  // negative inside the shadow
    };
    std::vector<Q> q;
    Dipole dipole;

    // Triangles: the ground's first, the occluder last (its vertices at one height).
    BruteForce(const Scene& s, double spacing) : dipole(s.material) {
        const Mesh& m = s.mesh;
        const glm::dvec3 light(s.lights.at(0).vec), rgb(s.lights.at(0).rgb);
        auto add = [&](const glm::dvec3(&p)[3], const glm::dvec3& n, double sign) {
            const double edge = std::max(
                {glm::length(p[1] - p[0]), glm::length(p[2] - p[1]), glm::length(p[0] - p[2])});
            const int k = static_cast<int>(std::ceil(edge / spacing));
            const double area = 0.5 * glm::length(glm::cross(p[1] - p[0], p[2] - p[0])) / (k * k);
            for (int i = 0; i < k; ++i)
                for (int j = 0; i + j < k; ++j)
                    for (int up = 0; up < (i + j + 1 < k ? 2 : 1); ++up) {
                        const double u = (i + (up ? 2.0 : 1.0) / 3) / k;
                        const double v = (j + (up ? 2.0 : 1.0) / 3) / k;
                        const glm::dvec3 x = p[0] + u * (p[1] - p[0]) + v * (p[2] - p[0]);
                        const glm::dvec3 toLight = light - x;
                        const double d2 = glm::dot(toLight, toLight);
                        const double cosI = glm::dot(n, toLight) / std::sqrt(d2);
                        const glm::dvec3 e =
                            cosI > 0
                                ? rgb * (fresnelTransmittance(s.material.eta, cosI) * cosI / d2)
                                : glm::dvec3(0.0);
                        q.push_back({x, e, sign * area});
                    }
        };
        glm::dvec3 p[3] = {};
        for (size_t t = 0; t < m.triangles.size(); ++t) {
            for (int i = 0; i < 3; ++i) p[i] = glm::dvec3(m.positions[m.triangles[t][i]]);
            add(p, glm::dvec3(m.normals[m.triangles[t].x]), 1.0);
        }
        // The occluder's shadow on y = 0: its vertices projected from the light.
        for (int i = 0; i < 3; ++i) p[i] = light + (p[i] - light) * (light.y / (light.y - p[i].y));
        add(p, glm::dvec3(0, 1, 0), -1.0);
    }
    glm::dvec3 operator()(const glm::dvec3& xo) const {
        glm::dvec3 b(0.0);
        for (const Q& s : q) b += s.e * s.area * dipole.Rd(glm::length(xo - s.x));
        return b;
    }
};

// A ground square with a floating triangle over it that shades part of it.
TEST(Reference, MatchesAnIndependentDoubleSum) {
    Scene scene;
    scene.material = presetMaterial("skin1");
    addTriangle(scene.mesh, {-4, 0, -4}, {-4, 0, 4}, {4, 0, 4});
    addTriangle(scene.mesh, {-4, 0, -4}, {4, 0, 4}, {4, 0, -4});
    addTriangle(scene.mesh, {-1.5f, 1.5f, -1}, {0, 1.5f, 2}, {1.5f, 1.5f, -1});
    // A light in general position: no row of sample points lies on a shadow edge.
    scene.lights = {{Light::Type::Point, glm::vec3(3.7f, 6.2f, 0.3f), glm::vec3(52)}};
    scene.camera.eye = glm::vec3(0, 12, 0);
    scene.camera.up = glm::vec3(0, 0, -1);
    scene.camera.fovYDegrees = 40;
    RenderOptions opt;
    opt.transport = Transport::Off;  // the thesis' model: its closed forms
    opt.width = opt.height = 24;
    const FrameResult f = test::renderWith(scene, opt, "reference");
    const BruteForce brute(scene, ReferenceMethod::defaultSpacing(scene.material) / 4);
    double se = 0, sum = 0, worst = 0, shadowed = 0;
    size_t n = 0;
    for (int y = 0; y < f.height; ++y)
        for (int x = 0; x < f.width; ++x) {
            if (f.coverage.at(x, y, 0) <= 0) continue;
            const glm::dvec3 xo(f.position.at(x, y, 0), f.position.at(x, y, 1),
                                f.position.at(x, y, 2));
            const glm::dvec3 want = brute(xo);
            for (int c = 0; c < 3; ++c) {
                const double got = f.radiosity.at(x, y, c), d = got - want[c];
                se += d * d;
                sum += want[c];
                worst = std::max(worst, std::abs(d) / want[c]);
                ++n;
            }
            // Ground pixels in the occluder's shadow, beside it as the camera sees it.
            if (xo.y < 0.1 && std::abs(xo.x + 2.3) < 0.3 && std::abs(xo.z + 0.8) < 0.3)
                shadowed = want.z;
        }
    ASSERT_GT(n, 300u);
    const double rel = std::sqrt(se / n) / (sum / n);
    std::printf("reference vs double sum: relative RMSE %.4f%%, worst pixel %.4f%% (%zu values)\n",
                100 * rel, 100 * worst, n);
    // Typically 0.1%; the worst pixels lie near the open edges and corners of
    // the occluder, where the centroid rule at h = ℓ/2 is ~0.7% off (0.15% at h/2).
    EXPECT_LT(rel, 0.002);
    EXPECT_LT(worst, 0.01);
    // The scene has a shadow worth testing: in blue (the shortest range) the
    // ground in it gets less than half of what an open ground point does.
    EXPECT_GT(shadowed, 0.0);
    EXPECT_LT(shadowed, 0.5 * brute({3, 0, 3}).z);
}

// An infinite plane under uniform irradiance E has B = E · Ft(1) · ∫Rd dA (the
// closed form of docs/design.md §2). Plane half-side 12/σtr: the missing tail is
// ~e^-12; the camera looks at a 5 mm window at its centre.
TEST(Reference, PlaneMatchesClosedFormWithinHalfAPercent) {
    const Scene scene = test::planeScene("skin1", 12.0);
    RenderOptions opt;
    opt.transport = Transport::Off;  // the thesis' model: its closed forms
    opt.width = opt.height = 32;
    const FrameResult f = test::renderWith(scene, opt, "reference");
    const glm::dvec3 expected = test::planeClosedForm(scene.material);
    double worst = 0;
    for (int y = 0; y < f.height; ++y)
        for (int x = 0; x < f.width; ++x)
            for (int c = 0; c < 3; ++c) {
                ASSERT_GT(f.coverage.at(x, y, 0), 0);
                worst = std::max(worst, std::abs(f.radiosity.at(x, y, c) / expected[c] - 1.0));
            }
    std::printf("plane skin1: worst pixel %.4f%% from the closed form\n", 100 * worst);
    EXPECT_LT(worst, 0.005);
}

// A coarse sphere (facets much larger than the spacing, so the subdivision is
// what the spacing controls), marble: halving the spacing moves the
// radiosity by less than 0.5% relative RMSE.
TEST(Reference, HalvingTheSpacingChangesLessThanHalfAPercent) {
    Scene scene;
    scene.material = presetMaterial("marble");
    const int slices = 8, stacks = 4;
    const float r = 3.0f;
    auto at = [&](int i, int j) {
        const double phi = 2 * M_PI * i / slices, theta = M_PI * j / stacks;
        return glm::vec3(r * std::sin(theta) * std::cos(phi), r * std::cos(theta),
                         r * std::sin(theta) * std::sin(phi));
    };
    for (int j = 0; j <= stacks; ++j)
        for (int i = 0; i <= slices; ++i) {
            scene.mesh.positions.push_back(at(i, j));
            scene.mesh.normals.push_back(glm::normalize(at(i, j)));
            scene.mesh.uvs.emplace_back(float(i) / slices, float(j) / stacks);
        }
    for (int j = 0; j < stacks; ++j)
        for (int i = 0; i < slices; ++i) {
            const uint32_t a = j * (slices + 1) + i, b = a + 1, c = a + slices + 1, d = c + 1;
            if (j > 0) scene.mesh.triangles.emplace_back(a, b, c);
            if (j < stacks - 1) scene.mesh.triangles.emplace_back(b, d, c);
        }
    // Back-right key light (a terminator in view) and a front fill.
    scene.lights = {{Light::Type::Point, glm::vec3(8, 5, -6), glm::vec3(120)},
                    {Light::Type::Directional, glm::vec3(-0.3f, -0.2f, -1), glm::vec3(0.2f)}};
    scene.camera.eye = glm::vec3(0, 2, 12);
    RenderOptions opt;
    opt.transport = Transport::Off;  // the thesis' model: its closed forms
    opt.width = opt.height = 48;
    const double h = ReferenceMethod::defaultSpacing(scene.material);
    opt.spacingMm = h;
    const FrameResult coarse = test::renderWith(scene, opt, "reference");
    opt.spacingMm = h / 2;
    const FrameResult fine = test::renderWith(scene, opt, "reference");
    EXPECT_GT(test::coveredPixels(fine), 0u);
    const double rel = test::relativeRmse(coarse, fine);
    std::printf("spacing %.4f mm vs %.4f mm: relative RMSE %.4f%%\n", h, h / 2, 100 * rel);
    EXPECT_LT(rel, 0.005);
}

}  // namespace
}  // namespace tsis
