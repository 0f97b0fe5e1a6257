#include "volumetric/camera_walk.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>
#include <limits>

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

// skin1 (η = 1.3) inside `boundary`, lit by one point light at `at`.
WalkScene skinLitBy(const MeshBoundary& boundary, const glm::vec3& at, float intensity,
                    const glm::dvec3& sky = glm::dvec3(0.0)) {
    Light light;
    light.vec = at;
    light.rgb = glm::vec3(intensity);
    return {&boundary, testMedium({0.74, 0.88, 1.01}, {0.032, 0.17, 0.48}, 1.3), {light}, sky};
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

// --env's residual is read by the paths that leave the object where the
// object does not hide it: on a convex sphere a unit environment is the unit
// sky to the last bit (same random numbers); on a small sphere 0.2 mm from a
// big one, which hides part of its sky, it is darker.
TEST(CameraWalk, EnvironmentIsHiddenOnlyWhereTheObjectHidesIt) {
    auto radiance = [](const Mesh& mesh, const glm::dvec3& toEye, bool environment) {
        const MeshBoundary boundary(mesh);
        WalkScene scene{&boundary,
                        testMedium({1.0, 1.0, 1.0}, {0.1, 0.1, 0.1}, 1.3),
                        {},
                        glm::dvec3(environment ? 0.0 : 1.0)};
        if (environment) scene.environment = [](const glm::dvec3&) { return glm::dvec3(1.0); };
        SurfaceHit hit;
        EXPECT_TRUE(boundary.intersect(toEye * 50.0, -toEye, kInfinity, hit));
        WalkCounters counters;
        glm::dvec3 sum(0.0);
        for (int i = 0; i < 2000; ++i) {
            Rng rng(5, static_cast<uint64_t>(i));
            sum += exitantRadiance(scene, hit, toEye, rng, counters);
        }
        return sum.x;
    };
    const glm::dvec3 front(0.0, 0.0, 1.0);
    EXPECT_EQ(radiance(sphere(3.0), front, true), radiance(sphere(3.0), front, false));
    // A 2 mm sphere beside a 6 mm one: the big one hides part of the small
    // one's sky, seen side on.
    Mesh pair = sphere(6.0);
    const Mesh small = sphere(2.0);
    const uint32_t base = static_cast<uint32_t>(pair.positions.size());
    for (size_t i = 0; i < small.positions.size(); ++i) {
        pair.positions.push_back(small.positions[i] + glm::vec3(0.0f, 0.0f, 4.2f));
        pair.normals.push_back(small.normals[i]);
        pair.uvs.push_back(small.uvs[i]);
    }
    for (const glm::uvec3& t : small.triangles) pair.triangles.push_back(t + base);
    const glm::dvec3 side(1.0, 0.0, 0.0);
    auto at = [&](bool environment) {
        const MeshBoundary boundary(pair);
        WalkScene scene{&boundary,
                        testMedium({1.0, 1.0, 1.0}, {0.1, 0.1, 0.1}, 1.3),
                        {},
                        glm::dvec3(environment ? 0.0 : 1.0)};
        if (environment) scene.environment = [](const glm::dvec3&) { return glm::dvec3(1.0); };
        SurfaceHit hit;
        EXPECT_TRUE(boundary.intersect(glm::dvec3(50.0, 0.0, 4.2), -side, kInfinity, hit));
        WalkCounters counters;
        double sum = 0;
        for (int i = 0; i < 2000; ++i) {
            Rng rng(5, static_cast<uint64_t>(i));
            sum += exitantRadiance(scene, hit, side, rng, counters).x;
        }
        return sum;
    };
    const double hidden = at(true), open = at(false);
    EXPECT_LT(hidden, 0.95 * open) << hidden << " vs " << open;  // measured 0.87
}

// Next-event estimation through a curved boundary against paths that escape
// into the light, which need no connection: a sun of half-angle 20° read by
// the paths that leave the object, and the same sun as one directional light
// per path (a direction drawn in its cone) connected through the facets. At
// η = 1.5 the refracted beams of a sphere's neighbouring facets overlap
// (the surface focuses the light); taking one facet's made the connection
// 12–25 % dark here, and the volumetric method ~11 % dark on spheres.
TEST(CameraWalk, ConnectionsThroughTheBoundaryAgreeWithEscapingPaths) {
    const Mesh mesh = sphere(4.0);
    const MeshBoundary boundary(mesh);
    const Medium medium = testMedium({3.0, 3.0, 3.0}, {0.05, 0.05, 0.05}, 1.5);
    const glm::dvec3 toSun = glm::normalize(glm::dvec3(0.3, 1.0, 0.2));
    const double cosMax = std::cos(20.0 * M_PI / 180.0);
    const double solidAngle = 2.0 * M_PI * (1.0 - cosMax);
    WalkScene escaping{&boundary, medium, {}, glm::dvec3(0.0), [&](const glm::dvec3& d) {
                           return glm::dvec3(glm::dot(d, toSun) >= cosMax ? 1.0 : 0.0);
                       }};
    // A frame around the sun's direction, for drawing directions in its cone.
    const glm::dvec3 t1 = glm::normalize(glm::cross(toSun, glm::dvec3(1, 0, 0)));
    const glm::dvec3 t2 = glm::cross(toSun, t1);
    WalkCounters counters;
    // Seen from the sun's side and from the side (from behind, the light is
    // too faint to measure in a unit test's time).
    for (const glm::dvec3& toEye : {toSun, glm::normalize(toSun + 2.0 * t1)}) {
        SurfaceHit hit;
        ASSERT_TRUE(boundary.intersect(toEye * 10.0, -toEye, kInfinity, hit));
        MeanEstimate byEscape, byConnection;
        // Escaping paths find the sun rarely: more of them.
        for (int i = 0; i < 60000; ++i) {
            Rng rng(21, static_cast<uint64_t>(i));
            byEscape.add(exitantRadiance(escaping, hit, toEye, rng, counters));
        }
        for (int i = 0; i < 15000; ++i) {
            Rng own(22, static_cast<uint64_t>(i));
            const double cosT = 1.0 - own.uniform() * (1.0 - cosMax),
                         phi = 2 * M_PI * own.uniform();
            const double sinT = std::sqrt(1.0 - cosT * cosT);
            Light sun;
            sun.type = Light::Type::Directional;
            sun.vec = glm::vec3(-(cosT * toSun + sinT * (std::cos(phi) * t1 + std::sin(phi) * t2)));
            sun.rgb = glm::vec3(static_cast<float>(solidAngle));
            const WalkScene connected{&boundary, medium, {sun}, glm::dvec3(0.0)};
            byConnection.add(exitantRadiance(connected, hit, toEye, own, counters));
        }
        const double a = byEscape.mean().x, b = byConnection.mean().x;
        const double sigma = std::hypot(byEscape.error(0), byConnection.error(0));
        EXPECT_NEAR(b, a, 4 * sigma) << "seen from " << toEye.x << "," << toEye.y << "," << toEye.z
                                     << ": escaping " << a << ", connected " << b;
        EXPECT_LT(sigma, 0.025 * a);  // the test sees a 10 % bias
    }
}

// Single scattering with the index matched (η = 1: no refraction, so a
// straight shadow ray is the connection) against the integral along the
// camera ray, by quadrature: L1 = ∫ σs e^(−σt t) (1/4π) I e^(−σt s(x)) / |p − x|² dt,
// s(x) the path from x to the surface towards the light.
TEST(CameraWalk, IndexMatchedSingleScatteringEqualsTheRayIntegral) {
    const Mesh mesh = sphere(4.0);
    const MeshBoundary boundary(mesh);
    const glm::dvec3 sigmaS(0.8, 1.2, 2.0), sigmaA(0.01, 0.05, 0.2);
    Light light;
    light.vec = glm::vec3(3.0f, 8.0f, 5.0f);
    light.rgb = glm::vec3(100.0f);
    WalkScene scene{&boundary, testMedium(sigmaS, sigmaA, 1.0), {light}, glm::dvec3(0.0)};
    scene.maxScatterings = 1;
    const glm::dvec3 p(light.vec);
    WalkCounters counters;
    for (const glm::dvec3& toEye :
         {glm::dvec3(0, 0, 1), glm::normalize(glm::dvec3(1, -0.5, 0.3))}) {
        SurfaceHit hit;
        ASSERT_TRUE(boundary.intersect(toEye * 10.0, -toEye, kInfinity, hit));
        SurfaceHit far;
        ASSERT_TRUE(boundary.intersect(hit.position - toEye * 1e-6, -toEye, kInfinity, far));
        glm::dvec3 integral(0.0);
        const int steps = 4000;
        const double h = far.t / steps;
        for (int i = 0; i < steps; ++i) {  // midpoint rule
            const double t = (i + 0.5) * h;
            const glm::dvec3 x = hit.position - toEye * t;
            const double r = glm::length(p - x);
            SurfaceHit out;
            ASSERT_TRUE(boundary.intersect(x, (p - x) / r, kInfinity, out));
            const glm::dvec3 sigmaT = sigmaS + sigmaA;
            integral += sigmaS * glm::exp(-sigmaT * (t + out.t)) * (100.0 / (4 * M_PI * r * r)) * h;
        }
        MeanEstimate walk;
        for (int i = 0; i < 20000; ++i) {
            Rng rng(31, static_cast<uint64_t>(i));
            walk.add(exitantRadiance(scene, hit, toEye, rng, counters));
        }
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(walk.mean()[c], integral[c], 4 * walk.error(c)) << "channel " << c;
            EXPECT_LT(walk.error(c), 0.01 * integral[c]);
        }
    }
}

// The orders of one path split exactly: single scattering alone
// (maxScatterings 1) plus every order from the second (minScatterings 2) is
// the whole path, stream for stream, at a point lit and in a sky (the
// escaping paths' part); and minScatterings 1 leaves out only what crosses
// unscattered, which a thin sphere shows and a thick one does not.
TEST(CameraWalk, ScatteringOrdersSplitEachPathExactly) {
    const Mesh mesh = sphere(3.0);
    const MeshBoundary boundary(mesh);
    const WalkScene scene = skinLitBy(boundary, {-2.0f, 6.0f, -5.0f}, 200.0f, glm::dvec3(0.05));
    SurfaceHit hit;
    ASSERT_TRUE(boundary.intersect({0.4, 0.3, 10}, {0, 0, -1}, kInfinity, hit));
    auto sum = [&](int lo, int hi) {
        WalkScene s = scene;
        s.minScatterings = lo;
        s.maxScatterings = hi;
        WalkCounters c;
        glm::dvec3 total(0.0);
        for (int i = 0; i < 4000; ++i) {
            Rng rng(17, static_cast<uint64_t>(i));
            total += exitantRadiance(s, hit, {0, 0, 1}, rng, c);
        }
        return total;
    };
    const glm::dvec3 all = sum(0, std::numeric_limits<int>::max());
    const glm::dvec3 single = sum(0, 1), multiple = sum(2, std::numeric_limits<int>::max());
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(single[c] + multiple[c], all[c], 1e-9 * all[c]) << "channel " << c;
        EXPECT_GT(single[c], 0.05 * all[c]) << "channel " << c;
        EXPECT_GT(multiple[c], 0.05 * all[c]) << "channel " << c;
    }
    // What crosses unscattered: the sky seen through the sphere. Through
    // 30 mm of skin1 nothing; through 0.1 mm most of what leaves.
    for (const double diameter : {30.0, 0.1}) {
        const Mesh m = sphere(diameter);
        const MeshBoundary b(m);
        WalkScene sky = scene;
        sky.boundary = &b;
        sky.lights.clear();
        SurfaceHit h;
        ASSERT_TRUE(b.intersect({0.01 * diameter, 0.02 * diameter, 100}, {0, 0, -1}, kInfinity, h));
        glm::dvec3 through(0.0), without(0.0);
        WalkCounters counters;
        for (int i = 0; i < 2000; ++i) {
            Rng r0(19, static_cast<uint64_t>(i)), r1(19, static_cast<uint64_t>(i));
            sky.minScatterings = 0;
            through += exitantRadiance(sky, h, {0, 0, 1}, r0, counters);
            sky.minScatterings = 1;
            without += exitantRadiance(sky, h, {0, 0, 1}, r1, counters);
        }
        for (int c = 0; c < 3; ++c) {
            if (diameter > 1)
                EXPECT_NEAR(without[c], through[c], 1e-6 * through[c]) << "channel " << c;
            else
                EXPECT_LT(without[c], 0.5 * through[c]) << "channel " << c;
        }
    }
}

TEST(CameraWalk, SameSeedSameRadiance) {
    const Mesh mesh = sphere(5.0);
    const MeshBoundary boundary(mesh);
    const WalkScene scene = skinLitBy(boundary, {0.0f, 0.0f, 20.0f}, 400.0f);
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
