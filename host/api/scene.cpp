#include "tsis/scene.h"

#include "api/api_internal.h"
#include "description/mesh_preparation.h"
#include "description/scene_params.h"
#include "mesh/repair.h"
#include "physics/material.h"
#include "render/albedo_inversion.h"
#include "render/render_params.h"
#include "scene/environment.h"
#include "util/args.h"
#include "util/input_file.h"
#include "util/note.h"

namespace tsis::api {

namespace {

// The description the scene options among `options` give; a render option
// is an error (Scene does nothing with it), and so is --mesh where `maker`
// (fromArrays, fromObjects) has the mesh already.
SceneDescription describe(const Options& options, const char* maker = nullptr) {
    const Args args("render", sceneOptionSpecs(), options.args());
    for (const OptionSpec& s : sceneOptionSpecs()) {
        if (!args.has(s.name) || findSceneParam(s.name) || s.name == "atlas-res") continue;
        if (s.name == "cl-device" || s.name == "gl")
            fail("Scene: option --", s.name, " is the Renderer's: give it when making one");
        fail("Scene: option --", s.name, " is not the scene's: give it to Renderer::render");
    }
    if (maker && args.has("mesh"))
        fail("Scene::", maker, ": option --mesh: the ",
             maker == std::string("fromArrays") ? "arrays" : "objects", " are the mesh");
    return sceneDescriptionFromArgs(args);
}

// A mesh from arrays as a loader gives one (repaired), named `name`.
Mesh meshOfArrays(const std::vector<float>& vertices, const std::vector<uint32_t>& triangles,
                  const std::string& name) {
    if (vertices.size() % 3 || triangles.size() % 3)
        fail("mesh '", name, "': ", vertices.size(), " vertex coordinates and ", triangles.size(),
             " triangle indices: each must be a multiple of 3");
    Mesh mesh;
    mesh.name = name;
    for (size_t i = 0; i < vertices.size(); i += 3)
        mesh.positions.emplace_back(vertices[i], vertices[i + 1], vertices[i + 2]);
    for (size_t i = 0; i < triangles.size(); i += 3)
        mesh.triangles.emplace_back(triangles[i], triangles[i + 1], triangles[i + 2]);
    repairMesh(mesh);
    return mesh;
}

Material fromInternal(const tsis::Material& m) {
    Material out;
    out.name = m.name;
    out.sigmaSPrime = toVec3(m.sigmaSPrime);
    out.sigmaA = toVec3(m.sigmaA);
    out.eta = static_cast<float>(m.eta);
    return out;
}

// How a Material is said as options: its albedo and mean free path when it
// has them, else its σ and η (with its preset's name when it is one).
MaterialDescription describe(const Material& m) {
    if (m.albedo.has_value() != m.mfpMm.has_value())
        fail("Material: albedo and mfp_mm go together (or neither: σs' and σa)");
    MaterialDescription d;
    d.eta = m.eta;
    if (m.albedo) {
        d.albedo = glm::dvec3(toGlm(*m.albedo));
        d.mfpMm = glm::dvec3(toGlm(*m.mfpMm));
        return d;
    }
    for (const tsis::Material& p : presetMaterials()) {
        if (p.name != m.name) continue;
        d.preset = m.name;
        // The preset as it is: said by name alone, so that it reads back so.
        const Material same = fromInternal(p);
        if (same.sigmaSPrime == m.sigmaSPrime && same.sigmaA == m.sigmaA) {
            if (same.eta == m.eta) d.eta.reset();
            return d;
        }
    }
    d.sigmaSPrime = glm::dvec3(toGlm(m.sigmaSPrime));
    d.sigmaA = glm::dvec3(toGlm(m.sigmaA));
    return d;
}

// The material `d` gives as the API shows it.
Material shown(const MaterialDescription& d, const tsis::Material& resolved) {
    Material m = fromInternal(resolved);
    if (d.albedo && d.mfpMm) {
        m.albedo = toVec3(*d.albedo);
        m.mfpMm = toVec3(*d.mfpMm);
    }
    return m;
}

// Scene::Impl's scene made again from its description, the mesh kept:
// throws the description's error and leaves `impl` as it was. With
// `newMaterial` the description's material replaces every object's and file's.
void replace(Scene::Impl& impl, const SceneDescription& next, bool newMaterial = false) {
    tsis::Scene& s = impl.scene;
    // Placed by the size the mesh has (the file's own, once loaded).
    SceneDescription placing = next;
    if (placing.mesh.sizeFromFile) {
        placing.mesh.sizeFromFile = false;
        placing.mesh.units.reset();
        placing.mesh.sizeMm = s.sizeMm;
    }
    tsis::Scene placed = placedScene(placing, impl.profile);
    placed.mesh = std::move(s.mesh);
    placed.sizeMm = s.sizeMm;
    if (!newMaterial) placed.objectMaterials = std::move(s.objectMaterials);
    s = std::move(placed);
    impl.description = next;
    if (newMaterial) impl.fileMaterials.materials.clear();  // until the scene is made again
}

// `d` with the lights (unless an environment lights alone) and camera the
// scene has now, a file's included, so that a change of something else keeps them.
SceneDescription pinned(const Scene::Impl& impl, SceneDescription d) {
    if (d.lights.empty() && !d.env)
        for (const tsis::Light& l : impl.scene.lights)
            if (!l.environment) d.lights.push_back(l);
    const tsis::Camera& c = impl.scene.camera;
    d.camera = {c.eye, c.target, c.up, c.fovYDegrees, std::nullopt};
    return d;
}

}  // namespace

std::optional<tsis::Scene> Scene::Impl::withProfile(ProfileModel p) const {
    // What a profile inverts: albedo + mfp given, and a file's materials
    // (their albedo with a mean free path).
    if (p == profile || (!description.material.mfpMm && fileMaterials.materials.empty()))
        return std::nullopt;
    tsis::Scene s = scene;
    const NoteCapture quiet;  // said once, when the scene was made
    s.material = resolveMaterial(description.material, p);
    // Objects keep their own materials; the description's fills the rest.
    const MaterialOverrides over =
        description.objects.empty() ? overridesOf(description.material) : MaterialOverrides{};
    if (!over.replaceAll)
        s.objectMaterials = objectMaterials(fileMaterials.materials, s.material, over, p,
                                            fileMaterials.mmPerFileUnit, fileMaterials.meshName);
    return s;
}

Material Material::preset(const std::string& name) {
    return fromInternal(tsis::presetMaterial(name));
}

Material Material::fromAlbedo(const Vec3& albedo, const Vec3& mfpMm, float eta) {
    Material m;
    m.albedo = albedo;
    m.mfpMm = mfpMm;
    m.eta = eta;
    // σ as the default profile inverts it (the renderer's own does it again).
    const tsis::Material t = resolveMaterial(describe(m), RenderOptions().profile);
    m.sigmaSPrime = toVec3(t.sigmaSPrime);
    m.sigmaA = toVec3(t.sigmaA);
    return m;
}

Material presetMaterial(const std::string& name) {
    return Material::preset(name);
}

std::vector<std::string> presetMaterialNames() {
    std::vector<std::string> names;
    for (const tsis::Material& m : presetMaterials()) names.push_back(m.name);
    return names;
}

Scene::Scene(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

Scene::Scene(const Options& options) : impl_(std::make_unique<Impl>()) {
    impl_->description = describe(options);
    const NoteCapture notes;
    impl_->scene = guarded(
        [&] { return buildScene(impl_->description, impl_->profile, &impl_->fileMaterials); });
    impl_->notes = notes.notes();
}

Scene load(const std::string& path, const Options& options) {
    Options o = options;
    o.set("mesh", path);
    return Scene(o);
}

Scene Scene::fromArrays(const std::vector<float>& vertices, const std::vector<uint32_t>& triangles,
                        const Options& options, const std::string& name) {
    Scene s(std::make_unique<Impl>());
    Impl& impl = *s.impl_;
    impl.arraysName = name.empty() ? "arrays" : name;  // its notes name it
    Mesh mesh = meshOfArrays(vertices, triangles, impl.arraysName);
    impl.description = describe(options, "fromArrays");
    impl.vertices = vertices;
    impl.triangles = triangles;
    if (impl.description.mesh.sizeFromFile)
        fail("--size-mm file: arrays have no size of their own");
    const NoteCapture notes;
    impl.scene = placedScene(impl.description, impl.profile);
    // What `tsis render` does with a loaded mesh.
    setOutsideAssetsAllowed(impl.description.mesh.allowOutsideAssets);
    impl.scene.mesh = prepareLoadedMesh(std::move(mesh), nominalSizeMm(impl.description.mesh),
                                        meshOptionsOf(impl.description.mesh));
    impl.notes = notes.notes();
    return s;
}

Scene Scene::fromObjects(const std::vector<Object>& objects, const Options& options) {
    Scene s(std::make_unique<Impl>());
    Impl& impl = *s.impl_;
    if (objects.empty()) fail("Scene::fromObjects: a scene of objects needs at least one object");
    impl.description = describe(options, "fromObjects");
    for (size_t i = 0; i < objects.size(); ++i) {
        const Object& o = objects[i];
        ObjectDescription d;
        d.spec = o.mesh;
        if (o.mesh.empty())
            d.arrays = std::make_shared<const Mesh>(
                meshOfArrays(o.vertices, o.triangles, "object " + std::to_string(i)));
        else if (!o.vertices.empty() || !o.triangles.empty())
            fail("object ", i, ": a mesh file and arrays: give one");
        d.scale = o.transform.scale;
        d.rotateDegrees = glm::dvec3(toGlm(o.transform.rotateDegrees));
        d.translateMm = glm::dvec3(toGlm(o.transform.translateMm));
        if (o.material) {
            d.material = describe(*o.material);
            d.albedoTexture = o.material->albedoTexture;
        }
        impl.description.objects.push_back(std::move(d));
    }
    impl.objects = objects;
    const NoteCapture notes;
    impl.scene =
        guarded([&] { return buildScene(impl.description, impl.profile, &impl.fileMaterials); });
    impl.notes = notes.notes();
    return s;
}

const std::vector<Object>& Scene::objects() const {
    return impl_->objects;
}

Scene::Scene(const Scene& other) : impl_(std::make_unique<Impl>(*other.impl_)) {}
Scene::Scene(Scene&& other) noexcept = default;
Scene& Scene::operator=(const Scene& other) {
    *impl_ = *other.impl_;
    return *this;
}
Scene& Scene::operator=(Scene&& other) noexcept = default;
Scene::~Scene() = default;

std::optional<Material> Scene::material() const {
    const MaterialDescription& d = impl_->description.material;
    if (!impl_->scene.objectMaterials.empty()) return std::nullopt;
    return shown(d, impl_->scene.material);
}

void Scene::setMaterial(const Material& material) {
    SceneDescription next = pinned(*impl_, impl_->description);
    next.material = describe(material);
    for (ObjectDescription& o : next.objects) o.material = next.material;
    replace(*impl_, next, true);
    for (Object& o : impl_->objects) o.material = material;
}

std::vector<Material> Scene::materials() const {
    const tsis::Scene& s = impl_->scene;
    if (s.objectMaterials.empty()) return {*material()};
    std::vector<Material> out;
    for (size_t i = 0; i < s.objectMaterials.size(); ++i) {
        const ObjectMaterial& o = s.objectMaterials[i];
        Material m = fromInternal(o.medium);
        if (i < impl_->fileMaterials.materials.size())
            m.name = impl_->fileMaterials.materials[i].name;
        m.albedo = toVec3(o.albedo);
        if (o.texture) m.albedoTexture = o.texture->name;
        out.push_back(m);
    }
    return out;
}

std::vector<Light> Scene::lights() const {
    std::vector<Light> out;
    for (const tsis::Light& l : impl_->scene.lights)
        if (!l.environment)  // an environment's sun is the map's, not a light to set
            out.push_back({l.type == tsis::Light::Type::Directional, toVec3(l.vec), toVec3(l.rgb)});
    return out;
}

void Scene::setLights(const std::vector<Light>& lights) {
    SceneDescription next = pinned(*impl_, impl_->description);
    next.lights.clear();
    for (const Light& l : lights) {
        tsis::Light t;
        t.type = l.directional ? tsis::Light::Type::Directional : tsis::Light::Type::Point;
        t.vec = toGlm(l.vec);
        t.rgb = toGlm(l.rgb);
        next.lights.push_back(parseLight(lightText(t)));  // checked as --light is
    }
    if (lights.empty())  // none given: the defaults for the object's size
        next.lights = defaultLights(impl_->scene.sizeMm);
    replace(*impl_, next);
}

std::optional<Environment> Scene::environment() const {
    const auto& e = impl_->description.env;
    if (!e) return std::nullopt;
    if (impl_->environment) return impl_->environment;  // with its pixels
    Environment out;
    out.path = e->path;
    out.intensity = e->intensity.value_or(1.0);
    out.rotateDegrees = e->rotateDegrees.value_or(0.0);
    return out;
}

void Scene::setEnvironment(const std::optional<Environment>& environment) {
    // The lights given stay; the file's or the defaults give way to the map
    // (it lights alone), and come back as the defaults without one.
    SceneDescription next = impl_->description;
    next.camera = pinned(*impl_, next).camera;
    next.env.reset();
    const NoteCapture notes;
    if (environment) {
        const Environment& e = *environment;
        if (e.path.empty() && e.pixels.empty())
            fail("Environment: no file and no pixels (path is empty)");
        Options check;  // each value as the CLI checks --env-intensity and --env-rotate
        check.set("env-intensity", e.intensity).set("env-rotate", e.rotateDegrees);
        next.env = EnvironmentDescription{e.path.empty() ? "pixels" : e.path, e.intensity,
                                          e.rotateDegrees, nullptr};
        if (!e.pixels.empty()) {
            if (e.width < 1 || e.height < 1 ||
                e.pixels.size() != static_cast<size_t>(e.width) * e.height * 3)
                fail("Environment: ", e.pixels.size(), " values for ", e.width, "×", e.height,
                     " RGB pixels");
            next.env->map = splitEnvironment(next.env->path, e.width, e.height, 3, e.pixels);
        }
    }
    replace(*impl_, next);
    impl_->environment.reset();
    if (environment && !environment->pixels.empty()) impl_->environment = environment;
    for (const std::string& n : notes.notes()) impl_->notes.push_back(n);
}

Camera Scene::camera() const {
    const tsis::Camera& c = impl_->scene.camera;
    return {toVec3(c.eye), toVec3(c.target), toVec3(c.up), c.fovYDegrees};
}

void Scene::setCamera(const Camera& camera) {
    SceneDescription next = pinned(*impl_, impl_->description);
    if (!(camera.fovYDegrees >= 1 && camera.fovYDegrees <= 170))
        fail("--fov ", camera.fovYDegrees, " is out of range [1, 170]");
    next.camera = {toGlm(camera.eye), toGlm(camera.target), toGlm(camera.up), camera.fovYDegrees,
                   std::nullopt};
    replace(*impl_, next);
}

Options Scene::options() const {
    SceneDescription d = impl_->description;
    // The lights and camera as the scene has them (a file's included).
    d.lights.clear();
    for (const tsis::Light& l : impl_->scene.lights)
        if (!l.environment) d.lights.push_back(l);
    const tsis::Camera& c = impl_->scene.camera;
    d.camera = {c.eye, c.target, c.up, c.fovYDegrees, std::nullopt};
    if (d.mesh.sizeFromFile) {
        d.mesh.sizeFromFile = false;
        d.mesh.units.reset();
        d.mesh.sizeMm = impl_->scene.sizeMm;
    }
    if (d.fileLightUnits && d.env)  // the map's scale as used (W/(m²·sr) → W/(mm²·sr))
        d.env->intensity = impl_->scene.env.intensity;
    if (impl_->environment) d.env.reset();  // pixels: environment() has them
    d.fileLightUnits = false;
    return optionsOfArgs(descriptionArgs(d));
}

const std::vector<std::string>& Scene::notes() const {
    return impl_->notes;
}

RenderSettings Scene::renderSettings() const {
    RenderSettings settings;
    if (impl_->description.fileLightUnits) settings.exposure = kFileLightUnitsExposure;
    return settings;
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
