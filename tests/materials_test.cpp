// Materials (issue 20, docs/design.md §2 "Materials"): each object scatters
// with its own material in every method, and a textured albedo is a factor on
// the light entering and leaving (render/albedo_atlas.h) — checked against
// renders of one material and against the plane's closed form.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <glm/geometric.hpp>

#include "atlas/atlas.h"
#include "mesh/media.h"
#include "render/albedo_inversion.h"
#include "render/env_reflection.h"
#include "render/mfp_map.h"
#include "render/surface_atlas.h"
#include "scene/environment.h"
#include "support/boxes.h"
#include "support/render.h"
#include "util/error.h"

namespace tsis {
namespace {

ObjectMaterial objectMaterial(const char* preset) {
    ObjectMaterial o;
    o.medium = presetMaterial(preset);
    o.albedo = albedoOf(o.medium, ProfileModel::Dipole);
    return o;
}

// Two 10 mm cubes 2 mm apart, side by side, lit from the front and above:
// the left one of file material 0, the right one of 1.
Scene twoCubes(const char* left, const char* right) {
    Mesh m;
    m.name = "two cubes";
    test::addBox(m, {-11, -5, -5}, {-1, 5, 5}, 0);
    test::addBox(m, {1, -5, -5}, {11, 5, 5}, 1);
    AtlasOptions atlas;
    atlas.resolution = 512;
    atlas.useCache = false;
    Scene s;
    s.mesh = buildAtlas(m, atlas);
    s.mesh.materialIds = m.materialIds;    // the triangles keep their order
    s.material = presetMaterial("skin1");  // no triangle uses it
    s.objectMaterials = {objectMaterial(left), objectMaterial(right)};
    s.lights = {
        {Light::Type::Directional, glm::normalize(glm::vec3(0.3f, -1, -1)), glm::vec3(1.0f)}};
    s.camera.eye = glm::vec3(0, 10, 40);
    return s;
}

// Relative RMSE of `aov` between two frames over the covered pixels of one
// cube (x < 0: the left one), against b's mean there.
double cubeError(const FrameResult& a, const FrameResult& b, bool left, bool radiance) {
    double sum2 = 0, sum = 0;
    size_t n = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            if (!(b.coverage.at(x, y, 0) > 0) || (b.position.at(x, y, 0) < 0) != left) continue;
            for (int c = 0; c < 3; ++c) {
                const float va = (radiance ? a.radiance : a.radiosity).at(x, y, c);
                const float vb = (radiance ? b.radiance : b.radiosity).at(x, y, c);
                sum2 += double(va - vb) * (va - vb);
                sum += vb;
                ++n;
            }
        }
    EXPECT_GT(n, 0u);
    return n && sum > 0 ? std::sqrt(sum2 / double(n)) / (sum / double(n)) : 0.0;
}

// Each cube of the two-material scene renders as it does when the whole scene
// is of its material: in every method, radiosity and radiance (η and the exit
// term per medium).
TEST(Materials, EachObjectScattersWithItsOwnMaterialInEveryMethod) {
    const Scene both = twoCubes("skin1", "marble");
    const Scene allSkin = twoCubes("skin1", "skin1"), allMarble = twoCubes("marble", "marble");
    RenderOptions opt = test::smallOptions(96, 512);
    opt.spp = 4;
    for (const std::string& method : methodNames()) {
        const FrameResult f = test::renderWith(both, opt, method);
        const FrameResult skin = test::renderWith(allSkin, opt, method);
        const FrameResult marble = test::renderWith(allMarble, opt, method);
        const double el = cubeError(f, skin, true, false), er = cubeError(f, marble, false, false);
        const double ll = cubeError(f, skin, true, true), lr = cubeError(f, marble, false, true);
        std::printf("%-12s skin1 cube %.2e (radiance %.2e), marble cube %.2e (%.2e)\n",
                    method.c_str(), el, ll, er, lr);
        // The sampling methods spread one sample budget over both cubes, whose
        // fluxes differ (η): their noise moves — by no more than it moves
        // with the seed.
        double left = 1e-4, right = 1e-4;
        // pyramid: each run's sparse grid is planned over its own points, so
        // beside the other cube it evaluates pixels the one-material frame
        // interpolates (measured 8.0e-4).
        if (method == "pyramid") left = right = 2e-3;
        if (method == "tsis" || method == "hybrid" || method == "mis") {
            RenderOptions other = opt;
            other.seed = opt.seed + 1;
            left = 2 * cubeError(test::renderWith(allSkin, other, method), skin, true, false);
            right = 2 * cubeError(test::renderWith(allMarble, other, method), marble, false, false);
            std::printf("%-12s another seed: skin1 cube %.2e, marble cube %.2e\n", method.c_str(),
                        left / 2, right / 2);
        }
        for (double e : {el, ll}) EXPECT_LT(e, left) << method;
        for (double e : {er, lr}) EXPECT_LT(e, right) << method;
        // And the two materials differ there by far more.
        EXPECT_GT(cubeError(skin, marble, false, false), 0.1) << method;
    }
}

// One connected solid of two materials (issue 39): a 20 mm box whose half
// x < 0 is of file material 0 and x > 0 of 1, every face split at x = 0 (its
// vertices there welded, so one medium). Each quad has its own vertices and
// normal, as test::addBox's.
Scene splitBox(const char* left, const char* right) {
    Mesh m;
    m.name = "split box";
    auto quad = [&](std::array<glm::vec3, 4> c, uint32_t material) {
        const auto base = static_cast<unsigned>(m.positions.size());
        const glm::vec3 n = glm::normalize(glm::cross(c[1] - c[0], c[2] - c[0]));
        for (const glm::vec3& p : c) m.positions.push_back(p), m.normals.push_back(n);
        m.triangles.emplace_back(base, base + 1, base + 2);
        m.triangles.emplace_back(base, base + 2, base + 3);
        m.materialIds.insert(m.materialIds.end(), {material, material});
    };
    const float h = 10;
    for (uint32_t side = 0; side < 2; ++side) {
        const float x0 = side == 0 ? -h : 0, x1 = side == 0 ? 0 : h;
        quad({{{x0, -h, h}, {x1, -h, h}, {x1, h, h}, {x0, h, h}}}, side);      // +z
        quad({{{x1, -h, -h}, {x0, -h, -h}, {x0, h, -h}, {x1, h, -h}}}, side);  // −z
        quad({{{x0, h, h}, {x1, h, h}, {x1, h, -h}, {x0, h, -h}}}, side);      // +y
        quad({{{x0, -h, -h}, {x1, -h, -h}, {x1, -h, h}, {x0, -h, h}}}, side);  // −y
    }
    quad({{{-h, -h, -h}, {-h, -h, h}, {-h, h, h}, {-h, h, -h}}}, 0);  // −x
    quad({{{h, -h, h}, {h, -h, -h}, {h, h, -h}, {h, h, h}}}, 1);      // +x
    AtlasOptions atlas;
    atlas.resolution = 512;
    atlas.useCache = false;
    Scene s;
    s.mesh = buildAtlas(m, atlas);
    s.mesh.materialIds = m.materialIds;
    s.material = presetMaterial("skin1");  // no triangle uses it
    s.objectMaterials = {objectMaterial(left), objectMaterial(right)};
    // From the front and above; the camera sees the front and the top, where
    // the light that reaches the top crossed the solid under the surface.
    s.lights = {
        {Light::Type::Directional, glm::normalize(glm::vec3(0.2f, -0.4f, -1)), glm::vec3(1.0f)}};
    s.camera.eye = glm::vec3(0, 30, 45);
    return s;
}

// Each half of the split box `both` renders as the box all of that half's
// medium (`left`, `right`) does, radiosity and radiance, in every method
// but volumetric, whose walk fills a solid with its first triangle's
// medium; and the two wholes differ there by more than `apart`.
void expectEachHalfAsItsWhole(const Scene& both, const Scene& left, const Scene& right,
                              double apart) {
    RenderOptions opt = test::smallOptions(96, 512);
    for (const std::string& method : methodNames()) {
        if (method == "volumetric") continue;
        const FrameResult f = test::renderWith(both, opt, method);
        const FrameResult a = test::renderWith(left, opt, method);
        const FrameResult b = test::renderWith(right, opt, method);
        const double el = cubeError(f, a, true, false), er = cubeError(f, b, false, false);
        const double ll = cubeError(f, a, true, true), lr = cubeError(f, b, false, true);
        std::printf("%-12s left half %.2e (radiance %.2e), right half %.2e (%.2e)\n",
                    method.c_str(), el, ll, er, lr);
        // pyramid plans its sparse grid per run (as above); mis draws its
        // distance samples by the point's place in its run's list: within
        // twice what another seed moves it.
        double within[2] = {method == "pyramid" ? 2e-3 : 1e-4, method == "pyramid" ? 2e-3 : 1e-4};
        if (method == "mis") {
            RenderOptions other = opt;
            other.seed = opt.seed + 1;
            within[0] = 2 * cubeError(test::renderWith(left, other, method), a, true, false);
            within[1] = 2 * cubeError(test::renderWith(right, other, method), b, false, false);
            std::printf("%-12s another seed: left half %.2e, right half %.2e\n", method.c_str(),
                        within[0] / 2, within[1] / 2);
        }
        for (double e : {el, ll}) EXPECT_LT(e, within[0]) << method;
        for (double e : {er, lr}) EXPECT_LT(e, within[1]) << method;
        EXPECT_GT(cubeError(a, b, false, false), apart) << method;
    }
}

// Each triangle of one solid is its own material: a point scatters with its
// own triangle's profile, over the entry points of the whole solid, so each
// half of the split box renders as the box all of that half's material does
// (the same flux enters: one η). Every method but volumetric, whose walk
// fills a solid with its first triangle's medium.
TEST(Materials, EachTriangleOfOneSolidScattersWithItsOwnMaterial) {
    const Scene both = splitBox("skin1", "apple");
    EXPECT_EQ(findMedia(both.mesh).count, 1u);
    expectEachHalfAsItsWhole(both, splitBox("skin1", "skin1"), splitBox("apple", "apple"), 0.1);
}

// A sky bright above and dark below: a lobe's width shows in its reflection.
std::shared_ptr<const EnvironmentMap> halfSky() {
    const int w = 32, h = 16;
    std::vector<float> sky(static_cast<size_t>(w) * h * 3);
    for (int y = 0; y < h; ++y)
        std::fill_n(&sky[static_cast<size_t>(y) * w * 3], w * 3, y < h / 2 ? 0.4f : 0.02f);
    return splitEnvironment("sky", w, h, 3, sky);
}

// Each object's surface has its file's roughness (ObjectMaterial::roughness)
// in the lights' lobe and in the environment's reflection: each cube renders
// as it does when every surface has its roughness; --roughness R replaces
// both. The two roughnesses' frames differ on each cube by far more than the
// bound, so a lobe of the wrong object shows.
TEST(Materials, EachObjectReflectsWithItsOwnRoughness) {
    Scene files = twoCubes("marble", "marble");
    files.objectMaterials[0].roughness = 0.15;
    files.objectMaterials[1].roughness = 0.8;
    RenderOptions opt = test::smallOptions(96, 256, 64);
    opt.aa = 1;
    for (bool env : {false, true}) {
        SCOPED_TRACE(env ? "a sky as well" : "a light");
        Scene scene = files;
        if (env) scene.env.map = halfSky();
        const FrameResult both = test::renderWith(scene, opt, "pyramid");
        RenderOptions all = opt;
        all.roughness = 0.15f;
        const FrameResult smooth = test::renderWith(scene, all, "pyramid");
        all.roughness = 0.8f;
        const FrameResult rough = test::renderWith(scene, all, "pyramid");
        EXPECT_LT(cubeError(both, smooth, true, true), 1e-5);
        EXPECT_LT(cubeError(both, rough, false, true), 1e-5);
        EXPECT_GT(cubeError(smooth, rough, true, true), 0.01);
        EXPECT_GT(cubeError(smooth, rough, false, true), 0.01);
        // Without the file's: kDefaultRoughness, or --roughness for all.
        Scene plain = scene;
        for (ObjectMaterial& o : plain.objectMaterials) o.roughness = -1;
        all.roughness = 0.3f;
        const FrameResult fixed = test::renderWith(plain, all, "pyramid");
        EXPECT_LT(cubeError(test::renderWith(plain, opt, "pyramid"), fixed, true, true), 1e-6);
        EXPECT_LT(cubeError(test::renderWith(scene, all, "pyramid"), fixed, false, true), 1e-6);
    }
}

// A texture of the medium's own albedo changes nothing (≤ 1e-4).
TEST(Materials, ConstantAlbedoTextureEqualsTheConstantMaterial) {
    const Light light{Light::Type::Point, glm::vec3(10, 12, 8), glm::vec3(200.0f)};
    const Scene plain = test::sphereScene("skin1", light);
    Scene textured = plain;
    ObjectMaterial o = objectMaterial("skin1");
    auto texture = std::make_shared<AlbedoTexture>();
    texture->name = "constant";
    texture->image = ImageF{4, 4, 3, {}};
    for (int i = 0; i < 16; ++i)
        for (int c = 0; c < 3; ++c) texture->image.pixels.push_back(float(o.albedo[c]));
    o.texture = texture;
    textured.objectMaterials = {o};
    textured.mesh.materialIds.assign(textured.mesh.triangles.size(), 0);
    textured.mesh.texcoords = textured.mesh.uvs;
    const RenderOptions opt = test::smallOptions(64, 512);
    for (const char* method : {"pyramid", "ltsm", "lss", "reference"}) {
        const FrameResult a = test::renderWith(plain, opt, method);
        const FrameResult b = test::renderWith(textured, opt, method);
        const double err = test::relativeRmse(b, a);
        std::printf("%-8s constant texture vs constant material: %.2e rel. RMSE\n", method, err);
        EXPECT_LT(err, 1e-4) << method;
    }
}

// A plane whose left half has albedo a1 and right half a2 (one medium, the
// mean albedo's): far from the border each half is a homogeneous plane of its
// albedo, B = Ft(1)·a·E (the inversion makes a the profile's total).
TEST(Materials, PlaneOfTwoAlbedoHalvesMatchesEachHalfsClosedForm) {
    const glm::dvec3 a1(0.8, 0.6, 0.4), a2(0.3, 0.45, 0.7), mfp(0.1);
    Scene s = test::squarePlaneScene("skin1", 5.0, 30.0, 2.5);
    ObjectMaterial o;
    o.medium = materialFromAlbedo("halves", 0.5 * (a1 + a2), mfp, 1.3, ProfileModel::Dipole);
    o.albedo = albedoOf(o.medium, ProfileModel::Dipole);
    auto texture = std::make_shared<AlbedoTexture>();
    texture->name = "halves";
    texture->image = ImageF{64, 1, 3, {}};
    for (int x = 0; x < 64; ++x)
        for (int c = 0; c < 3; ++c) texture->image.pixels.push_back(float(x < 32 ? a1[c] : a2[c]));
    o.texture = texture;
    s.objectMaterials = {o};
    s.mesh.materialIds.assign(s.mesh.triangles.size(), 0);
    s.mesh.texcoords = s.mesh.uvs;
    const double ell = 1.0 / Dipole(o.medium).sigmaTr().x;  // the longest diffusion length
    const glm::dvec3 e(fresnelTransmittance(1.3, 1.0));
    for (const char* method : {"pyramid", "ltsm"}) {
        const FrameResult f = test::renderWith(s, test::smallOptions(64, 1024), method);
        // Which half a pixel lies in, by its texture coordinate: u = the atlas' u here.
        glm::dvec3 sum[2] = {glm::dvec3(0.0), glm::dvec3(0.0)};
        int n[2] = {0, 0};
        for (int y = 0; y < f.height; ++y)
            for (int x = 0; x < f.width; ++x) {
                if (!(f.coverage.at(x, y, 0) > 0)) continue;
                const double px = f.position.at(x, y, 0);
                if (std::abs(px) < 5 * ell) continue;
                // builtin:plane's u runs along +x.
                const int half = px < 0 ? 0 : 1;
                for (int c = 0; c < 3; ++c) sum[half][c] += f.radiosity.at(x, y, c);
                ++n[half];
            }
        ASSERT_GT(n[0], 0);
        ASSERT_GT(n[1], 0);
        test::expectNearClosedForm(sum[0] / double(n[0]), e * a1, 0.01,
                                   std::string(method) + " left half");
        test::expectNearClosedForm(sum[1] / double(n[1]), e * a2, 0.01,
                                   std::string(method) + " right half");
    }
}

// A normal map of one colour: every texel's tangent-space normal `t`.
std::shared_ptr<AlbedoTexture> constantNormalMap(const glm::dvec3& t) {
    auto map = std::make_shared<AlbedoTexture>();
    map->name = "tilt";
    map->image = ImageF{4, 4, 3, {}};
    for (int i = 0; i < 16; ++i)
        for (int c = 0; c < 3; ++c) map->image.pixels.push_back(float(0.5 * (t[c] + 1.0)));
    return map;
}

// Normal maps (render/surface_atlas.h) turn the shading normal: on a plane
// whose map tilts every normal by θ, the G-buffer's normal is the tilted one
// (along the texture's u for +x, up the image for +y), and the radiosity is
// the plane's own under a light θ off its normal, as the entry's cosine
// says, ≠ the unmapped plane's under the same light.
TEST(Materials, NormalMapTurnsTheShadingNormalAndTheEntry) {
    const double theta = 25.0 * M_PI / 180.0;
    Scene plain = test::planeScene("marble");
    plain.mesh.texcoords = plain.mesh.uvs;  // builtin:plane's u runs along +x
    // "Up the image": where the texture's v (downwards) decreases.
    size_t low = 0, high = 0;
    for (size_t v = 0; v < plain.mesh.texcoords.size(); ++v) {
        if (plain.mesh.texcoords[v].y < plain.mesh.texcoords[low].y) low = v;
        if (plain.mesh.texcoords[v].y > plain.mesh.texcoords[high].y) high = v;
    }
    glm::dvec3 up = glm::dvec3(plain.mesh.positions[low] - plain.mesh.positions[high]);
    up = glm::normalize(up - glm::dvec3(0, up.y, 0));
    ObjectMaterial o;
    o.medium = plain.material;
    o.albedo = albedoOf(o.medium, ProfileModel::Dipole);
    RenderOptions opt = test::smallOptions(48, 512);
    opt.aa = 1;
    auto meanB = [](const FrameResult& f) { return test::meanCovered(f, f.radiosity); };
    const glm::dvec3 n(0, 1, 0);
    for (const glm::dvec3& axis : {glm::dvec3(1, 0, 0), up}) {
        SCOPED_TRACE(axis == up ? "+y" : "+x");
        Scene mapped = plain;
        o.normalMap =
            constantNormalMap(axis == up ? glm::dvec3(0, std::sin(theta), std::cos(theta))
                                         : glm::dvec3(std::sin(theta), 0, std::cos(theta)));
        mapped.objectMaterials = {o};
        mapped.mesh.materialIds.assign(mapped.mesh.triangles.size(), 0);
        const FrameResult f = test::renderWith(mapped, opt, "pyramid");
        const glm::dvec3 tilted = std::sin(theta) * axis + std::cos(theta) * n;
        double worst = 1;
        test::forEachSurfacePixel(f, [&](int, int, const glm::dvec3&, const glm::dvec3& g) {
            worst = std::min(worst, glm::dot(g, tilted));
        });
        EXPECT_GT(worst, 0.9995);
        Scene turned = plain;
        turned.lights[0].vec = glm::vec3(-(std::cos(theta) * n - std::sin(theta) * axis));
        const glm::dvec3 b = meanB(f), expected = meanB(test::renderWith(turned, opt, "pyramid"));
        const glm::dvec3 straight = meanB(test::renderWith(plain, opt, "pyramid"));
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(b[c] / expected[c], 1.0, 0.01) << c;
            EXPECT_LT(b[c] / straight[c], 0.95) << c;  // the tilt shows
        }
    }
}

// A metallic-roughness texture: G = g at every texel (R and B, the
// metalness, hold other values: only G is R).
std::shared_ptr<AlbedoTexture> roughnessMap(double g) {
    auto map = std::make_shared<AlbedoTexture>();
    map->name = "roughness";
    map->image = ImageF{2, 2, 3, {}};
    for (int i = 0; i < 4; ++i)
        map->image.pixels.insert(map->image.pixels.end(), {0.9f, float(g), 0.4f});
    return map;
}

// A roughness map (render/surface_atlas.h) sets the lobe's R per texel, as
// its factor × its G: each cube renders as the cube whose material has that
// R, in the lights' lobe and in the environment's reflection (which blends
// the two nearest steps of the prefiltered ladder: exact on a step, within
// the stated bound between steps); --roughness R replaces the maps too.
TEST(Materials, RoughnessMapSetsTheLobePerTexel) {
    Scene files = twoCubes("marble", "marble");
    files.mesh.texcoords = files.mesh.uvs;
    const double onStep[2] = {ladderRoughness(4), ladderRoughness(6)};
    RenderOptions opt = test::smallOptions(96, 256, 64);
    opt.aa = 1;
    for (bool env : {false, true}) {
        SCOPED_TRACE(env ? "a sky as well" : "a light");
        Scene scene = files;
        if (env) scene.env.map = halfSky();
        // The maps: R = 0.5 × G on the left cube, 1 × G on the right.
        auto withMaps = [&](double left, double right) {
            Scene s = scene;
            s.objectMaterials[0].roughness = 0.5;
            s.objectMaterials[0].roughnessMap = roughnessMap(left / 0.5);
            s.objectMaterials[1].roughness = -1;  // no factor: 1
            s.objectMaterials[1].roughnessMap = roughnessMap(right);
            return s;
        };
        auto withoutMaps = [&](double left, double right) {
            Scene s = scene;
            s.objectMaterials[0].roughness = left;
            s.objectMaterials[1].roughness = right;
            return s;
        };
        const FrameResult mapped = test::renderWith(withMaps(onStep[0], onStep[1]), opt, "pyramid");
        const FrameResult plain =
            test::renderWith(withoutMaps(onStep[0], onStep[1]), opt, "pyramid");
        EXPECT_LT(cubeError(mapped, plain, true, true), 1e-5);
        EXPECT_LT(cubeError(mapped, plain, false, true), 1e-5);
        // The factors alone (0.5 and 1) would differ by far more.
        const FrameResult factors = test::renderWith(withoutMaps(0.5, 1.0), opt, "pyramid");
        EXPECT_GT(cubeError(factors, plain, true, true), 0.005);
        EXPECT_GT(cubeError(factors, plain, false, true), 0.005);
        // Between the ladder's steps (0.15: between 0.109 and 0.184; 0.7:
        // between 0.584 and 0.776).
        const double between = std::max(
            cubeError(test::renderWith(withMaps(0.15, 0.7), opt, "pyramid"),
                      test::renderWith(withoutMaps(0.15, 0.7), opt, "pyramid"), true, true),
            cubeError(test::renderWith(withMaps(0.15, 0.7), opt, "pyramid"),
                      test::renderWith(withoutMaps(0.15, 0.7), opt, "pyramid"), false, true));
        std::printf("roughness map between the ladder's steps: %.2e rel. RMSE (%s)\n", between,
                    env ? "sky" : "light");
        EXPECT_LT(between, env ? 8e-3 : 1e-5);
        // --roughness R: every surface's, maps included.
        RenderOptions all = opt;
        all.roughness = 0.3f;
        const FrameResult fixed = test::renderWith(withoutMaps(0.5, 1.0), all, "pyramid");
        const FrameResult over = test::renderWith(withMaps(onStep[0], onStep[1]), all, "pyramid");
        EXPECT_LT(cubeError(over, fixed, true, true), 1e-6);
        EXPECT_LT(cubeError(over, fixed, false, true), 1e-6);
    }
}

// The environment's prefiltered bands are kept per roughness while the map
// stays: a renderer that drew the cubes at R 0.15 / 0.8 and then draws them
// at 0.8 / 0.4 (one band kept, one filtered) draws what a fresh one does.
TEST(Materials, PrefilteredBandsKeptPerRoughness) {
    Scene before = twoCubes("marble", "marble");
    before.env.map = halfSky();
    before.objectMaterials[0].roughness = 0.15;
    before.objectMaterials[1].roughness = 0.8;
    Scene after = before;
    after.objectMaterials[0].roughness = 0.8;
    after.objectMaterials[1].roughness = 0.4;
    RenderOptions opt = test::smallOptions(64, 256, 64);
    opt.method = "pyramid";
    Renderer reused;
    reused.render(before, opt);
    EXPECT_EQ(reused.render(after, opt).rgb8, Renderer().render(after, opt).rgb8);
}

// The roughness atlas holds each texel's own R: a map whose left half is
// 0.2 and right half 0.9 (64 texels across, bilinear: a texel either side
// of the border and of the wrap blends) gives those on each side.
TEST(Materials, RoughnessAtlasFollowsTheMapPerTexel) {
    Scene s = test::planeScene("marble");
    s.mesh.texcoords = s.mesh.uvs;
    ObjectMaterial o = objectMaterial("marble");
    o.roughness = 1.0;
    auto map = std::make_shared<AlbedoTexture>();
    map->name = "halves";
    map->image = ImageF{64, 1, 3, {}};
    for (int x = 0; x < 64; ++x)
        map->image.pixels.insert(map->image.pixels.end(), {0.0f, x < 32 ? 0.2f : 0.9f, 0.0f});
    o.roughnessMap = map;
    s.objectMaterials = {o};
    s.mesh.materialIds.assign(s.mesh.triangles.size(), 0);
    const int res = 256;
    const Media media = findMedia(s.mesh);
    const SurfaceAtlas atlas = bakeSurfaceAtlas(s, media, res, true);
    ASSERT_EQ(atlas.roughness.size(), static_cast<size_t>(res) * res);
    EXPECT_TRUE(atlas.normal.empty());  // no normal map: none baked
    int counted[2] = {0, 0};
    for (int y = 0; y < res; ++y)
        for (int x = 0; x < res; ++x) {
            const float r = atlas.roughness[static_cast<size_t>(y) * res + x];
            if (r == 0) continue;  // no triangle here
            const double u = (x + 0.5) / res;
            if (std::abs(u - 0.5) < 1.0 / 64 || u < 1.0 / 128 || u > 1 - 1.0 / 128) continue;
            EXPECT_NEAR(r, u < 0.5 ? 0.2 : 0.9, 1e-6) << x << " " << y;
            ++counted[u < 0.5 ? 0 : 1];
        }
    EXPECT_GT(counted[0], 1000);
    EXPECT_GT(counted[1], 1000);
    EXPECT_TRUE(bakeSurfaceAtlas(s, media, res, false).empty());  // --roughness R: no map read
}

// The split box of one material whose mean-free-path map (render/mfp_map.h)
// scales the x < 0 half by `left` and the x > 0 half by `right`: a 2×1 map,
// each half's texture coordinates at its texel's centre.
Scene mappedBox(const char* preset, double left, double right) {
    Scene s = splitBox(preset, preset);
    s.mesh.materialIds.assign(s.mesh.triangles.size(), 0);
    s.objectMaterials.resize(1);
    s.mesh.texcoords.assign(s.mesh.positions.size(), glm::vec2(-1.0f));
    for (const glm::uvec3& tri : s.mesh.triangles) {
        const float x =
            s.mesh.positions[tri[0]].x + s.mesh.positions[tri[1]].x + s.mesh.positions[tri[2]].x;
        const glm::vec2 tc(x < 0 ? 0.25f : 0.75f, 0.5f);
        for (int k = 0; k < 3; ++k) {
            // Each quad has its own corners: no corner is on both halves.
            EXPECT_TRUE(s.mesh.texcoords[tri[k]] == glm::vec2(-1.0f) ||
                        s.mesh.texcoords[tri[k]] == tc);
            s.mesh.texcoords[tri[k]] = tc;
        }
    }
    auto map = std::make_shared<AlbedoTexture>();
    map->name = "halves";
    map->image = ImageF{2, 1, 3, {}};
    for (double v : {left, right})
        for (int c = 0; c < 3; ++c) map->image.pixels.push_back(float(v));
    ObjectMaterial& o = s.objectMaterials[0];
    o.mfpSteps = mfpSteps(map->image, map->name, o.medium);
    o.mfpMap = map;
    return s;
}

// The box all of `preset` with its mean free path × `scale` (σ / scale).
Scene scaledBox(const char* preset, double scale) {
    Scene s = splitBox(preset, preset);
    for (ObjectMaterial& o : s.objectMaterials) {
        o.medium.sigmaSPrime /= scale;
        o.medium.sigmaA /= scale;
    }
    return s;
}

// A mean-free-path map scales the mean free path per texel: each half of a
// box whose map halves it on one side and doubles it on the other renders as
// the box all of that half's scale does (each point scatters with its
// texel's step, over the light entering the whole solid, as a solid of two
// materials does), in every method but volumetric (its walk fills the solid
// with the material's own medium).
TEST(Materials, MeanFreePathMapScalesEachTexelsMedium) {
    const Scene mapped = mappedBox("skin1", 0.5, 2.0);
    ASSERT_EQ(mapped.objectMaterials[0].mfpSteps.size(), 8u);
    const Scene half = scaledBox("skin1", 0.5), twice = scaledBox("skin1", 2.0);
    EXPECT_EQ(mapped.objectMaterials[0].mfpSteps.front().medium.sigmaA,
              half.objectMaterials[0].medium.sigmaA);
    expectEachHalfAsItsWhole(mapped, half, twice, 0.05);
}

// The steps: one for a constant map, geometric between the map's extremes at
// most kMfpStepRatio apart (kMaxMfpSteps at most), the albedo kept; each
// texture coordinate takes its nearest step; a texel of 0 is an error.
TEST(Materials, MeanFreePathMapSteps) {
    const Material skin = presetMaterial("skin1");
    auto map = [](const std::vector<float>& values) {
        ImageF m{static_cast<int>(values.size()), 1, 1, values};
        return m;
    };
    const std::vector<MfpStep> one = mfpSteps(map({0.7f, 0.7f}), "constant", skin);
    ASSERT_EQ(one.size(), 1u);
    EXPECT_NEAR(one[0].scale, 0.7, 1e-6);
    const std::vector<MfpStep> three = mfpSteps(map({1.0f, 1.4375f}), "narrow", skin);
    ASSERT_EQ(three.size(), 3u);  // 1.4375 < 1.2²: two ratios of √1.4375
    EXPECT_NEAR(three[1].scale, std::sqrt(1.4375), 1e-6);
    const std::vector<MfpStep> wide = mfpSteps(map({0.1f, 10.0f}), "wide", skin);
    ASSERT_EQ(wide.size(), static_cast<size_t>(kMaxMfpSteps));
    const glm::dvec3 a = albedoOf(skin, ProfileModel::Dipole);
    for (const MfpStep& st : wide) {
        const glm::dvec3 as = albedoOf(st.medium, ProfileModel::Dipole);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(as[c], a[c], 1e-9);
        const glm::dvec3 ratio = meanFreePathOf(st.medium) / meanFreePathOf(skin);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(ratio[c], st.scale, 1e-5 * st.scale);
    }
    ObjectMaterial o;
    o.mfpSteps = wide;
    auto texture = std::make_shared<AlbedoTexture>();
    texture->image = map({0.1f, 10.0f});
    o.mfpMap = texture;
    EXPECT_EQ(mfpStepAt(o, glm::vec2(0.25f, 0.5f)), 0u);
    EXPECT_EQ(mfpStepAt(o, glm::vec2(0.75f, 0.5f)), wide.size() - 1);
    EXPECT_EQ(mfpStepAt(o, glm::vec2(0.5f, 0.5f)), 6u);  // 5.05: the nearest step in log
    try {
        mfpSteps(map({1.0f, 0.0f}), "holes.png", skin);
        ADD_FAILURE() << "a texel of 0 was taken";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(),
                     "mean free path map 'holes.png': texel (1, 0) scales by 0; it must be finite "
                     "and > 0");
    }
}

// Each triangle of one solid reflects with its own material's roughness
// (the media table holds one R per medium, so the surface atlas carries R
// per texel where a medium holds several): each half of a split box of R
// 0.2875 and 0.584 (two of the ladder's steps) renders as the box all of
// that R, under a light and a sky.
TEST(Materials, EachTriangleOfOneSolidReflectsWithItsOwnRoughness) {
    const double r[2] = {ladderRoughness(4), ladderRoughness(6)};
    auto box = [&](double left, double right, bool env) {
        Scene s = splitBox("marble", "marble");
        s.objectMaterials[0].roughness = left;
        s.objectMaterials[1].roughness = right;
        if (env) s.env.map = halfSky();
        return s;
    };
    RenderOptions opt = test::smallOptions(96, 256, 64);
    opt.aa = 1;
    for (bool env : {false, true}) {
        SCOPED_TRACE(env ? "a sky as well" : "a light");
        const FrameResult both = test::renderWith(box(r[0], r[1], env), opt, "pyramid");
        const FrameResult left = test::renderWith(box(r[0], r[0], env), opt, "pyramid");
        const FrameResult right = test::renderWith(box(r[1], r[1], env), opt, "pyramid");
        EXPECT_LT(cubeError(both, left, true, true), 1e-5);
        EXPECT_LT(cubeError(both, right, false, true), 1e-5);
        EXPECT_GT(cubeError(left, right, false, true), 1e-3);  // the R shows
    }
}

// A corrugated sheet y = A sin(2πx/λ) (λ 4 mm, slopes to ±25°, 24 mm
// square), as displaced geometry (`displaced`) or flat (y = 0) with the
// slopes in a normal map (x along the texture's u) or without one.
Scene corrugatedSheet(bool displaced, bool mapped) {
    const double half = 12, lambda = 4, slope = std::tan(25.0 * M_PI / 180.0);
    const double amplitude = slope * lambda / (2 * M_PI);
    const int nx = 240, nz = 24;
    auto height = [&](double x) { return amplitude * std::sin(2 * M_PI * x / lambda); };
    auto slopeAt = [&](double x) { return slope * std::cos(2 * M_PI * x / lambda); };
    Mesh m;
    m.name = "corrugated";
    for (int j = 0; j <= nz; ++j)
        for (int i = 0; i <= nx; ++i) {
            const double x = -half + 2 * half * i / nx, z = -half + 2 * half * j / nz;
            m.positions.emplace_back(x, displaced ? height(x) : 0.0, z);
            m.normals.push_back(displaced ? glm::vec3(glm::normalize(glm::dvec3(-slopeAt(x), 1, 0)))
                                          : glm::vec3(0, 1, 0));
        }
    for (int j = 0; j < nz; ++j)
        for (int i = 0; i < nx; ++i) {
            const unsigned a = j * (nx + 1) + i, b = a + 1, c = a + nx + 1, d = c + 1;
            m.triangles.emplace_back(a, c, b);
            m.triangles.emplace_back(b, c, d);
        }
    AtlasOptions atlas;
    atlas.resolution = 1024;
    atlas.useCache = false;
    Scene s;
    s.mesh = buildAtlas(m, atlas);
    s.material = presetMaterial("marble");
    s.mesh.texcoords.clear();
    for (const glm::vec3& p : s.mesh.positions)
        s.mesh.texcoords.emplace_back((p.x + half) / (2 * half), (p.z + half) / (2 * half));
    if (mapped) {
        ObjectMaterial o = objectMaterial("marble");
        auto map = std::make_shared<AlbedoTexture>();
        map->name = "slopes";
        const int w = 960;  // 160 texels a period
        map->image = ImageF{w, 1, 3, {}};
        for (int k = 0; k < w; ++k) {
            const glm::dvec3 n =
                glm::normalize(glm::dvec3(-slopeAt(-half + 2 * half * (k + 0.5) / w), 0, 1));
            for (int c = 0; c < 3; ++c) map->image.pixels.push_back(float(0.5 * (n[c] + 1)));
        }
        o.normalMap = map;
        s.objectMaterials = {o};
        s.mesh.materialIds.assign(s.mesh.triangles.size(), 0);
    }
    s.lights = {{Light::Type::Directional, glm::normalize(glm::vec3(-1, -1, 0)), glm::vec3(1.0f)}};
    s.camera.eye = glm::vec3(0, 40, 0);
    s.camera.target = glm::vec3(0);
    s.camera.up = glm::vec3(0, 0, -1);
    s.camera.fovYDegrees = 20;  // ±7 mm of the sheet's centre
    return s;
}

// The normal map against the geometry it stands for: a flat sheet whose
// normal map holds a corrugation's slopes renders as the corrugated sheet
// does, far closer than the flat sheet without the map (the map's entry and
// exit cosines, lobe and shading are the geometry's; what it cannot give is
// the geometry's extra area, up to 1/cos 25° = 1.10, and its parallax).
TEST(Materials, NormalMapStandsForDisplacedGeometry) {
    RenderOptions opt = test::smallOptions(128, 1024);
    opt.aa = 1;
    const FrameResult geometry = test::renderWith(corrugatedSheet(true, false), opt, "pyramid");
    const FrameResult mapped = test::renderWith(corrugatedSheet(false, true), opt, "pyramid");
    const FrameResult flat = test::renderWith(corrugatedSheet(false, false), opt, "pyramid");
    auto error = [&](const FrameResult& f, bool radiance) {
        double sum2 = 0, sum = 0;
        size_t n = 0;
        for (int y = 0; y < f.height; ++y)
            for (int x = 0; x < f.width; ++x) {
                if (!(geometry.coverage.at(x, y, 0) > 0.99 && f.coverage.at(x, y, 0) > 0.99))
                    continue;
                for (int c = 0; c < 3; ++c) {
                    const float a = (radiance ? f.radiance : f.radiosity).at(x, y, c);
                    const float b = (radiance ? geometry.radiance : geometry.radiosity).at(x, y, c);
                    sum2 += double(a - b) * (a - b), sum += b, ++n;
                }
            }
        return std::sqrt(sum2 / double(n)) / (sum / double(n));
    };
    const double mappedB = error(mapped, false), flatB = error(flat, false);
    const double mappedL = error(mapped, true), flatL = error(flat, true);
    std::printf(
        "against the displaced geometry, rel. RMSE: normal map B %.4f L %.4f, "
        "flat B %.4f L %.4f\n",
        mappedB, mappedL, flatB, flatL);
    EXPECT_LT(mappedB, 0.3 * flatB);
    EXPECT_LT(mappedL, 0.2 * flatL);
}

}  // namespace
}  // namespace tsis
