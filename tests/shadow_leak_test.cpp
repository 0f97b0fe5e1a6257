// No light where the truth has none (issue 39 item 1), in every method: a
// solid B wholly in the shadow of a solid A beside it, across an air gap,
// gets no light. The shadow maps' filter once lit B's face towards the light
// along the edge that lines up with A's silhouette (its tent's texels past the
// silhouette see nothing and counted lit): the texture-space methods summed
// that flux into B (cubes 2 % of their size apart, light along the gap's
// normal: up to 1 % of A's top on B's top, bench/results/shadow_leak.md).
// The family: gaps of 0.1–30 % of A's size, the light from either side, along
// another axis and oblique, directional and point, cubes and spheres.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <string>

#include "atlas/atlas.h"
#include "mesh/media.h"
#include "support/boxes.h"
#include "support/render.h"

namespace tsis {
namespace {

constexpr float kSize = 20.0f;  // A: a 20 mm cube, or a sphere 20 mm across, at the origin

struct Config {
    const char* name;
    bool spheres;
    float gap;       // between A and B, a fraction of A's size
    float halfB;     // B's half size (radius), a fraction of A's size
    glm::vec3 axis;  // B lies from A along it; the light travels along it…
    glm::vec2 tilt;  // …tilted down by tilt.x and across by tilt.y
    bool point;      // a point light 3 sizes before A's centre instead
};

glm::vec3 centreOfB(const Config& c) {
    return c.axis * (kSize * (0.5f + c.gap + c.halfB));
}

// The light's direction of travel: the axis tilted down (−y) and across (z,
// or x for an axis along z).
glm::vec3 travel(const Config& c) {
    const glm::vec3 across = c.axis.z == 0 ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0);
    return glm::normalize(c.axis + glm::vec3(0, -c.tilt.x, 0) + c.tilt.y * across);
}

Scene sideBySide(const Config& c) {
    Mesh m;
    m.name = c.name;
    const glm::vec3 b = centreOfB(c);
    if (c.spheres) {
        test::addSphere(m, glm::vec3(0), kSize / 2);
        test::addSphere(m, b, kSize * c.halfB);
    } else {
        test::addBox(m, glm::vec3(-kSize / 2), glm::vec3(kSize / 2));
        test::addBox(m, b - kSize * c.halfB, b + kSize * c.halfB);
    }
    AtlasOptions atlas;
    atlas.resolution = 512;
    atlas.useCache = false;
    Scene s;
    s.mesh = buildAtlas(m, atlas);
    s.material = presetMaterial("skimmilk");
    const glm::vec3 d = travel(c);
    if (c.point) {
        const glm::vec3 p = -3.0f * kSize * d;
        s.lights = {{Light::Type::Point, p, glm::vec3(glm::dot(p, p))}};
    } else {
        s.lights = {{Light::Type::Directional, d, glm::vec3(1.0f)}};
    }
    // From above, both tops in view.
    s.camera.target = 0.5f * b;
    s.camera.eye = s.camera.target + glm::vec3(0, 110, 0.01f);
    s.camera.up = glm::vec3(0, 0, -1);
    s.camera.fovYDegrees = 35.0f;
    return s;
}

struct Tops {
    double a = 0, b = 0;  // mean radiosity (r + g + b) of A's top and of B's
};

Tops tops(const FrameResult& f, const Config& c) {
    double sum[2] = {0, 0};
    int count[2] = {0, 0};
    for (int y = 0; y < f.height; ++y)
        for (int x = 0; x < f.width; ++x) {
            if (!(f.coverage.at(x, y, 0) > 0) || f.normal.at(x, y, 1) < (c.spheres ? 0.5f : 0.9f))
                continue;
            const int m = f.medium.at(x, y, 0) > 0.5f ? 1 : 0;  // A is medium 0
            sum[m] += f.radiosity.at(x, y, 0) + f.radiosity.at(x, y, 1) + f.radiosity.at(x, y, 2);
            ++count[m];
        }
    EXPECT_GT(count[0], 50) << c.name;
    EXPECT_GT(count[1], 20) << c.name;
    return {sum[0] / std::max(count[0], 1), sum[1] / std::max(count[1], 1)};
}

const Config kFamily[] = {
    {"cubes, gap 0.1 %, dir +x", false, 0.001f, 0.5f, {1, 0, 0}, {0, 0}, false},
    {"cubes, gap 2 %, dir +z", false, 0.02f, 0.5f, {0, 0, 1}, {0, 0}, false},
    {"cubes, gap 30 %, dir -x", false, 0.30f, 0.5f, {-1, 0, 0}, {0, 0}, false},
    {"cubes, gap 10 %, dir oblique", false, 0.10f, 0.25f, {1, 0, 0}, {0.2f, 0.2f}, false},
    {"cubes, gap 10 %, point -z", false, 0.10f, 0.5f, {0, 0, -1}, {0, 0}, true},
    {"spheres, gap 2 %, dir +x", true, 0.02f, 0.4f, {1, 0, 0}, {0, 0}, false},
    {"spheres, gap 10 %, point oblique", true, 0.10f, 0.3f, {-1, 0, 0}, {0.1f, 0.1f}, true},
};

TEST(ShadowLeak, TheFamilyIsTwoMediaEach) {
    for (const Config& c : kFamily) EXPECT_EQ(findMedia(sideBySide(c).mesh).count, 2u) << c.name;
}

// B's top gets at most 0.5 % of A's top in every method (lss, which sees
// only what the camera sees lit, sees neither lit: B's must be 0 too).
TEST(ShadowLeak, NoLightReachesASolidInAnothersShadowInAnyMethod) {
    RenderOptions opt = test::smallOptions(96, 512);
    opt.spp = 4;
    for (const Config& c : kFamily) {
        const Scene scene = sideBySide(c);
        for (const std::string& method : methodNames()) {
            const Tops t = tops(test::renderWith(scene, opt, method), c);
            std::printf("%-34s %-12s A %.4g, B %.3g (%.3g%%)\n", c.name, method.c_str(), t.a, t.b,
                        t.a > 0 ? 100 * t.b / t.a : 0.0);
            EXPECT_LE(t.b, 0.005 * t.a) << c.name << ", " << method;
            if (method != "lss") {
                EXPECT_GT(t.a, 0.0) << c.name << ", " << method;
            }
        }
    }
}

}  // namespace
}  // namespace tsis
