#include "cli/scene_options.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <sstream>

#include "atlas/atlas.h"
#include "mesh/mesh_io.h"
#include "mesh/uv_check.h"
#include "physics/material.h"
#include "render/method.h"
#include "render/render_params.h"
#include "scene/from_file.h"
#include "util/error.h"

namespace tsis {

namespace {

// " (default V)" with V as the user types it.
template <typename T>
std::string byDefault(const T& value) {
    std::ostringstream s;
    s << " (default " << value << ")";
    return s.str();
}

}  // namespace

const std::vector<OptionSpec>& sceneOptionSpecs() {
    static const std::vector<OptionSpec> specs = [] {
        const SceneDefaults sd;
        std::vector<OptionSpec> specs = {
            {"mesh", true, false,
             "M  mesh file (.off/.obj/.ply/.stl/.gltf/.glb), builtin:NAME or a data mesh name" +
                 byDefault(sd.mesh)},
            {"size-mm", true, false, "S  bounding-box diagonal in mm" + byDefault(sd.sizeMm)},
            {"material", true, false,
             "NAME  preset material (see tsis materials)" + byDefault(sd.material)},
            {"sigma-s", true, false,
             "R,G,B  reduced scattering σs' in 1/mm (overrides the preset)"},
            {"sigma-a", true, false, "R,G,B  absorption σa in 1/mm (overrides the preset)"},
            {"eta", true, false, "E  relative index of refraction (overrides the preset)"},
            {"light", true, true,
             "SPEC  point:X,Y,Z:R,G,B (intensity) or dir:X,Y,Z:R,G,B (direction of travel, "
             "irradiance); repeatable"},
            {"eye", true, false, "X,Y,Z  camera position in mm (default: framed from the front)"},
            {"target", true, false, "X,Y,Z  camera target (default 0,0,0)"},
            {"up", true, false, "X,Y,Z  camera up (default 0,1,0)"},
            {"fov", true, false, "DEG  vertical field of view" + byDefault(sd.fovDegrees)},
            {"camera", true, false,
             "N  the mesh file's camera N, from 0 (glTF; default: its first, when --eye, "
             "--target and --up are not given)"},
            {"atlas", true, false,
             "MODE  auto (the mesh's UVs when valid, else build), file (require valid UVs) or "
             "build" +
                 byDefault(sd.atlasMode)},
            {"cl-device", true, false,
             "SUBSTR  OpenCL device (default: $TSIS_CL_DEVICE, else PoCL)"},
        };
        std::string methods;
        for (const std::string& m : methodNames()) methods += (methods.empty() ? "" : ", ") + m;
        specs.push_back({"method", true, false,
                         "NAME  " + methods + "; see README" + byDefault(RenderOptions().method)});
        for (const RenderParam& p : renderParams())
            specs.push_back({p.name, !p.flag, false, p.usage()});
        return specs;
    }();
    return specs;
}

double sizeMmFromArgs(const Args& args) {
    return args.getDouble("size-mm", SceneDefaults().sizeMm, 1e-3, 1e5);
}

Material materialFromArgs(const Args& args) {
    Material m = presetMaterial(args.getString("material", SceneDefaults().material));
    bool custom = false;
    if (auto v = args.value("sigma-s")) {
        m.sigmaSPrime = parseVec3("--sigma-s", *v);
        custom = true;
    }
    if (auto v = args.value("sigma-a")) {
        m.sigmaA = parseVec3("--sigma-a", *v);
        custom = true;
    }
    if (auto v = args.value("eta")) {
        m.eta = parseNumber("--eta", *v);
        custom = true;
    }
    if (custom) m.name = "custom";
    validateMaterial(m);
    return m;
}

Light parseLight(const std::string& spec) {
    auto c1 = spec.find(':');
    auto c2 = c1 == std::string::npos ? c1 : spec.find(':', c1 + 1);
    if (c2 == std::string::npos)
        fail("--light '", spec, "': expected point:X,Y,Z:R,G,B or dir:X,Y,Z:R,G,B");
    std::string kind = spec.substr(0, c1);
    Light l;
    if (kind == "point")
        l.type = Light::Type::Point;
    else if (kind == "dir")
        l.type = Light::Type::Directional;
    else
        fail("--light '", spec, "': unknown kind '", kind, "' (point or dir)");
    l.vec = glm::vec3(parseVec3("--light position/direction", spec.substr(c1 + 1, c2 - c1 - 1)));
    l.rgb = glm::vec3(parseVec3("--light colour", spec.substr(c2 + 1)));
    if (l.rgb.x < 0 || l.rgb.y < 0 || l.rgb.z < 0) fail("--light '", spec, "': negative intensity");
    if (l.type == Light::Type::Directional && glm::length(l.vec) == 0.0f)
        fail("--light '", spec, "': zero direction");
    return l;
}

std::vector<Light> defaultLights(double sizeMm) {
    const float s = static_cast<float>(sizeMm);
    Light back;
    back.type = Light::Type::Point;
    back.vec = glm::vec3(-0.45f, 0.75f, -1.0f) * (1.3f * s);
    // Intensity so that the irradiance at the object's centre is about 1.
    back.rgb = glm::vec3(glm::dot(back.vec, back.vec));
    Light fill;
    fill.type = Light::Type::Directional;
    fill.vec = glm::vec3(0.6f, -0.4f, -1.0f);
    fill.rgb = glm::vec3(0.12f);
    return {back, fill};
}

Camera defaultCamera(double sizeMm, float fovYDegrees) {
    Camera c;
    c.fovYDegrees = fovYDegrees;
    float halfFov = glm::radians(fovYDegrees) * 0.5f;
    float dist = 0.5f * static_cast<float>(sizeMm) / std::sin(halfFov) * 1.05f;
    c.eye = glm::normalize(glm::vec3(0.0f, 0.35f, 1.0f)) * dist;
    return c;
}

std::string atlasMode(const Args& args) {
    std::string mode = args.getString("atlas", SceneDefaults().atlasMode);
    if (mode != "auto" && mode != "file" && mode != "build")
        fail("--atlas '", mode, "': expected auto, file or build");
    return mode;
}

AtlasOptions atlasOptionsFromArgs(const Args& args) {
    RenderOptions r;
    if (auto v = args.value("atlas-res")) findRenderParam("atlas-res")->set(r, *v);
    AtlasOptions o;
    o.resolution = r.atlasResolution;
    return o;
}

Scene parseScene(const Args& args) {
    Scene scene;
    const double size = sizeMmFromArgs(args);
    scene.material = materialFromArgs(args);
    atlasMode(args);
    atlasOptionsFromArgs(args);
    for (const std::string& l : args.values("light")) scene.lights.push_back(parseLight(l));
    if (static_cast<int>(scene.lights.size()) > kMaxLights)
        fail("too many lights: ", scene.lights.size(), " (at most ", kMaxLights, ")");
    if (scene.lights.empty()) scene.lights = defaultLights(size);
    float fov = static_cast<float>(args.getDouble("fov", SceneDefaults().fovDegrees, 1.0, 170.0));
    scene.camera = defaultCamera(size, fov);
    if (auto v = args.value("eye")) scene.camera.eye = glm::vec3(parseVec3("--eye", *v));
    if (auto v = args.value("target")) scene.camera.target = glm::vec3(parseVec3("--target", *v));
    if (auto v = args.value("up")) scene.camera.up = glm::vec3(parseVec3("--up", *v));
    if (args.has("camera") && (args.has("eye") || args.has("target") || args.has("up")))
        fail("--camera picks the mesh file's camera: not with --eye, --target or --up");
    args.getInt("camera", 0, 0, 1 << 20);
    glm::vec3 forward = scene.camera.target - scene.camera.eye;
    if (glm::length(forward) == 0.0f) fail("--eye and --target are the same point");
    if (glm::length(glm::cross(forward, scene.camera.up)) < 1e-6f * glm::length(forward))
        fail("--up is parallel to the view direction (or zero)");
    return scene;
}

namespace {

// The mesh at sizeMm; with `view`, its file's cameras and lights moved with it.
Mesh loadNormalized(const std::string& spec, double sizeMm, FileView* view) {
    Mesh mesh = loadMesh(spec, view);
    const Normalization n = normalizeMesh(mesh, sizeMm);
    if (view) normalizeView(*view, n);
    return mesh;
}

Mesh withAtlas(Mesh mesh, const std::string& atlasMode, const AtlasOptions& atlasOptions) {
    ensureNormals(mesh);
    return ensureAtlas(mesh, atlasMode, atlasOptions);
}

}  // namespace

Mesh prepareMesh(const std::string& spec, double sizeMm, const std::string& atlasMode,
                 const AtlasOptions& atlasOptions) {
    return withAtlas(loadNormalized(spec, sizeMm, nullptr), atlasMode, atlasOptions);
}

void loadSceneMesh(Scene& scene, const Args& args) {
    const double size = sizeMmFromArgs(args);
    FileView view;
    Mesh mesh = loadNormalized(args.getString("mesh", SceneDefaults().mesh), size, &view);
    // The command line's camera and lights win, per kind. Before the atlas: a
    // wrong --camera costs no waiting.
    FileViewUse use;
    use.camera = !args.has("eye") && !args.has("target") && !args.has("up");
    if (args.has("camera")) use.cameraIndex = args.getInt("camera", 0, 0, 1 << 20);
    use.fov = !args.has("fov");
    use.lights = !args.has("light");
    useFileView(scene, view, use, size, mesh.name);
    scene.mesh = withAtlas(std::move(mesh), atlasMode(args), atlasOptionsFromArgs(args));
}

Scene sceneFromArgs(const Args& args) {
    Scene scene = parseScene(args);
    loadSceneMesh(scene, args);
    return scene;
}

RenderOptions renderOptionsFromArgs(const Args& args) {
    RenderOptions o;
    o.method = args.getString("method", o.method);
    validateRenderOptions(o);  // the method's name first
    for (const RenderParam& p : renderParams()) {
        if (!args.has(p.name)) continue;
        if (const std::string foreign = foreignParamMessage(p, o.method); !foreign.empty())
            fail(foreign);
        p.set(o, p.flag ? "1" : *args.value(p.name));
    }
    return o;
}

namespace {

template <typename V>
std::string exact3(const V& v) {
    return exactText(v.x) + "," + exactText(v.y) + "," + exactText(v.z);
}

}  // namespace

std::vector<std::string> sceneArgs(const Scene& scene, const std::string& meshSpec, double sizeMm) {
    std::vector<std::string> a = {"--mesh", meshSpec, "--size-mm", exactText(sizeMm)};
    const Material& m = scene.material;
    for (const Material& p : presetMaterials())
        if (p.name == m.name) a.insert(a.end(), {"--material", m.name});
    a.insert(a.end(), {"--sigma-s", exact3(m.sigmaSPrime), "--sigma-a", exact3(m.sigmaA), "--eta",
                       exactText(m.eta)});
    for (const Light& l : scene.lights)
        a.insert(a.end(),
                 {"--light", std::string(l.type == Light::Type::Point ? "point:" : "dir:") +
                                 exact3(l.vec) + ":" + exact3(l.rgb)});
    const Camera& c = scene.camera;
    a.insert(a.end(), {"--eye", exact3(c.eye), "--target", exact3(c.target), "--up", exact3(c.up),
                       "--fov", exactText(c.fovYDegrees)});
    return a;
}

std::vector<std::string> renderOptionArgs(const RenderOptions& o) {
    std::vector<std::string> a = {"--method", o.method};
    // The method's own parameters and the frame-wide ones, where not the default.
    for (const RenderParam& p : renderParams()) {
        if (!p.usedBy(o.method) || p.isDefault(o)) continue;
        a.push_back("--" + p.name);
        if (!p.flag) a.push_back(p.text(o));
    }
    return a;
}

}  // namespace tsis
