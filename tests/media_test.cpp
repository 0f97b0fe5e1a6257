// Media (mesh/media.h): light under the surface never crosses from one solid
// to another, in every method. Two skim-milk cubes 0.5 mm apart, the lower one
// narrower and wholly in the upper one's shadow (a light from above): the
// lower cube's front face next to the gap gets no light. Before media, every
// method but volumetric summed the upper cube's entry points there too (~24 %
// of the upper cube's radiosity across the gap).
#include "mesh/media.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <glm/geometric.hpp>

#include "atlas/atlas.h"
#include "support/boxes.h"
#include "support/render.h"

namespace tsis {
namespace {

Scene twoCubes(glm::vec3 lightTravels = {0, -1, 0}) {
    Mesh m;
    m.name = "two cubes";
    test::addBox(m, {-10, 0.25f, -10}, {10, 20.25f, 10});
    test::addBox(m, {-8, -20.25f, -8}, {8, -0.25f, 8});
    AtlasOptions atlas;
    atlas.resolution = 512;
    atlas.useCache = false;
    Scene s;
    s.mesh = buildAtlas(m, atlas);
    s.material = presetMaterial("skimmilk");
    s.lights = {{Light::Type::Directional, glm::normalize(lightTravels), glm::vec3(1.0f)}};
    s.camera.eye = glm::vec3(0, 0, 70);
    return s;
}

struct Bands {
    double lit = 0;      // upper cube's front face, its top millimetre (the lit side)
    double nearGap = 0;  // lower cube's front face, the millimetre below the gap
};

// Mean red radiosity over the front faces' bands (pixels by their position).
Bands bands(const FrameResult& f) {
    Bands b;
    int lit = 0, near = 0;
    for (int y = 0; y < f.height; ++y)
        for (int x = 0; x < f.width; ++x) {
            if (!(f.coverage.at(x, y, 0) > 0) || f.position.at(x, y, 2) < 7.9f) continue;
            const float py = f.position.at(x, y, 1), r = f.radiosity.at(x, y, 0);
            // The medium AOV: the upper cube (first in the mesh) is medium 0.
            EXPECT_EQ(f.medium.at(x, y, 0), py > 0 ? 0.0f : 1.0f) << x << ", " << y;
            if (py > 19.25f) {
                b.lit += r;
                ++lit;
            }
            if (py < -0.25f && py > -1.25f && std::abs(f.position.at(x, y, 0)) < 7) {
                b.nearGap += r;
                ++near;
            }
        }
    EXPECT_GT(lit, 0);
    EXPECT_GT(near, 0);
    b.lit /= std::max(lit, 1);
    b.nearGap /= std::max(near, 1);
    return b;
}

TEST(Media, TwoCubesAreTwoMedia) {
    const Scene s = twoCubes();
    EXPECT_EQ(findMedia(s.mesh).count, 2u);
}

TEST(Media, NoLightCrossesTheGapInAnyMethod) {
    const Scene scene = twoCubes();
    RenderOptions opt = test::smallOptions(128, 512);
    opt.spp = 4;
    for (const std::string& method : methodNames()) {
        const Bands b = bands(test::renderWith(scene, opt, method));
        std::printf("%-12s lit %.4g, next to the gap %.3g (%.3g%%)\n", method.c_str(), b.lit,
                    b.nearGap, 100 * b.nearGap / b.lit);
        // lss sees only what the camera sees lit: here nothing, so no figure.
        EXPECT_LE(b.nearGap, 0.01 * b.lit) << method;
        if (method != "lss") {
            EXPECT_GT(b.lit, 0.0) << method;
        }
    }
}

// Both cubes lit (from above and in front; the lower one's top in the upper
// one's shadow).
TEST(Media, PyramidAgreesWithTheReferenceOnTwoCubes) {
    const Scene scene = twoCubes({0.3f, -1, -1});
    const RenderOptions opt = test::smallOptions(128, 512);
    const FrameResult ref = test::renderWith(scene, opt, "reference");
    const double err = test::relativeRmse(test::renderWith(scene, opt, "pyramid"), ref);
    std::printf("pyramid vs reference on two cubes: %.2f%% rel. RMSE\n", 100 * err);
    EXPECT_LT(err, 0.02);
}

}  // namespace
}  // namespace tsis
