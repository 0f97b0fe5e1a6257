#include "cli/scene_options.h"

#include <charconv>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <sstream>

#include "atlas/atlas.h"
#include "mesh/mesh_io.h"
#include "mesh/uv_check.h"
#include "physics/material.h"
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
    const SceneDefaults sd;
    const RenderOptions d;
    static const std::vector<OptionSpec> specs = {
        {"mesh", true, false,
         "M  mesh file (.off/.obj/.ply/.stl/.gltf/.glb), builtin:NAME or a data mesh name" +
             byDefault(sd.mesh)},
        {"size-mm", true, false, "S  bounding-box diagonal in mm" + byDefault(sd.sizeMm)},
        {"material", true, false,
         "NAME  preset material (see tsis materials)" + byDefault(sd.material)},
        {"sigma-s", true, false, "R,G,B  reduced scattering σs' in 1/mm (overrides the preset)"},
        {"sigma-a", true, false, "R,G,B  absorption σa in 1/mm (overrides the preset)"},
        {"eta", true, false, "E  relative index of refraction (overrides the preset)"},
        {"light", true, true,
         "SPEC  point:X,Y,Z:R,G,B (intensity) or dir:X,Y,Z:R,G,B (direction of travel, "
         "irradiance); repeatable"},
        {"eye", true, false, "X,Y,Z  camera position in mm (default: framed from the front)"},
        {"target", true, false, "X,Y,Z  camera target (default 0,0,0)"},
        {"up", true, false, "X,Y,Z  camera up (default 0,1,0)"},
        {"fov", true, false, "DEG  vertical field of view" + byDefault(sd.fovDegrees)},
        {"width", true, false, "W  image width" + byDefault(d.width)},
        {"height", true, false, "H  image height" + byDefault(d.height)},
        {"method", true, false,
         "NAME  pyramid, tsis, hybrid, mis, ltsm, tsm, lss, hierarchical, reference, volumetric; "
         "see README" +
             byDefault(d.method)},
        {"samples", true, false,
         "N  importance samples; lss: samples per pixel" + byDefault(d.samples)},
        {"seed", true, false, "S  random seed" + byDefault(d.seed)},
        {"spacing", true, false,
         "MM  sample spacing of reference (default ℓ/2) and hierarchical (default ℓ); ℓ = 1/max "
         "σt', the smallest mean free path"},
        {"epsilon", true, false,
         "E  hierarchical: use an octree node whole when its area/distance^2 < E" +
             byDefault(d.epsilon)},
        {"pyramid-epsilon", true, false,
         "E  pyramid: use a node whole when max(radius^2, area/pi) < E·(d^2 + l^2), 0 ≤ E ≤ 1" +
             byDefault(d.pyramidEpsilon)},
        {"pyramid-stride", true, false,
         "S  pyramid: evaluate every S-th pixel and interpolate where the cell is one surface; "
         "0 = from the mean free path and the pixel size, 1 = every pixel" +
             byDefault(d.pyramidStride)},
        {"rp-bound", true, false,
         "B  hybrid: Rp is the largest r where Rd(r)·2πr crosses B" + byDefault(d.rpBound)},
        {"rp-k", true, false,
         "K  hybrid: slope of the local/global weights around Rp, 1/mm" + byDefault(d.rpK)},
        {"rd-part", true, false,
         "P  tsis, ltsm: integrate Rd (full), Rd·Wl (local) or Rd·Wg (global)" +
             byDefault(rdPartName(d.rdPart))},
        {"profile", true, false,
         "P  the radial profile: dipole (Jensen's), better-dipole (d'Eon's) or pbd (photon beam "
         "diffusion); README \"Physical accuracy\"" +
             byDefault(profileModelName(d.profile))},
        {"exit", true, false,
         "E  the exit term: jensen (Ft/pi·B) or normalized (Ft/(c·pi)·B, exitance B)" +
             byDefault(exitTermName(d.exit))},
        {"ltsm-rings", true, false,
         "L  ltsm, hybrid: rings of the light-view filter" + byDefault(d.ltsmRings)},
        {"ltsm-per-ring", true, false,
         "C  ltsm, hybrid: samples per ring (L×C+1 in all)" + byDefault(d.ltsmPerRing)},
        {"mis-distance", true, false,
         "M  mis: distance-driven samples per pixel and light" + byDefault(d.misDistanceSamples)},
        {"tsm-radius", true, false,
         "K  tsm: filter radius K/σtr of the widest channel, at most the object's bounding "
         "radius" +
             byDefault(d.tsmRadius)},
        {"spp", true, false,
         "N  volumetric: paths per pixel (default 16; with --time: until the time is up)"},
        {"time", true, false, "S  volumetric: stop after S seconds of paths (whole passes)"},
        {"atlas-res", true, false,
         "R  atlas resolution, a power of two" + byDefault(d.atlasResolution)},
        {"atlas", true, false,
         "MODE  auto (the mesh's UVs when valid, else build), file (require valid UVs) or build" +
             byDefault(sd.atlasMode)},
        {"light-res", true, false,
         "R  shadow/light-view map resolution; 0 = 2048 when the object is over 100 diffusion "
         "lengths 1/max σtr across, else 1024" +
             byDefault(d.lightResolution)},
        {"key", true, false, "K  tone-mapping key" + byDefault(d.key)},
        {"no-specular", false, false, "turn off the Phong highlight"},
        {"force", false, false,
         "reference: run even past the cost bounds (points, memory, Rd evaluations)"},
        {"no-reuse-lighting", false, false,
         "make the light maps and flux atlas every frame, even when the lighting did not change"},
        {"cl-device", true, false, "SUBSTR  OpenCL device (default: $TSIS_CL_DEVICE, else PoCL)"},
    };
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
    AtlasOptions o;
    o.resolution = args.getInt("atlas-res", RenderOptions{}.atlasResolution, 16, 4096);
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
    glm::vec3 forward = scene.camera.target - scene.camera.eye;
    if (glm::length(forward) == 0.0f) fail("--eye and --target are the same point");
    if (glm::length(glm::cross(forward, scene.camera.up)) < 1e-6f * glm::length(forward))
        fail("--up is parallel to the view direction (or zero)");
    return scene;
}

Mesh prepareMesh(const std::string& spec, double sizeMm, const std::string& atlasMode,
                 const AtlasOptions& atlasOptions) {
    Mesh mesh = loadMesh(spec);
    normalizeMesh(mesh, sizeMm);
    ensureNormals(mesh);
    return ensureAtlas(mesh, atlasMode, atlasOptions);
}

void loadSceneMesh(Scene& scene, const Args& args) {
    scene.mesh = prepareMesh(args.getString("mesh", SceneDefaults().mesh), sizeMmFromArgs(args),
                             atlasMode(args), atlasOptionsFromArgs(args));
}

Scene sceneFromArgs(const Args& args) {
    Scene scene = parseScene(args);
    loadSceneMesh(scene, args);
    return scene;
}

RenderOptions renderOptionsFromArgs(const Args& args) {
    RenderOptions o;
    o.method = args.getString("method", o.method);
    o.width = args.getInt("width", o.width, 1, 8192);
    o.height = args.getInt("height", o.height, 1, 8192);
    o.samples = args.getInt("samples", o.samples, 1, 1 << 22);
    o.seed = static_cast<uint32_t>(args.getInt("seed", o.seed, 0, 0xffffffffll >> 1));
    o.spacingMm = args.getDouble("spacing", o.spacingMm, 1e-4, 1e4);
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
    o.rpBound = args.getDouble("rp-bound", o.rpBound, 1e-9, 1e9);
    o.rpK = args.getDouble("rp-k", o.rpK, 0.0, 1e6);
    o.rdPart = parseRdPart(args.getString("rd-part", rdPartName(o.rdPart)));
    o.profile = parseProfileModel(args.getString("profile", profileModelName(o.profile)));
    o.exit = parseExitTerm(args.getString("exit", exitTermName(o.exit)));
    o.ltsmRings = args.getInt("ltsm-rings", o.ltsmRings, 0, 64);
    o.ltsmPerRing = args.getInt("ltsm-per-ring", o.ltsmPerRing, 1, 256);
    o.misDistanceSamples = args.getInt("mis-distance", o.misDistanceSamples, 0, 1 << 16);
    o.tsmRadius = args.getDouble("tsm-radius", o.tsmRadius, 1e-3, 1e3);
    o.spp = args.getInt("spp", o.spp, 1, 1 << 20);
    o.timeSeconds = args.getDouble("time", o.timeSeconds, 1e-3, 1e6);
    o.key = static_cast<float>(args.getDouble("key", o.key, 1e-4, 100.0));
    o.specular = !args.flag("no-specular");
    o.force = args.flag("force");
    o.reuseLighting = !args.flag("no-reuse-lighting");
    validateRenderOptions(o);
    return o;
}

namespace {

// The shortest text that parses back to exactly v.
template <typename T>
std::string exact(T v) {
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

template <typename V>
std::string exact3(const V& v) {
    return exact(v.x) + "," + exact(v.y) + "," + exact(v.z);
}

}  // namespace

std::vector<std::string> sceneArgs(const Scene& scene, const std::string& meshSpec, double sizeMm) {
    std::vector<std::string> a = {"--mesh", meshSpec, "--size-mm", exact(sizeMm)};
    const Material& m = scene.material;
    for (const Material& p : presetMaterials())
        if (p.name == m.name) a.insert(a.end(), {"--material", m.name});
    a.insert(a.end(), {"--sigma-s", exact3(m.sigmaSPrime), "--sigma-a", exact3(m.sigmaA), "--eta",
                       exact(m.eta)});
    for (const Light& l : scene.lights)
        a.insert(a.end(),
                 {"--light", std::string(l.type == Light::Type::Point ? "point:" : "dir:") +
                                 exact3(l.vec) + ":" + exact3(l.rgb)});
    const Camera& c = scene.camera;
    a.insert(a.end(), {"--eye", exact3(c.eye), "--target", exact3(c.target), "--up", exact3(c.up),
                       "--fov", exact(c.fovYDegrees)});
    return a;
}

std::vector<std::string> renderOptionArgs(const RenderOptions& o) {
    std::vector<std::string> a = {
        "--method",
        o.method,
        "--width",
        exact(o.width),
        "--height",
        exact(o.height),
        "--samples",
        exact(o.samples),
        "--seed",
        exact(o.seed),
        "--atlas-res",
        exact(o.atlasResolution),
        "--light-res",
        exact(o.lightResolution),
        "--key",
        exact(o.key),
        "--rp-bound",
        exact(o.rpBound),
        "--rp-k",
        exact(o.rpK),
        "--rd-part",
        rdPartName(o.rdPart),
        "--profile",
        profileModelName(o.profile),
        "--exit",
        exitTermName(o.exit),
        "--ltsm-rings",
        exact(o.ltsmRings),
        "--ltsm-per-ring",
        exact(o.ltsmPerRing),
        "--mis-distance",
        exact(o.misDistanceSamples),
        "--epsilon",
        exact(o.epsilon),
        "--pyramid-epsilon",
        exact(o.pyramidEpsilon),
        "--pyramid-stride",
        exact(o.pyramidStride),
        "--tsm-radius",
        exact(o.tsmRadius),
    };
    if (o.spacingMm > 0) a.insert(a.end(), {"--spacing", exact(o.spacingMm)});
    if (!o.specular) a.push_back("--no-specular");
    if (o.force) a.push_back("--force");
    if (!o.reuseLighting) a.push_back("--no-reuse-lighting");
    return a;
}

}  // namespace tsis
