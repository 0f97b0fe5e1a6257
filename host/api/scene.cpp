#include "tsis/scene.h"

#include "api/api_internal.h"
#include "cli/args.h"
#include "cli/scene_options.h"
#include "mesh/repair.h"
#include "physics/material.h"

namespace tsis::api {

namespace {

Args sceneArgsOf(const Options& options) {
    return Args("render", sceneOptionSpecs(), options.args());
}

// Throws the CLI's error for whatever in `scene` its options could not say:
// the scene is written as options and parsed back.
void checkScene(const tsis::Scene& scene, double sizeMm) {
    parseScene(Args("render", sceneOptionSpecs(), sceneArgs(scene, "builtin:default", sizeMm)));
}

tsis::Material toInternal(const Material& m) {
    tsis::Material t;
    t.name = m.name;
    t.sigmaSPrime = glm::dvec3(toGlm(m.sigmaSPrime));
    t.sigmaA = glm::dvec3(toGlm(m.sigmaA));
    t.eta = m.eta;
    return t;
}

Material fromInternal(const tsis::Material& m) {
    return {m.name, toVec3(m.sigmaSPrime), toVec3(m.sigmaA), static_cast<float>(m.eta)};
}

}  // namespace

Material presetMaterial(const std::string& name) {
    return fromInternal(tsis::presetMaterial(name));
}

std::vector<std::string> presetMaterialNames() {
    std::vector<std::string> names;
    for (const tsis::Material& m : presetMaterials()) names.push_back(m.name);
    return names;
}

Scene::Scene(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

Scene::Scene(const Options& options) : impl_(std::make_unique<Impl>()) {
    const Args args = sceneArgsOf(options);
    impl_->scene = guarded([&] { return sceneFromArgs(args); });
    impl_->sizeMm = impl_->scene.sizeMm;  // --size-mm S, or the file's own
}

Scene Scene::fromArrays(const std::vector<float>& vertices, const std::vector<uint32_t>& triangles,
                        const Options& options, const std::string& name) {
    if (vertices.size() % 3 || triangles.size() % 3)
        fail("mesh '", name, "': ", vertices.size(), " vertex coordinates and ", triangles.size(),
             " triangle indices: each must be a multiple of 3");
    const Args args = sceneArgsOf(options);
    Scene s(std::make_unique<Impl>());
    s.impl_->scene = parseScene(args);
    s.impl_->sizeMm = sizeMmFromArgs(args);
    Mesh mesh;
    mesh.name = name.empty() ? "arrays" : name;  // its notes name it
    for (size_t i = 0; i < vertices.size(); i += 3)
        mesh.positions.emplace_back(vertices[i], vertices[i + 1], vertices[i + 2]);
    for (size_t i = 0; i < triangles.size(); i += 3)
        mesh.triangles.emplace_back(triangles[i], triangles[i + 1], triangles[i + 2]);
    // What a loader does (repair), then what `tsis render` does with a loaded mesh.
    repairMesh(mesh);
    s.impl_->scene.mesh =
        prepareLoadedMesh(std::move(mesh), s.impl_->sizeMm, meshOptionsFromArgs(args));
    return s;
}

Scene::Scene(const Scene& other) : impl_(std::make_unique<Impl>(*other.impl_)) {}
Scene::Scene(Scene&& other) noexcept = default;
Scene& Scene::operator=(const Scene& other) {
    *impl_ = *other.impl_;
    return *this;
}
Scene& Scene::operator=(Scene&& other) noexcept = default;
Scene::~Scene() = default;

Material Scene::material() const {
    return fromInternal(impl_->scene.material);
}

void Scene::setMaterial(const Material& material) {
    tsis::Scene next = impl_->scene;
    next.material = toInternal(material);
    checkScene(next, impl_->sizeMm);
    impl_->scene.material = next.material;
}

std::vector<Light> Scene::lights() const {
    std::vector<Light> out;
    for (const tsis::Light& l : impl_->scene.lights)
        if (!l.environment)  // an --env map's sun is the map's, not a light to set
            out.push_back({l.type == tsis::Light::Type::Directional, toVec3(l.vec), toVec3(l.rgb)});
    return out;
}

void Scene::setLights(const std::vector<Light>& lights) {
    tsis::Scene next = impl_->scene;
    next.lights.clear();
    for (const Light& l : lights) {
        tsis::Light t;
        t.type = l.directional ? tsis::Light::Type::Directional : tsis::Light::Type::Point;
        t.vec = toGlm(l.vec);
        t.rgb = toGlm(l.rgb);
        next.lights.push_back(t);
    }
    applyEnvironment(next);  // the --env map's sun stays
    checkScene(next, impl_->sizeMm);
    impl_->scene.lights = next.lights;
}

Camera Scene::camera() const {
    const tsis::Camera& c = impl_->scene.camera;
    return {toVec3(c.eye), toVec3(c.target), toVec3(c.up), c.fovYDegrees};
}

void Scene::setCamera(const Camera& camera) {
    tsis::Scene next = impl_->scene;
    next.camera = {toGlm(camera.eye), toGlm(camera.target), toGlm(camera.up), camera.fovYDegrees};
    checkScene(next, impl_->sizeMm);
    impl_->scene.camera = next.camera;
}

std::string Scene::meshName() const {
    return impl_->scene.mesh.name;
}
size_t Scene::vertexCount() const {
    return impl_->scene.mesh.positions.size();
}
size_t Scene::triangleCount() const {
    return impl_->scene.mesh.triangles.size();
}

}  // namespace tsis::api
