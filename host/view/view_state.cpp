#include "view/view_state.h"

#include <algorithm>
#include <cstdio>

#include "description/scene_params.h"
#include "mesh/media.h"
#include "render/method.h"
#include "render/render_params.h"
#include "util/error.h"
#include "util/parse.h"

namespace tsis {

namespace {

bool onOff(const std::string& name, const std::string& value) {
    if (value == "on" || value == "1") return true;
    if (value == "off" || value == "0") return false;
    fail(name, ": '", value, "' is not on or off");
}

int integerIn(const std::string& name, const std::string& value, int lo, int hi) {
    const long long v = parseInteger(name, value);
    if (v < lo || v > hi) fail(name, ": ", v, " is outside [", lo, ", ", hi, "]");
    return static_cast<int>(v);
}

bool sameCamera(const Camera& a, const Camera& b) {
    return a.eye == b.eye && a.target == b.target && a.up == b.up && a.fovYDegrees == b.fovYDegrees;
}

bool sameLights(const std::vector<Light>& a, const std::vector<Light>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const Light& x, const Light& y) {
        return x.type == y.type && x.vec == y.vec && x.rgb == y.rgb && x.shadows == y.shadows;
    });
}

bool sameMaterial(const Material& a, const Material& b) {
    return a.sigmaSPrime == b.sigmaSPrime && a.sigmaA == b.sigmaA && a.eta == b.eta;
}

}  // namespace

void resize(ViewState& state, double sizeMm) {
    if (!(sizeMm >= kMinSizeMm && sizeMm <= kMaxSizeMm))
        fail("size-mm: ", sizeMm, " is outside [", kMinSizeMm, ", ", kMaxSizeMm, "]");
    const float k = static_cast<float>(sizeMm / state.sizeMm);
    for (Camera* c : {&state.camera, &state.home}) {
        c->eye *= k;
        c->target *= k;
    }
    for (Light& l : state.lights) {
        if (l.type != Light::Type::Point) continue;
        l.vec *= k;
        l.rgb *= k * k;
    }
    state.sizeMm = sizeMm;
}

std::shared_ptr<const Mesh> scaledMesh(const ViewState& state) {
    if (!state.mesh || state.sizeMm == state.meshSizeMm) return state.mesh;
    auto mesh = std::make_shared<Mesh>(*state.mesh);
    normalizeMesh(*mesh, state.sizeMm);
    return mesh;
}

Scene sceneOf(const ViewState& state, const std::shared_ptr<const Mesh>& mesh) {
    Scene scene;
    if (mesh) scene.mesh = *mesh;
    scene.material = state.material;
    if (state.objectMaterials) scene.objectMaterials = *state.objectMaterials;
    scene.lights = state.lights;
    scene.camera = state.camera;
    scene.env = state.env;
    applyEnvironment(scene);
    return scene;
}

std::string objectsSummary(const Mesh& mesh, const ViewState& state) {
    const Media media = findMedia(mesh);
    // Each material once, in the order of the objects, with how many use it.
    std::vector<std::pair<std::string, int>> names;
    for (uint32_t id : media.materialOf) {
        std::string name = state.material.name.empty() ? "custom" : state.material.name;
        if (state.objectMaterials && id < state.objectMaterials->size()) {
            const ObjectMaterial& o = (*state.objectMaterials)[id];
            name = o.medium.name + (o.texture ? " (textured)" : "");
        }
        auto it = std::find_if(names.begin(), names.end(),
                               [&](const auto& n) { return n.first == name; });
        if (it == names.end())
            names.emplace_back(name, 1);
        else
            ++it->second;
    }
    std::string line = concat(media.count, media.count == 1 ? " object: " : " objects: ");
    for (size_t i = 0; i < names.size(); ++i)
        line += concat(i ? ", " : "", names[i].first,
                       names[i].second > 1 ? concat(" ×", names[i].second) : std::string());
    return line;
}

namespace {

std::string triple(const glm::dvec3& v) {
    char text[96];
    std::snprintf(text, sizeof text, "%.3g %.3g %.3g", v.x, v.y, v.z);
    return text;
}

}  // namespace

FileMaterialLines fileMaterialLines(const Mesh& mesh, const ViewState& state) {
    FileMaterialLines out;
    out.sceneMaterialUsed = false;
    const Media media = findMedia(mesh);
    std::vector<uint32_t> shown;
    for (uint32_t id : media.materialOf) {
        if (!state.objectMaterials || id >= state.objectMaterials->size()) {
            out.sceneMaterialUsed = true;
            continue;
        }
        if (std::find(shown.begin(), shown.end(), id) != shown.end()) continue;
        shown.push_back(id);
        const ObjectMaterial& o = (*state.objectMaterials)[id];
        const Material& m = o.medium;
        out.lines.push_back(concat(m.name, ": sigma_s' ", triple(m.sigmaSPrime), " /mm, sigma_a ",
                                   triple(m.sigmaA), " /mm, eta ", m.eta,
                                   o.texture ? ", albedo: texture x " + triple(o.textureScale)
                                             : ", albedo " + triple(o.albedo)));
    }
    return out;
}

bool drawsSamples(const std::string& method) {
    return findRenderParam("samples")->usedBy(method);
}

namespace {

// The scene options the viewer changes (the mesh, lights and camera it has
// its own controls for), parsed and checked by the scene's table.
const std::vector<std::string> kSceneParameters = {
    "material", "sigma-s", "sigma-a", "eta", "size-mm", "env", "env-intensity", "env-rotate"};
// The viewer's own switches.
const std::vector<std::string> kViewParameters = {"progressive", "frames", "auto-orbit"};

// Scene option `name` set to `value` in `s`: its text through the table's row.
void setSceneParameter(ViewState& s, const std::string& name, const std::string& value) {
    SceneDescription d;
    if (name == "env" && value == "none") {
        s.env.map = nullptr;
    } else {
        findSceneParam(name)->set(d, value);
    }
    Material& m = s.material;
    if (name == "material") {
        m = presetMaterial(*d.material.preset);
    } else if (name == "sigma-s" || name == "sigma-a" || name == "eta") {
        if (d.material.sigmaSPrime) m.sigmaSPrime = *d.material.sigmaSPrime;
        if (d.material.sigmaA) m.sigmaA = *d.material.sigmaA;
        if (d.material.eta) m.eta = *d.material.eta;
        m.name = "custom";
        validateMaterial(m);
    } else if (name == "size-mm") {
        if (!d.mesh.sizeMm) fail("size-mm ", value, ": the viewer's size is a number (mm)");
        resize(s, *d.mesh.sizeMm);
    } else if (name == "env") {
        if (d.env) s.env.map = loadEnvironment(d.env->path);
        const int lights = static_cast<int>(s.lights.size()) + (s.env ? 1 : 0);
        if (lights == 0) fail("env none: the scene would have no light");
        if (lights > kMaxLights) fail("env: ", s.lights.size(), " lights and a sun are too many");
    } else if (name == "env-intensity") {
        s.env.intensity = *d.env->intensity;
    } else if (name == "env-rotate") {
        s.env.rotateDegrees = *d.env->rotateDegrees;
    }
}

bool contains(const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

const std::vector<std::string>& parameterNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> n = kSceneParameters;
        n.push_back("method");
        for (const RenderParam& p : renderParams()) n.push_back(p.name);
        n.insert(n.end(), kViewParameters.begin(), kViewParameters.end());
        return n;
    }();
    return names;
}

void setParameter(ViewState& state, const std::string& name, const std::string& value) {
    ViewState s = state;
    RenderOptions& o = s.options;
    if (contains(kSceneParameters, name)) {
        setSceneParameter(s, name, value);
    } else if (name == "method") {
        o.method = value;
        validateRenderOptions(o);
    } else if (const RenderParam* p = findRenderParam(name)) {
        p->set(o, value);  // the ranges of the command line's options
    } else if (name == "progressive") {
        s.progressive = onOff(name, value);
    } else if (name == "frames") {
        s.maxFrames = integerIn(name, value, 1, 100000);
    } else if (name == "auto-orbit") {
        s.autoOrbit = onOff(name, value);
    } else {
        std::string list;
        for (const std::string& n : parameterNames()) list += (list.empty() ? "" : ", ") + n;
        fail("unknown parameter '", name, "' (", list, ")");
    }
    state = std::move(s);
}

bool sameScene(const ViewState& a, const ViewState& b) {
    return a.mesh == b.mesh && a.objectMaterials == b.objectMaterials && a.sizeMm == b.sizeMm &&
           sameMaterial(a.material, b.material) && sameLights(a.lights, b.lights) &&
           sameCamera(a.camera, b.camera) && a.env.map == b.env.map &&
           a.env.intensity == b.env.intensity && a.env.rotateDegrees == b.env.rotateDegrees &&
           a.options.width == b.options.width && a.options.height == b.options.height;
}

bool sameFrame(const ViewState& a, const ViewState& b) {
    const RenderOptions &oa = a.options, &ob = b.options;
    if (!sameScene(a, b) || oa.method != ob.method) return false;
    // Every parameter that changes the pixels, by the table's text of it.
    for (const RenderParam& p : renderParams())
        if (p.effect != ParamEffect::None && p.text(oa) != p.text(ob)) return false;
    return true;
}

}  // namespace tsis
