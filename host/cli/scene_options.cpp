#include "cli/scene_options.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "atlas/atlas.h"
#include "mesh/mesh_io.h"
#include "mesh/uv_check.h"
#include "physics/material.h"
#include "render/profiles.h"
#include "util/error.h"

namespace tsis {

const std::vector<OptionSpec>& sceneOptionSpecs() {
    static const std::vector<OptionSpec> specs = {
        {"mesh", true, false,
         "M  mesh file (.off/.obj/.ply/.stl), builtin:NAME or a data mesh name (default "
         "builtin:default)"},
        {"size-mm", true, false, "S  bounding-box diagonal in mm (default 10)"},
        {"material", true, false, "NAME  preset material (default skin1; see tsis materials)"},
        {"sigma-s", true, false, "R,G,B  reduced scattering σs' in 1/mm (overrides the preset)"},
        {"sigma-a", true, false, "R,G,B  absorption σa in 1/mm (overrides the preset)"},
        {"eta", true, false, "E  relative index of refraction (overrides the preset)"},
        {"light", true, true,
         "SPEC  point:X,Y,Z:R,G,B (intensity) or dir:X,Y,Z:R,G,B (direction of travel, "
         "irradiance); repeatable"},
        {"eye", true, false, "X,Y,Z  camera position in mm (default: framed from the front)"},
        {"target", true, false, "X,Y,Z  camera target (default 0,0,0)"},
        {"up", true, false, "X,Y,Z  camera up (default 0,1,0)"},
        {"fov", true, false, "DEG  vertical field of view (default 35)"},
        {"width", true, false, "W  image width (default 512)"},
        {"height", true, false, "H  image height (default 512)"},
        {"method", true, false,
         "NAME  pyramid (default), tsis, hybrid, mis, ltsm, tsm, lss, hierarchical, reference, "
         "volumetric; see README"},
        {"samples", true, false, "N  importance samples (default 900); lss: samples per pixel"},
        {"seed", true, false, "S  random seed (default 1)"},
        {"spacing", true, false,
         "MM  sample spacing of reference (default ℓ/2) and hierarchical (default ℓ); ℓ = 1/max "
         "σt', the smallest mean free path"},
        {"epsilon", true, false,
         "E  hierarchical: use an octree node whole when its area/distance^2 < E (default 0.05)"},
        {"pyramid-epsilon", true, false,
         "E  pyramid: use a node whole when max(radius^2, area/pi) < E·(d^2 + l^2), 0 ≤ E ≤ 1 "
         "(default 0.05)"},
        {"pyramid-stride", true, false,
         "S  pyramid: evaluate every S-th pixel and interpolate where the cell is one surface; "
         "0 = from the mean free path and the pixel size (default), 1 = every pixel"},
        {"rp-bound", true, false,
         "B  hybrid: Rp is the largest r where Rd(r)·2πr crosses B (default 0.1)"},
        {"rp-k", true, false,
         "K  hybrid: slope of the local/global weights around Rp, 1/mm (default 1.5)"},
        {"rd-part", true, false,
         "P  tsis, ltsm: integrate Rd (full, default), Rd·Wl (local) or Rd·Wg (global)"},
        {"ltsm-rings", true, false, "L  ltsm, hybrid: rings of the light-view filter (default 4)"},
        {"ltsm-per-ring", true, false,
         "C  ltsm, hybrid: samples per ring (default 4; L×C+1 in all)"},
        {"mis-distance", true, false,
         "M  mis: distance-driven samples per pixel and light (default 16)"},
        {"tsm-radius", true, false,
         "K  tsm: filter radius K/σtr of the widest channel, at most the object's bounding radius "
         "(default 2)"},
        {"spp", true, false,
         "N  volumetric: paths per pixel (default 16; with --time: until the time is up)"},
        {"time", true, false, "S  volumetric: stop after S seconds of paths (whole passes)"},
        {"atlas-res", true, false, "R  atlas resolution, a power of two (default 512)"},
        {"atlas", true, false,
         "MODE  auto (the mesh's UVs when valid, else build; default), file (require valid UVs) or "
         "build"},
        {"light-res", true, false,
         "R  shadow/light-view map resolution; 0 = 2048 when the object is over 100 diffusion "
         "lengths 1/max σtr across, else 1024 (default 0)"},
        {"key", true, false, "K  tone-mapping key (default 0.18)"},
        {"no-specular", false, false, "turn off the Phong highlight"},
        {"no-reuse-lighting", false, false,
         "make the light maps and flux atlas every frame, even when the lighting did not change"},
        {"cl-device", true, false, "SUBSTR  OpenCL device (default: $TSIS_CL_DEVICE, else PoCL)"},
    };
    return specs;
}

Material materialFromArgs(const Args& args) {
    Material m = presetMaterial(args.getString("material", "skin1"));
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
    std::string mode = args.getString("atlas", "auto");
    if (mode != "auto" && mode != "file" && mode != "build")
        fail("--atlas '", mode, "': expected auto, file or build");
    return mode;
}

AtlasOptions atlasOptionsFromArgs(const Args& args) {
    AtlasOptions o;
    o.resolution = args.getInt("atlas-res", RenderOptions{}.atlasResolution, 16, 4096);
    return o;
}

Scene parseScene(const Args& args) {
    Scene scene;
    const double size = args.getDouble("size-mm", 10.0, 1e-3, 1e5);
    scene.material = materialFromArgs(args);
    atlasMode(args);
    atlasOptionsFromArgs(args);
    for (const std::string& l : args.values("light")) scene.lights.push_back(parseLight(l));
    if (static_cast<int>(scene.lights.size()) > kMaxLights)
        fail("too many lights: ", scene.lights.size(), " (at most ", kMaxLights, ")");
    if (scene.lights.empty()) scene.lights = defaultLights(size);
    float fov = static_cast<float>(args.getDouble("fov", 35.0, 1.0, 170.0));
    scene.camera = defaultCamera(size, fov);
    if (auto v = args.value("eye")) scene.camera.eye = glm::vec3(parseVec3("--eye", *v));
    if (auto v = args.value("target")) scene.camera.target = glm::vec3(parseVec3("--target", *v));
    if (auto v = args.value("up")) scene.camera.up = glm::vec3(parseVec3("--up", *v));
    glm::vec3 forward = scene.camera.target - scene.camera.eye;
    if (glm::length(forward) == 0.0f) fail("--eye and --target are the same point");
    if (glm::length(glm::cross(forward, scene.camera.up)) < 1e-6f * glm::length(forward))
        fail("--up is parallel to the view direction (or zero)");
    return scene;
}

void loadSceneMesh(Scene& scene, const Args& args) {
    scene.mesh = loadMesh(args.getString("mesh", "builtin:default"));
    normalizeMesh(scene.mesh, args.getDouble("size-mm", 10.0, 1e-3, 1e5));
    ensureNormals(scene.mesh);
    scene.mesh = ensureAtlas(scene.mesh, atlasMode(args), atlasOptionsFromArgs(args));
}

Scene sceneFromArgs(const Args& args) {
    Scene scene = parseScene(args);
    loadSceneMesh(scene, args);
    return scene;
}

RenderOptions renderOptionsFromArgs(const Args& args) {
    RenderOptions o;
    o.method = args.getString("method", o.method);
    o.width = args.getInt("width", 512, 1, 8192);
    o.height = args.getInt("height", 512, 1, 8192);
    o.samples = args.getInt("samples", 900, 1, 1 << 22);
    o.seed = static_cast<uint32_t>(args.getInt("seed", 1, 0, 0xffffffffll >> 1));
    o.spacingMm = args.getDouble("spacing", 0.0, 1e-4, 1e4);
    o.epsilon = static_cast<float>(args.getDouble("epsilon", o.epsilon, 0.0, 1e3));
    o.pyramidEpsilon =
        static_cast<float>(args.getDouble("pyramid-epsilon", o.pyramidEpsilon, 0.0, 1.0));
    o.pyramidStride = args.getInt("pyramid-stride", o.pyramidStride, 0, 16);
    auto powerOfTwo = [&](const char* name, int def) {
        int r = args.getInt(name, def, 1, 8192);
        if (r & (r - 1)) fail("--", name, " ", r, " is not a power of two");
        return r;
    };
    o.atlasResolution = powerOfTwo("atlas-res", o.atlasResolution);
    if (o.atlasResolution > 4096)
        fail("--atlas-res ", o.atlasResolution, " is too large (at most 4096)");
    o.lightResolution = args.getInt("light-res", o.lightResolution, 0, 8192);
    o.rpBound = args.getDouble("rp-bound", 0.1, 1e-9, 1e9);
    o.rpK = args.getDouble("rp-k", 1.5, 0.0, 1e6);
    o.rdPart = args.getString("rd-part", "full");
    parseRdPart(o.rdPart);
    o.ltsmRings = args.getInt("ltsm-rings", 4, 0, 64);
    o.ltsmPerRing = args.getInt("ltsm-per-ring", 4, 1, 256);
    o.misDistanceSamples = args.getInt("mis-distance", 16, 0, 1 << 16);
    o.tsmRadius = args.getDouble("tsm-radius", 2.0, 1e-3, 1e3);
    o.spp = args.getInt("spp", 0, 1, 1 << 20);
    o.timeSeconds = args.getDouble("time", 0.0, 1e-3, 1e6);
    o.key = static_cast<float>(args.getDouble("key", 0.18, 1e-4, 100.0));
    o.specular = !args.flag("no-specular");
    o.reuseLighting = !args.flag("no-reuse-lighting");
    validateRenderOptions(o);
    return o;
}

}  // namespace tsis
