#include "render/flux_octree.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "mesh/builtin.h"
#include "physics/dipole.h"

namespace tsis {
namespace {

// Irradiance samples on a 10 mm sphere lit from one side (E ∝ max(0, n·l)).
std::vector<SurfacePoint> litSphere(double spacing) {
    Mesh m = builtinSphere();
    normalizeMesh(m, 10.0);
    ensureNormals(m);
    std::vector<SurfacePoint> pts = poissonThin(placeSurfacePoints(m, 0.5 * spacing), spacing);
    const glm::vec3 l = glm::normalize(glm::vec3(1, 2, 0.5f));
    for (SurfacePoint& p : pts)
        p.irradiance = glm::vec3(1.0f, 0.6f, 0.3f) * std::max(0.0f, glm::dot(p.normal, l));
    return pts;
}

ProfileTable rdTable(const char* material) {
    const Dipole d(presetMaterial(material));
    return ProfileTable::build([&](double r) { return d.Rd(r); }, 10.0);
}

glm::dvec3 exactSum(const std::vector<SurfacePoint>& pts, const glm::vec3& x,
                    const ProfileTable& rd) {
    glm::dvec3 b(0.0);
    for (const SurfacePoint& p : pts)
        b += glm::dvec3(p.irradiance * p.area) * glm::dvec3(rd.lookup(glm::length(x - p.position)));
    return b;
}

TEST(FluxOctree, AggregatesAndEpsilonZeroSumsEverySample) {
    const std::vector<SurfacePoint> pts = litSphere(0.4);
    const FluxOctree tree(pts);
    EXPECT_EQ(tree.sampleCount(), pts.size());
    EXPECT_GT(tree.nodeCount(), pts.size() / FluxOctree::kLeafSize);
    glm::dvec3 flux(0.0);
    double area = 0;
    for (const SurfacePoint& p : pts) {
        flux += glm::dvec3(p.irradiance * p.area);
        area += p.area;
    }
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(tree.totalFlux()[c] / flux[c], 1.0, 1e-5);
    EXPECT_NEAR(tree.totalArea() / area, 1.0, 1e-5);
    const ProfileTable rd = rdTable("marble");
    for (size_t i = 0; i < pts.size(); i += pts.size() / 7) {
        long long evals = 0;
        const glm::vec3 got = tree.radiosity(pts[i].position, 0.0f, rd, &evals);
        const glm::dvec3 want = exactSum(pts, pts[i].position, rd);
        // Dark samples are skipped whole, the rest are all evaluated.
        EXPECT_LE(evals, static_cast<long long>(pts.size()));
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c] / want[c], 1.0, 1e-4) << i;
    }
}

TEST(FluxOctree, SmallerEpsilonIsCloserAndCostsMore) {
    const std::vector<SurfacePoint> pts = litSphere(0.4);
    const FluxOctree tree(pts);
    const ProfileTable rd = rdTable("skin1");
    double lastErr = 1e9;
    long long lastEvals = 0;
    for (float eps : {0.5f, 0.1f, 0.02f}) {
        double err2 = 0, ref2 = 0;
        long long evals = 0;
        for (size_t i = 0; i < pts.size(); i += 37) {
            const glm::vec3 got = tree.radiosity(pts[i].position, eps, rd, &evals);
            const glm::dvec3 want = exactSum(pts, pts[i].position, rd);
            for (int c = 0; c < 3; ++c) {
                err2 += (got[c] - want[c]) * (got[c] - want[c]);
                ref2 += want[c] * want[c];
            }
        }
        const double err = std::sqrt(err2 / ref2);
        std::printf("epsilon %.2f: relative error %.2e, %lld evaluations\n", eps, err, evals);
        EXPECT_LT(err, lastErr);
        EXPECT_GT(evals, lastEvals);
        lastErr = err;
        lastEvals = evals;
    }
    EXPECT_LT(lastErr, 2e-3);
}

TEST(FluxOctree, EmptyTreeGivesZero) {
    const FluxOctree tree;
    EXPECT_EQ(tree.radiosity(glm::vec3(0), 0.1f, rdTable("marble")), glm::vec3(0));
}

}  // namespace
}  // namespace tsis
