#include "description/scene_params.h"

#include <glm/geometric.hpp>
#include <sstream>

#include "description/mesh_preparation.h"
#include "physics/material.h"
#include "render/method.h"
#include "render/render_params.h"
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

template <typename V>
std::string exact3(const V& v) {
    return exactText(v.x) + "," + exactText(v.y) + "," + exactText(v.z);
}

// --name's number, within [lo, hi] (the message Args' getters give).
double numberIn(const std::string& name, const std::string& v, double lo, double hi) {
    const double x = parseNumber("--" + name, v);
    if (x < lo || x > hi) fail("--", name, " ", v, " is out of range [", lo, ", ", hi, "]");
    return x;
}

// The row's value when given, as one text; none when not.
template <typename T, typename F>
std::vector<std::string> given(const std::optional<T>& v, F&& write) {
    return v ? std::vector<std::string>{write(*v)} : std::vector<std::string>{};
}

std::vector<std::string> givenNumber(const std::optional<double>& v) {
    return given(v, [](double x) { return exactText(x); });
}

template <typename V>
std::vector<std::string> givenVec3(const std::optional<V>& v) {
    return given(v, [](const V& x) { return exact3(x); });
}

}  // namespace

std::string lightText(const Light& l) {
    return std::string(l.type == Light::Type::Point ? "point:" : "dir:") + exact3(l.vec) + ":" +
           exact3(l.rgb);
}

namespace {

std::vector<SceneParam> makeSceneParams() {
    const SceneDefaults sd;
    using D = SceneDescription;
    using S = std::string;
    return {
        {"mesh",
         "M  mesh file (.off/.obj/.ply/.stl/.gltf/.glb), builtin:NAME or a data mesh name" +
             byDefault(sd.mesh),
         false, false, [](D& d, const S& v) { d.mesh.spec = v; },
         [](const D& d) { return given(d.mesh.spec, [](const S& s) { return s; }); }},
        {"size-mm",
         "S|file  bounding-box diagonal in mm, or file: the file's own size (glTF: metres; "
         "others: --units)" +
             byDefault(sd.sizeMm),
         false, false,
         [](D& d, const S& v) {
             d.mesh.sizeFromFile = v == "file";
             d.mesh.sizeMm.reset();
             if (!d.mesh.sizeFromFile)
                 d.mesh.sizeMm = numberIn("size-mm", v, kMinSizeMm, kMaxSizeMm);
         },
         [](const D& d) {
             return d.mesh.sizeFromFile ? std::vector<S>{"file"} : givenNumber(d.mesh.sizeMm);
         }},
        {"units",
         "m|cm|mm  with --size-mm file: the unit of a mesh file that does not state one "
         "(.obj, .ply, .stl, .off)",
         false, false,
         [](D& d, const S& v) {
             if (v != "m" && v != "cm" && v != "mm")
                 fail("--units '", v, "': expected m, cm or mm");
             d.mesh.units = v;
         },
         [](const D& d) { return given(d.mesh.units, [](const S& s) { return s; }); }},
        {"light-units",
         "tsis|file  file: the glTF's lights at their own candela and lux (683 lm/W, no "
         "re-levelling), --env in W/(m²·sr), and --exposure 19.93 by default (default "
         "tsis)",
         false, false,
         [](D& d, const S& v) {
             if (v != "tsis" && v != "file") fail("--light-units '", v, "': expected tsis or file");
             d.fileLightUnits = v == "file";
         },
         [](const D& d) { return d.fileLightUnits ? std::vector<S>{"file"} : std::vector<S>{}; }},
        {"allow-outside-assets",
         "read the files a mesh names (.mtl libraries, textures, glTF buffers and images) "
         "also outside its folder (default: inside only, links resolved)",
         true, false, [](D& d, const S&) { d.mesh.allowOutsideAssets = true; },
         [](const D& d) {
             return d.mesh.allowOutsideAssets ? std::vector<S>{"1"} : std::vector<S>{};
         }},
        {"material", "NAME  preset material (see tsis materials)" + byDefault(sd.material), false,
         false,
         [](D& d, const S& v) {
             presetMaterial(v);  // an unknown name is an error now
             d.material.preset = v;
         },
         [](const D& d) { return given(d.material.preset, [](const S& s) { return s; }); }},
        {"sigma-s", "R,G,B  reduced scattering σs' in 1/mm (overrides the preset)", false, false,
         [](D& d, const S& v) { d.material.sigmaSPrime = parseVec3("--sigma-s", v); },
         [](const D& d) { return givenVec3(d.material.sigmaSPrime); }},
        {"sigma-a", "R,G,B  absorption σa in 1/mm (overrides the preset)", false, false,
         [](D& d, const S& v) { d.material.sigmaA = parseVec3("--sigma-a", v); },
         [](const D& d) { return givenVec3(d.material.sigmaA); }},
        {"eta", "E  relative index of refraction (overrides the preset)", false, false,
         [](D& d, const S& v) { d.material.eta = parseNumber("--eta", v); },
         [](const D& d) { return givenNumber(d.material.eta); }},
        {"albedo",
         "R,G,B  surface albedo, the total diffuse reflectance in (0, 0.99] (with --mfp, "
         "instead of --sigma-s/--sigma-a; overrides the mesh file's materials)",
         false, false, [](D& d, const S& v) { d.material.albedo = parseVec3("--albedo", v); },
         [](const D& d) { return givenVec3(d.material.albedo); }},
        {"mfp",
         "R,G,B  mean free path 1/σt' in mm (with --albedo; alone it keeps the preset's or "
         "the file's albedo, textures included)",
         false, false, [](D& d, const S& v) { d.material.mfpMm = parseVec3("--mfp", v); },
         [](const D& d) { return givenVec3(d.material.mfpMm); }},
        {"light",
         "SPEC  point:X,Y,Z:R,G,B (intensity) or dir:X,Y,Z:R,G,B (direction of travel, "
         "irradiance); repeatable",
         false, true, [](D& d, const S& v) { d.lights.push_back(parseLight(v)); },
         [](const D& d) {
             std::vector<S> out;
             for (const Light& l : d.lights) out.push_back(lightText(l));
             return out;
         }},
        {"env",
         "FILE  environment light: a lat-long radiance map (.exr, .hdr), W/(mm²·sr); with "
         "no --light it lights alone",
         false, false,
         [](D& d, const S& v) {
             if (!d.env) d.env.emplace();
             d.env->path = v;
         },
         [](const D& d) {
             return d.env && !d.env->path.empty() ? std::vector<S>{d.env->path} : std::vector<S>{};
         }},
        {"env-intensity", "S  scale of the --env map's radiance (default 1)", false, false,
         [](D& d, const S& v) {
             if (!d.env) d.env.emplace();
             d.env->intensity = numberIn("env-intensity", v, 0.0, 1e12);
         },
         [](const D& d) { return d.env ? givenNumber(d.env->intensity) : std::vector<S>{}; }},
        {"env-rotate", "DEG  turn the --env map about the up axis (+y), within ±3600 (default 0)",
         false, false,
         [](D& d, const S& v) {
             if (!d.env) d.env.emplace();
             d.env->rotateDegrees = numberIn("env-rotate", v, -3600.0, 3600.0);
         },
         [](const D& d) { return d.env ? givenNumber(d.env->rotateDegrees) : std::vector<S>{}; }},
        {"eye", "X,Y,Z  camera position in mm (default: framed from the front)", false, false,
         [](D& d, const S& v) { d.camera.eye = glm::vec3(parseVec3("--eye", v)); },
         [](const D& d) { return givenVec3(d.camera.eye); }},
        {"target", "X,Y,Z  camera target (default 0,0,0)", false, false,
         [](D& d, const S& v) { d.camera.target = glm::vec3(parseVec3("--target", v)); },
         [](const D& d) { return givenVec3(d.camera.target); }},
        {"up", "X,Y,Z  camera up (default 0,1,0)", false, false,
         [](D& d, const S& v) {
             if (v == "y" || v == "z")  // the other up
                 fail("--up ", v, ": --up is the camera's X,Y,Z; the mesh's up axis is --mesh-up ",
                      v);
             d.camera.up = glm::vec3(parseVec3("--up", v));
         },
         [](const D& d) { return givenVec3(d.camera.up); }},
        {"fov", "DEG  vertical field of view" + byDefault(sd.fovDegrees), false, false,
         [](D& d, const S& v) {
             d.camera.fovDegrees = static_cast<float>(numberIn("fov", v, 1, 170));
         },
         [](const D& d) {
             return given(d.camera.fovDegrees, [](float f) { return exactText(f); });
         }},
        {"rotate",
         "X,Y,Z  turn the mesh by these degrees about X, then Y, then Z (after --mesh-up; "
         "default 0,0,0)",
         false, false,
         [](D& d, const S& v) {
             const glm::dvec3 r = parseVec3("--rotate", v);
             for (int k = 0; k < 3; ++k)
                 if (std::abs(r[k]) > 360)
                     fail("--rotate ", v, ": each angle must be within [-360, 360]");
             d.mesh.rotateDegrees = r;
         },
         [](const D& d) { return givenVec3(d.mesh.rotateDegrees); }},
        {"mesh-up",
         "y|z  the mesh's up axis: z turns a Z-up mesh's +z to +y" + byDefault(sd.meshUp), false,
         false,
         [](D& d, const S& v) {
             if (v != "y" && v != "z") fail("--mesh-up '", v, "': expected y or z");
             d.mesh.zUp = v == "z";
         },
         [](const D& d) { return given(d.mesh.zUp, [](bool z) { return S(z ? "z" : "y"); }); }},
        {"crease",
         "DEG  normals the mesh lacks are not smoothed across edges sharper than this (0: "
         "flat triangles, 180: smooth everywhere)" +
             byDefault(sd.creaseDegrees),
         false, false,
         [](D& d, const S& v) { d.mesh.creaseDegrees = numberIn("crease", v, 0, 180); },
         [](const D& d) { return givenNumber(d.mesh.creaseDegrees); }},
        {"camera",
         "N  the mesh file's camera N, from 0 (glTF; default: its first, when --eye, "
         "--target and --up are not given)",
         false, false,
         [](D& d, const S& v) {
             const long long n = parseInteger("--camera", v);
             if (n < 0 || n > (1 << 20))
                 fail("--camera ", v, " is out of range [0, ", 1 << 20, "]");
             d.camera.fileCamera = static_cast<int>(n);
         },
         [](const D& d) {
             return given(d.camera.fileCamera, [](int n) { return std::to_string(n); });
         }},
        {"atlas",
         "MODE  auto (the mesh's UVs when valid, else build), file (require valid UVs) or "
         "build" +
             byDefault(sd.atlasMode),
         false, false,
         [](D& d, const S& v) {
             if (v != "auto" && v != "file" && v != "build")
                 fail("--atlas '", v, "': expected auto, file or build");
             d.mesh.atlasMode = v;
         },
         [](const D& d) { return given(d.mesh.atlasMode, [](const S& s) { return s; }); }},
    };
}

}  // namespace

const std::vector<SceneParam>& sceneParams() {
    static const std::vector<SceneParam> params = makeSceneParams();
    return params;
}

const SceneParam* findSceneParam(const std::string& name) {
    for (const SceneParam& p : sceneParams())
        if (p.name == name) return &p;
    return nullptr;
}

const std::vector<OptionSpec>& sceneOptionSpecs() {
    static const std::vector<OptionSpec> specs = [] {
        std::vector<OptionSpec> specs;
        for (const SceneParam& p : sceneParams())
            specs.push_back({p.name, !p.flag, p.repeatable, p.help});
        specs.push_back({"cl-device", true, false,
                         "SUBSTR  OpenCL device (default: $TSIS_CL_DEVICE, else PoCL)"});
        specs.push_back({"gl", true, false,
                         "API  OpenGL through egl (headless: a GPU, or Mesa's software device), "
                         "osmesa, or auto: egl when it gives a context, else osmesa (default: "
                         "$TSIS_GL, else auto)"});
        std::string methods;
        for (const std::string& m : methodNames()) methods += (methods.empty() ? "" : ", ") + m;
        specs.push_back({"method", true, false,
                         "NAME  " + methods + "; see docs/guide/methods.md" +
                             byDefault(RenderOptions().method)});
        for (const RenderParam& p : renderParams())
            specs.push_back({p.name, !p.flag, false, p.usage()});
        return specs;
    }();
    return specs;
}

SceneDescription sceneDescriptionFromArgs(const Args& args) {
    SceneDescription d;
    for (const SceneParam& p : sceneParams())
        for (const std::string& v : args.values(p.name)) p.set(d, v);
    // The atlas's resolution is a render parameter the mesh's atlas is made at.
    if (auto v = args.value("atlas-res")) {
        RenderOptions r;
        findRenderParam("atlas-res")->set(r, *v);
        d.mesh.atlasResolution = r.atlasResolution;
    }
    return d;
}

std::vector<std::string> descriptionArgs(const SceneDescription& d) {
    std::vector<std::string> a;
    for (const SceneParam& p : sceneParams())
        for (const std::string& v : p.text(d)) {
            a.push_back("--" + p.name);
            if (!p.flag) a.push_back(v);
        }
    if (d.mesh.atlasResolution)
        a.insert(a.end(), {"--atlas-res", std::to_string(*d.mesh.atlasResolution)});
    return a;
}

ProfileModel profileModelFromArgs(const Args& args) {
    RenderOptions r;
    if (auto v = args.value("profile")) findRenderParam("profile")->set(r, *v);
    return r.profile;
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

Scene parseScene(const Args& args) {
    return placedScene(sceneDescriptionFromArgs(args), profileModelFromArgs(args));
}

void loadSceneMesh(Scene& scene, const Args& args) {
    loadSceneMesh(scene, sceneDescriptionFromArgs(args), profileModelFromArgs(args));
}

Scene sceneFromArgs(const Args& args) {
    return buildScene(sceneDescriptionFromArgs(args), profileModelFromArgs(args));
}

RenderOptions renderOptionsFromArgs(const Args& args) {
    RenderOptions o;
    // The file's light units: radiance in W/(mm²·sr) exposed as Blender's
    // exposure 0 shows W/(m²·sr) (docs/guide/scenes-and-materials.md "The file's units and light
    // power").
    if (args.value("light-units") == std::optional<std::string>("file"))
        o.exposure = kFileLightUnitsExposure;
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

std::vector<std::string> sceneArgs(const Scene& scene, const SceneDescription& d) {
    // The description without what the scene resolved (size, lights,
    // environment, camera): those are written as they were used.
    SceneDescription rest = d;
    rest.mesh.spec = meshSpecOf(d.mesh);
    rest.mesh.sizeFromFile = false;
    rest.mesh.sizeMm = scene.sizeMm;
    rest.mesh.units.reset();
    rest.fileLightUnits = false;
    rest.lights.clear();
    for (const Light& l : scene.lights)
        if (!l.environment) rest.lights.push_back(l);
    rest.env.reset();
    if (scene.env)
        rest.env = EnvironmentDescription{scene.env.map->path, scene.env.intensity,
                                          scene.env.rotateDegrees};
    const Camera& c = scene.camera;
    rest.camera = {c.eye, c.target, c.up, c.fovYDegrees, std::nullopt};
    return descriptionArgs(rest);
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
