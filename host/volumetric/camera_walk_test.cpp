#include "volumetric/camera_walk.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "mesh/builtin.h"
#include "mesh/mesh.h"
#include "physics/fresnel.h"
#include "support/volumetric_walk.h"
#include "volumetric/mesh_boundary.h"

namespace tsis {
namespace {

Mesh sphere(double diameterMm) {
    Mesh mesh = builtinSphere();
    normalizeMesh(mesh, diameterMm * std::sqrt(3.0));  // bounding-box diagonal
    ensureNormals(mesh);
    return mesh;
}

TEST(CameraWalk, WhiteFurnaceWithoutAbsorption) {
    // σa = 0 in a closed object under a unit sky: all light that enters
    // leaves, so the radiance leaving (without the specular reflection) is
    // exactly Ft(η, cosθo) in every direction. Channels with different σt
    // exercise the spectral weights; the mesh, the Fresnel splits inside.
    const Mesh mesh = sphere(3.0);
    const MeshBoundary boundary(mesh);
    WalkScene scene{&boundary, testMedium({2.19, 2.62, 3.0}, {0, 0, 0}, 1.5), {}, glm::dvec3(1.0)};
    WalkCounters counters;
    for (double angle : {0.0, 0.7, 1.2}) {
        const glm::dvec3 toEye(std::sin(angle), 0.0, std::cos(angle));
        SurfaceHit hit;
        ASSERT_TRUE(boundary.intersect(toEye * 10.0, -toEye, kInfinity, hit));
        const double ft = fresnelTransmittance(1.5, glm::dot(hit.normal, toEye));
        MeanEstimate walk;
        const int n = 4000;
        for (int i = 0; i < n; ++i) {
            Rng rng(11, static_cast<uint64_t>(i));
            walk.add(exitantRadiance(scene, hit, toEye, rng, counters));
        }
        for (int c = 0; c < 3; ++c) {
            const double mean = walk.mean()[c], err = walk.error(c);
            EXPECT_NEAR(mean, ft, 4 * err + 1e-9) << "angle " << angle << " channel " << c;
        }
    }
}

TEST(CameraWalk, SameSeedSameRadiance) {
    const Mesh mesh = sphere(5.0);
    const MeshBoundary boundary(mesh);
    Light light;
    light.vec = glm::vec3(0.0f, 0.0f, 20.0f);
    light.rgb = glm::vec3(400.0f);
    WalkScene scene{&boundary,
                    testMedium({0.74, 0.88, 1.01}, {0.032, 0.17, 0.48}, 1.3),
                    {light},
                    glm::dvec3(0.0)};
    SurfaceHit hit;
    ASSERT_TRUE(boundary.intersect({0, 0, 10}, {0, 0, -1}, kInfinity, hit));
    WalkCounters c;
    Rng a(5, 9), b(5, 9), other(6, 9);
    const glm::dvec3 first = exitantRadiance(scene, hit, {0, 0, 1}, a, c);
    EXPECT_EQ(first, exitantRadiance(scene, hit, {0, 0, 1}, b, c));
    EXPECT_NE(first, exitantRadiance(scene, hit, {0, 0, 1}, other, c));
}

}  // namespace
}  // namespace tsis
