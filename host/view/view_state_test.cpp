#include "view/view_state.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <glm/geometric.hpp>

#include "mesh/builtin.h"
#include "render/render_params.h"
#include "util/error.h"

namespace tsis {
namespace {

ViewState twoLights() {
    ViewState s;
    s.sizeMm = s.meshSizeMm = 10;
    s.material = presetMaterial("skin1");
    Light point;
    point.vec = {3, 4, 0};
    point.rgb = glm::vec3(2);
    Light dir;
    dir.type = Light::Type::Directional;
    dir.vec = {0, -1, 0};
    dir.rgb = glm::vec3(0.5f);
    s.lights = {point, dir};
    s.camera.eye = {0, 2, 20};
    s.camera.target = {0, 1, 0};
    s.home = s.camera;
    return s;
}

TEST(ViewState, ResizeScalesCameraAndPointLightsKeepingIrradiance) {
    ViewState s = twoLights();
    resize(s, 30);
    EXPECT_EQ(s.sizeMm, 30);
    EXPECT_EQ(s.camera.eye, glm::vec3(0, 6, 60));
    EXPECT_EQ(s.camera.target, glm::vec3(0, 3, 0));
    EXPECT_EQ(s.home.eye, s.camera.eye);
    EXPECT_EQ(s.lights[0].vec, glm::vec3(9, 12, 0));
    // I/d² at the object's centre stays.
    EXPECT_FLOAT_EQ(s.lights[0].rgb.x / glm::dot(s.lights[0].vec, s.lights[0].vec), 2.0f / 25.0f);
    EXPECT_EQ(s.lights[1].vec, glm::vec3(0, -1, 0));
    EXPECT_EQ(s.lights[1].rgb, glm::vec3(0.5f));
    // The range is render's --size-mm's (kMinSizeMm to kMaxSizeMm).
    EXPECT_THROW(resize(s, 0.5e-3), Error);
    EXPECT_THROW(resize(s, 1.01e5), Error);
    EXPECT_THROW(resize(s, 0), Error);
    EXPECT_EQ(s.sizeMm, 30);
}

TEST(ViewState, ScaledMeshHasTheSizeAsItsDiagonal) {
    ViewState s = twoLights();
    Mesh m = builtinMesh("sphere");
    normalizeMesh(m, 10);
    s.mesh = std::make_shared<Mesh>(m);
    EXPECT_EQ(scaledMesh(s), s.mesh) << "no copy at the prepared size";
    resize(s, 25);
    const std::shared_ptr<const Mesh> big = scaledMesh(s);
    glm::vec3 lo(1e9f), hi(-1e9f);
    for (const glm::vec3& p : big->positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    EXPECT_NEAR(glm::length(hi - lo), 25.0f, 1e-4f);
    EXPECT_EQ(big->uvs, s.mesh->uvs) << "the atlas stays";
}

TEST(ViewState, SetParameterChangesOneThingOrNothing) {
    ViewState s = twoLights();
    setParameter(s, "material", "marble");
    EXPECT_EQ(s.material.name, "marble");
    EXPECT_EQ(s.material.eta, 1.5);
    setParameter(s, "sigma-a", "0.1,0.2,0.3");
    EXPECT_EQ(s.material.sigmaA, glm::dvec3(0.1, 0.2, 0.3));
    EXPECT_EQ(s.material.name, "custom");
    setParameter(s, "method", "tsis");
    setParameter(s, "samples", "64");
    setParameter(s, "atlas-res", "256");
    setParameter(s, "light-res", "0");
    setParameter(s, "progressive", "off");
    setParameter(s, "auto-orbit", "on");
    setParameter(s, "frames", "8");
    setParameter(s, "size-mm", "20");
    setParameter(s, "roughness", "0.5");
    setParameter(s, "exposure", "-2.5");
    EXPECT_EQ(s.options.roughness, 0.5f);
    EXPECT_EQ(s.options.exposure, -2.5f);
    EXPECT_EQ(s.options.method, "tsis");
    EXPECT_EQ(s.options.samples, 64);
    EXPECT_EQ(s.options.atlasResolution, 256);
    EXPECT_FALSE(s.progressive);
    EXPECT_TRUE(s.autoOrbit);
    EXPECT_EQ(s.maxFrames, 8);
    EXPECT_EQ(s.sizeMm, 20);
    const std::pair<const char*, const char*> bad[] = {
        {"material", "unobtainium"}, {"sigma-s", "1,2"}, {"eta", "0.5"},        {"size-mm", "1e6"},
        {"method", "magic"},         {"samples", "0"},   {"atlas-res", "1000"}, {"light-res", "12"},
        {"progressive", "maybe"},    {"frames", "x"},    {"colour", "red"},     {"roughness", "2"},
        {"exposure", "nan"},
    };
    for (const auto& [name, value] : bad) {
        ViewState before = s;
        EXPECT_THROW(setParameter(s, name, value), Error) << name << " " << value;
        EXPECT_TRUE(sameFrame(before, s)) << name;
        EXPECT_EQ(before.material.name, s.material.name) << name;
    }
}

// The viewer's parameters are the tables' rows: each render parameter sets
// from its example and makes another frame exactly when it changes the
// pixels; each scene parameter refuses what the command line refuses.
TEST(ViewState, EveryRenderParameterSetsAndSameFrameFollowsItsEffect) {
    for (const RenderParam& p : renderParams()) {
        const ViewState a = twoLights();
        ViewState b = a;
        ASSERT_NO_THROW(setParameter(b, p.name, p.example)) << p.name;
        EXPECT_EQ(sameFrame(a, b), p.effect == ParamEffect::None) << p.name << " " << p.example;
    }
    for (const auto& [name, value] :
         std::vector<std::pair<std::string, std::string>>{{"env-intensity", "-1"},
                                                          {"env-rotate", "4000"},
                                                          {"size-mm", "file"},
                                                          {"sigma-a", "-1,0,0"},
                                                          {"env", "/nonexistent.hdr"}}) {
        ViewState s = twoLights();
        EXPECT_THROW(setParameter(s, name, value), Error) << name << " " << value;
    }
}

TEST(ViewState, SameSceneAndSameFrame) {
    const ViewState a = twoLights();
    ViewState b = a;
    EXPECT_TRUE(sameFrame(a, b));
    b.options.method = "tsis";
    EXPECT_TRUE(sameScene(a, b)) << "a reference holds for any method";
    EXPECT_FALSE(sameFrame(a, b));
    b = a;
    b.lights[0].vec.x += 1e-3f;
    EXPECT_FALSE(sameScene(a, b));
    b = a;
    b.camera.eye.z += 1e-3f;
    EXPECT_FALSE(sameScene(a, b));
    b = a;
    b.material.sigmaA.x *= 2;
    EXPECT_FALSE(sameScene(a, b));
    b = a;
    b.autoOrbit = true;
    b.options.keepAovs = true;
    EXPECT_TRUE(sameFrame(a, b)) << "switches that do not change the image";
}

}  // namespace
}  // namespace tsis

namespace tsis {
namespace {

// The panel's objects line: each separate solid's material, textured ones
// marked, repeated ones counted; triangles without a file material take the
// scene's.
TEST(ViewState, ObjectsSummaryNamesEachObjectsMaterial) {
    Mesh mesh;
    for (int k = 0; k < 4; ++k) {
        Mesh sphere = builtinSphere();
        const auto base = static_cast<uint32_t>(mesh.positions.size());
        for (const glm::vec3& p : sphere.positions)
            mesh.positions.push_back(p + glm::vec3(3.0f * k, 0, 0));
        for (const glm::uvec3& t : sphere.triangles) {
            mesh.triangles.push_back(t + glm::uvec3(base));
            // Spheres 0 and 1 of material 0, 2 of 1, 3 of none.
            mesh.materialIds.push_back(k < 2 ? 0u : k == 2 ? 1u : kNoFileMaterial);
        }
    }
    ViewState state;
    state.material.name = "skin1";
    auto materials = std::make_shared<std::vector<ObjectMaterial>>(2);
    (*materials)[0].medium.name = "jade";
    (*materials)[1].medium.name = "tile";
    (*materials)[1].texture = std::make_shared<AlbedoTexture>();
    state.objectMaterials = materials;
    EXPECT_EQ(objectsSummary(mesh, state), "4 objects: jade ×2, tile (textured), skin1");
    state.objectMaterials = nullptr;
    EXPECT_EQ(objectsSummary(mesh, state), "4 objects: skin1 ×4");
}

// The panel shows the file's materials' own σ, η and albedo (issue 39: it
// showed skin1's), each material once, and says whether the sliders'
// material is used by any object; over meshes where none, some or all
// objects have a file material.
TEST(ViewState, PanelShowsTheFilesMaterials) {
    auto materials = std::make_shared<std::vector<ObjectMaterial>>(2);
    (*materials)[0].medium = presetMaterial("marble");
    (*materials)[0].medium.name = "stone";
    (*materials)[0].albedo = glm::dvec3(0.8, 0.7, 0.6);
    (*materials)[1].medium = presetMaterial("ketchup");
    (*materials)[1].medium.name = "tile";
    (*materials)[1].texture = std::make_shared<AlbedoTexture>();
    (*materials)[1].textureScale = glm::dvec3(0.5);
    const Material& stone = (*materials)[0].medium;
    char sigma[128];
    std::snprintf(sigma, sizeof sigma, "stone: sigma_s' %.3g %.3g %.3g /mm", stone.sigmaSPrime.x,
                  stone.sigmaSPrime.y, stone.sigmaSPrime.z);
    const std::vector<std::vector<uint32_t>> layouts = {
        {kNoFileMaterial, kNoFileMaterial}, {0, kNoFileMaterial, 0}, {1, 0, 1}, {0, 0}};
    for (const std::vector<uint32_t>& ids : layouts) {
        Mesh mesh;
        for (size_t k = 0; k < ids.size(); ++k) {
            Mesh sphere = builtinSphere();
            const auto base = static_cast<uint32_t>(mesh.positions.size());
            for (const glm::vec3& p : sphere.positions)
                mesh.positions.push_back(p + glm::vec3(3.0f * k, 0, 0));
            for (const glm::uvec3& t : sphere.triangles) {
                mesh.triangles.push_back(t + glm::uvec3(base));
                mesh.materialIds.push_back(ids[k]);
            }
        }
        ViewState state;
        state.material = presetMaterial("skin1");
        state.objectMaterials = materials;
        const FileMaterialLines f = fileMaterialLines(mesh, state);
        const bool none = std::count(ids.begin(), ids.end(), kNoFileMaterial) == int(ids.size());
        EXPECT_EQ(f.sceneMaterialUsed,
                  std::find(ids.begin(), ids.end(), kNoFileMaterial) != ids.end());
        std::vector<uint32_t> distinct;
        for (uint32_t id : ids)
            if (id != kNoFileMaterial &&
                std::find(distinct.begin(), distinct.end(), id) == distinct.end())
                distinct.push_back(id);
        ASSERT_EQ(f.lines.size(), distinct.size());
        EXPECT_EQ(none, f.lines.empty());
        for (size_t i = 0; i < distinct.size(); ++i) {
            const std::string& line = f.lines[i];
            EXPECT_EQ(line.find("skin1"), std::string::npos) << line;
            if (distinct[i] == 0) {
                EXPECT_EQ(line.rfind(sigma, 0), 0u) << line;
                EXPECT_NE(line.find("albedo 0.8 0.7 0.6"), std::string::npos) << line;
            } else {
                EXPECT_EQ(line.rfind("tile: ", 0), 0u) << line;
                EXPECT_NE(line.find("albedo: texture x 0.5 0.5 0.5"), std::string::npos) << line;
            }
        }
    }
}

}  // namespace
}  // namespace tsis
