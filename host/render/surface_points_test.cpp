#include "render/surface_points.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include "mesh/builtin.h"
#include "physics/fresnel.h"
#include "render/ray_caster.h"
#include "tsis_shared.h"

namespace tsis {
namespace {

Mesh oneTriangle() {
    Mesh m;
    m.positions = {{0, 0, 0}, {0, 0, 2}, {1.5f, 0, 0}};  // faces +y
    m.normals = {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
    m.triangles = {{0, 1, 2}};
    return m;
}

// A horizontal square at height y facing +y (two triangles), side s, centred at (cx, cz).
void addSquare(Mesh& m, float y, float s, float cx = 0, float cz = 0) {
    const uint32_t b = static_cast<uint32_t>(m.positions.size());
    const float h = s / 2;
    m.positions.insert(
        m.positions.end(),
        {{cx - h, y, cz - h}, {cx + h, y, cz - h}, {cx + h, y, cz + h}, {cx - h, y, cz + h}});
    m.normals.insert(m.normals.end(), 4, glm::vec3(0, 1, 0));
    m.triangles.insert(m.triangles.end(), {{b, b + 2, b + 1}, {b, b + 3, b + 2}});
}

TEST(SurfacePoints, SubTrianglesNoLongerThanSpacingCoverTheTriangle) {
    const Mesh m = oneTriangle();
    const double spacing = 0.3;
    const std::vector<SurfacePoint> pts = placeSurfacePoints(m, spacing);
    const int k = static_cast<int>(std::ceil(std::sqrt(1.5 * 1.5 + 4.0) / spacing));  // 9
    ASSERT_EQ(pts.size(), static_cast<size_t>(k * k));
    double area = 0;
    glm::dvec3 centroid(0.0);
    for (const SurfacePoint& p : pts) {
        area += p.area;
        centroid += glm::dvec3(p.position) * static_cast<double>(p.area);
        EXPECT_NEAR(p.area, m.triangleArea(0) / (k * k), 1e-7);
        EXPECT_EQ(p.normal, glm::vec3(0, 1, 0));
        EXPECT_GE(p.position.x, 0.0f);
        EXPECT_GE(p.position.z, 0.0f);
        EXPECT_LE(p.position.x / 1.5 + p.position.z / 2.0, 1.0 + 1e-6) << "inside";
    }
    EXPECT_NEAR(area, 1.5, 1e-6);
    // The centroid rule integrates linear functions exactly.
    centroid /= area;
    EXPECT_NEAR(centroid.x, 0.5, 1e-6);
    EXPECT_NEAR(centroid.z, 2.0 / 3.0, 1e-6);
    // Deterministic.
    const std::vector<SurfacePoint> again = placeSurfacePoints(m, spacing);
    for (size_t i = 0; i < pts.size(); ++i) EXPECT_EQ(pts[i].position, again[i].position);
    // A triangle smaller than the spacing keeps one point.
    EXPECT_EQ(placeSurfacePoints(m, 10.0).size(), 1u);
}

TEST(SurfacePoints, AreasSumToTheMeshArea) {
    Mesh m = builtinSphere();
    normalizeMesh(m, 10.0);
    ensureNormals(m);
    double area = 0;
    for (const SurfacePoint& p : placeSurfacePoints(m, 0.05)) area += p.area;
    EXPECT_NEAR(area / m.surfaceArea(), 1.0, 1e-5);
}

TEST(SurfacePoints, CountWithoutPlacing) {
    Mesh m = builtinSphere();
    normalizeMesh(m, 10.0);
    ensureNormals(m);
    for (double spacing : {10.0, 0.5, 0.05})
        EXPECT_EQ(surfacePointCount(m, spacing), placeSurfacePoints(m, spacing).size()) << spacing;
}

TEST(SurfacePoints, IrradianceOfPointAndDirectionalLightsWithShadow) {
    Mesh m;
    addSquare(m, 0.0f, 4.0f);
    addSquare(m, 1.0f, 1.0f);  // occluder over the centre
    const RayCaster rays(m);
    const double eta = 1.3;
    const glm::dvec3 n(0, 1, 0);
    // Directional light at 60° from the normal, travelling down towards -x.
    const glm::dvec3 dir = glm::normalize(glm::dvec3(-std::sqrt(3.0), -1.0, 0.0));
    const std::vector<Light> sun = {
        {Light::Type::Directional, glm::vec3(dir), glm::vec3(2, 1, 0.5f)}};
    const double cos60 = 0.5, ft = fresnelTransmittance(eta, cos60);
    const glm::dvec3 lit = irradianceAt({-1.5, 0, -1.5}, n, sun, eta, rays, 1e-4, 100.0);
    EXPECT_NEAR(lit.x, 2 * ft * cos60, 1e-6);  // the light's direction is float
    EXPECT_NEAR(lit.z, 0.5 * ft * cos60, 1e-6);
    // Under the occluder's shadow: the sun comes from +x, 60° off vertical, so
    // the shadow of the 1 mm square at height 1 is shifted by -√3 in x.
    EXPECT_EQ(irradianceAt({-std::sqrt(3.0), 0, 0}, n, sun, eta, rays, 1e-4, 100.0), glm::dvec3(0));
    // Light from below the surface: nothing.
    const std::vector<Light> below = {{Light::Type::Directional, glm::vec3(0, 1, 0), glm::vec3(1)}};
    EXPECT_EQ(irradianceAt({1.5, 0, 1.5}, n, below, eta, rays, 1e-4, 100.0), glm::dvec3(0));
    // Point light straight above at distance 2: I Ft(1) / d².
    const std::vector<Light> bulb = {{Light::Type::Point, glm::vec3(1.5f, 2, 1.5f), glm::vec3(8)}};
    EXPECT_NEAR(irradianceAt({1.5, 0, 1.5}, n, bulb, eta, rays, 1e-4, 100.0).y,
                8 * fresnelTransmittance(eta, 1.0) / 4, 1e-12);
    // The occluder blocks it for a point below it; the top of the occluder is lit.
    const std::vector<Light> over = {{Light::Type::Point, glm::vec3(0, 3, 0), glm::vec3(1)}};
    EXPECT_EQ(irradianceAt({0.1, 0, 0.1}, n, over, eta, rays, 1e-4, 100.0), glm::dvec3(0));
    EXPECT_GT(irradianceAt({0.1, 1, 0.1}, n, over, eta, rays, 1e-4, 100.0).x, 0.0);
    std::vector<Light> unshadowed = over;
    unshadowed[0].shadows = false;
    EXPECT_GT(irradianceAt({0.1, 0, 0.1}, n, unshadowed, eta, rays, 1e-4, 100.0).x, 0.0);
}

// A square occluder over a ground square under a vertical directional light:
// the ground's flux and its first moment are those of the exactly known lit
// region, though the shadow's edges run between the sample points.
TEST(SurfacePoints, ShadowEdgesAreIntegratedAdaptively) {
    Mesh m;
    addSquare(m, 0.0f, 4.0f);
    addSquare(m, 1.0f, 2.0f, 0.37f, 0.13f);
    const RayCaster rays(m);
    const std::vector<Light> sun = {{Light::Type::Directional, glm::vec3(0, -1, 0), glm::vec3(1)}};
    const double e0 = fresnelTransmittance(1.3, 1.0);
    auto groundFlux = [&](const std::vector<SurfacePoint>& pts, bool exactE) {
        glm::dvec3 sum(0.0);  // flux, then the moment in x and z
        for (const SurfacePoint& p : pts) {
            if (p.position.y > 0.5f) continue;
            const double e = exactE ? irradianceAt(glm::dvec3(p.position), glm::dvec3(p.normal),
                                                   sun, 1.3, rays, 1e-4, 100.0)
                                          .x
                                    : p.irradiance.x;
            sum += e * p.area * glm::dvec3(1.0, p.position.x, p.position.z);
        }
        return sum;
    };
    // Lit: the ground minus the occluder's 2×2 footprint centred at (0.37, 0.13).
    const glm::dvec3 exact = e0 * glm::dvec3(12.0, -4.0 * 0.37, -4.0 * 0.13);
    const double spacing = 0.3;
    const glm::dvec3 adaptive =
        groundFlux(sampleSurface(m, spacing, sun, findMedia(m), {1.3}, rays, 1e-4, 100.0), false);
    const glm::dvec3 centroids = groundFlux(placeSurfacePoints(m, spacing), true);
    std::printf("lit flux: exact %.5f, adaptive %.5f, centroid rule %.5f\n", exact.x, adaptive.x,
                centroids.x);
    EXPECT_NEAR(adaptive.x / exact.x, 1.0, 1e-3);
    for (int c = 1; c < 3; ++c) EXPECT_NEAR(adaptive[c], exact[c], 2e-3 * exact.x) << c;
    // What the refinement buys: the plain centroid rule is several times further off.
    EXPECT_GT(std::abs(centroids.x - exact.x), 3 * std::abs(adaptive.x - exact.x));
}

TEST(SurfacePoints, PoissonThinningKeepsDistanceAndConservesAreaAndFlux) {
    Mesh m;
    addSquare(m, 0.0f, 6.0f);
    std::vector<SurfacePoint> pts = placeSurfacePoints(m, 0.1);
    for (SurfacePoint& p : pts)
        p.irradiance = glm::vec3(1.0f + p.position.x, 2.0f, p.position.z * p.position.z);
    const double radius = 0.5;
    const std::vector<SurfacePoint> thin = poissonThin(pts, radius);
    auto totals = [](const std::vector<SurfacePoint>& s) {
        glm::dvec4 t(0.0);
        for (const SurfacePoint& p : s)
            t += glm::dvec4(glm::dvec3(p.irradiance) * static_cast<double>(p.area), p.area);
        return t;
    };
    const glm::dvec4 before = totals(pts), after = totals(thin);
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(after[c] / before[c], 1.0, 1e-5) << c;
    // The first moment of luminous flux is kept (the points sit at the cells' centroids).
    auto moment = [](const std::vector<SurfacePoint>& s) {
        glm::dvec3 m(0.0);
        for (const SurfacePoint& p : s) {
            const glm::dvec3 f = glm::dvec3(p.irradiance) * static_cast<double>(p.area);
            m += TSIS_LUMINANCE(f.x, f.y, f.z) * glm::dvec3(p.position);
        }
        return m;
    };
    const glm::dvec3 m0 = moment(pts), m1 = moment(thin);
    for (int c = 0; c < 3; c += 2) EXPECT_NEAR(m1[c], m0[c], 1e-4 * std::abs(m0[c]) + 1e-3) << c;
    // Cells are about `radius` across: no two points nearly coincide.
    for (size_t i = 0; i < thin.size(); ++i)
        for (size_t j = i + 1; j < thin.size(); ++j)
            ASSERT_GE(glm::length(thin[i].position - thin[j].position), 0.25 * radius);
    // A maximal disk packing of radius r has between 1/(π r²)·… and 2/(√3 r²) points per area.
    const double density = thin.size() / 36.0;
    EXPECT_GT(density, 1.0 / (M_PI * radius * radius));
    EXPECT_LT(density, 2.0 / (std::sqrt(3.0) * radius * radius));
    // Deterministic.
    const std::vector<SurfacePoint> again = poissonThin(pts, radius);
    ASSERT_EQ(again.size(), thin.size());
    for (size_t i = 0; i < thin.size(); ++i) EXPECT_EQ(again[i].position, thin[i].position);
}

TEST(SurfacePoints, OppositeSidesOfAThinSheetDoNotMerge) {
    std::vector<SurfacePoint> pts(2);
    pts[0].position = glm::vec3(0, 0.01f, 0);
    pts[0].normal = glm::vec3(0, 1, 0);
    pts[1].position = glm::vec3(0, -0.01f, 0);
    pts[1].normal = glm::vec3(0, -1, 0);
    pts[0].area = pts[1].area = 1;
    EXPECT_EQ(poissonThin(pts, 1.0).size(), 2u);
    pts[1].normal = glm::vec3(0, 1, 0);
    EXPECT_EQ(poissonThin(pts, 1.0).size(), 1u);
}

TEST(SurfacePoints, CacheRebuildsOnlyWhenItsInputsChange) {
    Scene scene;
    addSquare(scene.mesh, 0.0f, 2.0f);
    scene.material = presetMaterial("skin1");
    scene.lights = {{Light::Type::Directional, glm::vec3(0, -1, 0), glm::vec3(1)}};
    SurfaceSampleCache cache;
    EXPECT_TRUE(cache.update(scene, 0.2, "test"));
    EXPECT_FALSE(cache.update(scene, 0.2, "test"));
    const float e = cache.points()[0].irradiance.x;
    EXPECT_NEAR(e, fresnelTransmittance(scene.material.eta, 1.0), 1e-6);
    scene.material.sigmaA *= 2.0;  // E does not depend on σ: only the spacing does
    EXPECT_FALSE(cache.update(scene, 0.2, "test"));
    EXPECT_TRUE(cache.update(scene, 0.1, "test"));
    scene.lights[0].rgb = glm::vec3(2);
    EXPECT_TRUE(cache.update(scene, 0.1, "test"));
    EXPECT_NEAR(cache.points()[0].irradiance.x, 2 * e, 1e-6);
    scene.lights[0].shadows = false;
    EXPECT_TRUE(cache.update(scene, 0.1, "test"));
    scene.material.eta = 1.5;
    EXPECT_TRUE(cache.update(scene, 0.1, "test"));
    scene.mesh.positions[0].y += 0.01f;
    EXPECT_TRUE(cache.update(scene, 0.1, "test"));
}

}  // namespace
}  // namespace tsis
