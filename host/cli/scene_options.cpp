#include "cli/scene_options.h"

#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <optional>
#include <sstream>

#include "atlas/atlas.h"
#include "mesh/mesh_io.h"
#include "mesh/repair.h"
#include "mesh/uv_check.h"
#include "physics/material.h"
#include "render/albedo_inversion.h"
#include "render/method.h"
#include "render/object_materials.h"
#include "render/render_params.h"
#include "scene/from_file.h"
#include "util/error.h"
#include "util/input_file.h"

namespace tsis {

namespace {

constexpr double kPerM2ToPerMm2 = 1e-6;  // W/m² → W/mm²

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
            {"size-mm", true, false,
             "S|file  bounding-box diagonal in mm, or file: the file's own size (glTF: metres; "
             "others: --units)" +
                 byDefault(sd.sizeMm)},
            {"units", true, false,
             "m|cm|mm  with --size-mm file: the unit of a mesh file that does not state one "
             "(.obj, .ply, .stl, .off)"},
            {"light-units", true, false,
             "tsis|file  file: the glTF's lights at their own candela and lux (683 lm/W, no "
             "re-levelling), --env in W/(m²·sr), and --exposure 19.93 by default (default "
             "tsis)"},
            {"allow-outside-assets", false, false,
             "read the files a mesh names (.mtl libraries, textures, glTF buffers and images) "
             "also outside its folder (default: inside only, links resolved)"},
            {"material", true, false,
             "NAME  preset material (see tsis materials)" + byDefault(sd.material)},
            {"sigma-s", true, false,
             "R,G,B  reduced scattering σs' in 1/mm (overrides the preset)"},
            {"sigma-a", true, false, "R,G,B  absorption σa in 1/mm (overrides the preset)"},
            {"eta", true, false, "E  relative index of refraction (overrides the preset)"},
            {"albedo", true, false,
             "R,G,B  surface albedo, the total diffuse reflectance in (0, 0.99] (with --mfp, "
             "instead of --sigma-s/--sigma-a; overrides the mesh file's materials)"},
            {"mfp", true, false,
             "R,G,B  mean free path 1/σt' in mm (with --albedo; alone it keeps the preset's or "
             "the file's albedo, textures included)"},
            {"light", true, true,
             "SPEC  point:X,Y,Z:R,G,B (intensity) or dir:X,Y,Z:R,G,B (direction of travel, "
             "irradiance); repeatable"},
            {"env", true, false,
             "FILE  environment light: a lat-long radiance map (.exr, .hdr), W/(mm²·sr); with "
             "no --light it lights alone"},
            {"env-intensity", true, false, "S  scale of the --env map's radiance (default 1)"},
            {"env-rotate", true, false,
             "DEG  turn the --env map about the up axis (+y), within ±3600 (default 0)"},
            {"eye", true, false, "X,Y,Z  camera position in mm (default: framed from the front)"},
            {"target", true, false, "X,Y,Z  camera target (default 0,0,0)"},
            {"up", true, false, "X,Y,Z  camera up (default 0,1,0)"},
            {"fov", true, false, "DEG  vertical field of view" + byDefault(sd.fovDegrees)},
            {"rotate", true, false,
             "X,Y,Z  turn the mesh by these degrees about X, then Y, then Z (after --mesh-up; "
             "default 0,0,0)"},
            {"mesh-up", true, false,
             "y|z  the mesh's up axis: z turns a Z-up mesh's +z to +y" + byDefault(sd.meshUp)},
            {"crease", true, false,
             "DEG  normals the mesh lacks are not smoothed across edges sharper than this (0: "
             "flat triangles, 180: smooth everywhere)" +
                 byDefault(sd.creaseDegrees)},
            {"camera", true, false,
             "N  the mesh file's camera N, from 0 (glTF; default: its first, when --eye, "
             "--target and --up are not given)"},
            {"atlas", true, false,
             "MODE  auto (the mesh's UVs when valid, else build), file (require valid UVs) or "
             "build" +
                 byDefault(sd.atlasMode)},
            {"cl-device", true, false,
             "SUBSTR  OpenCL device (default: $TSIS_CL_DEVICE, else PoCL)"},
            {"gl", true, false,
             "API  OpenGL through egl (headless: a GPU, or Mesa's software device), osmesa, "
             "or auto: egl when it gives a context, else osmesa (default: $TSIS_GL, else "
             "auto)"},
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

bool sizeFromFile(const Args& args) {
    return args.value("size-mm") == std::optional<std::string>("file");
}

double sizeMmFromArgs(const Args& args) {
    return args.getDouble("size-mm", SceneDefaults().sizeMm, kMinSizeMm, kMaxSizeMm);
}

std::optional<double> unitsMmFromArgs(const Args& args) {
    const auto u = args.value("units");
    if (!u) return std::nullopt;
    if (!sizeFromFile(args)) fail("--units ", *u, " is the file's unit for --size-mm file");
    if (*u == "m") return 1000.0;
    if (*u == "cm") return 10.0;
    if (*u == "mm") return 1.0;
    fail("--units '", *u, "': expected m, cm or mm");
}

bool fileLightUnits(const Args& args) {
    const std::string u = args.getString("light-units", "tsis");
    if (u != "tsis" && u != "file") fail("--light-units '", u, "': expected tsis or file");
    if (u == "file" && args.has("light"))
        fail(
            "--light-units file reads the glTF's lights (and --env in W/(m²·sr)): not with "
            "--light, whose values are tsis' own");
    return u == "file";
}

double fileSizeMm(const Mesh& mesh, const FileView& view, std::optional<double> unitsMm,
                  const std::string& spec) {
    if (spec.rfind("builtin:", 0) == 0)
        fail("--size-mm file: ", spec, " has no size of its own; give --size-mm S");
    if (view.statedMmPerUnit && unitsMm)
        fail("--units: mesh '", mesh.name, "' states its unit (glTF: metres); not with --units");
    const std::optional<double> mmPerUnit = view.statedMmPerUnit ? view.statedMmPerUnit : unitsMm;
    if (!mmPerUnit)
        fail("--size-mm file: mesh '", mesh.name,
             "' does not state its unit; give --units m, cm or mm");
    const double diagonal = boundingDiagonal(mesh) * *mmPerUnit;
    if (!(diagonal >= kMinSizeMm && diagonal <= kMaxSizeMm))
        fail("--size-mm file: mesh '", mesh.name, "' is ", diagonal,
             " mm across (its bounding-box diagonal), outside [", kMinSizeMm, ", ", kMaxSizeMm,
             "]; give --size-mm S");
    return diagonal;
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
    validateMaterial(m);
    // The artist's parameters (render/albedo_inversion.h): --albedo with
    // --mfp, or --mfp alone with the material's own albedo.
    const auto albedo = args.value("albedo"), mfp = args.value("mfp");
    if (albedo && (args.has("sigma-s") || args.has("sigma-a")))
        fail("--albedo sets σs' and σa: not with --sigma-s or --sigma-a");
    if (albedo && !mfp)
        fail(
            "--albedo needs --mfp R,G,B (mm): the albedo fixes σs'/σt', the mean free path the "
            "scale");
    if (mfp) {
        const ProfileModel model = profileModelFromArgs(args);
        const glm::dvec3 a = albedo ? parseVec3("--albedo", *albedo) : albedoOf(m, model);
        m = materialFromAlbedo("custom", a, parseVec3("--mfp", *mfp), m.eta, model);
        custom = true;
    }
    if (custom) m.name = "custom";
    return m;
}

MaterialOverrides materialOverridesFromArgs(const Args& args) {
    MaterialOverrides o;
    o.replaceAll =
        args.has("material") || args.has("albedo") || args.has("sigma-s") || args.has("sigma-a");
    if (auto v = args.value("mfp")) o.mfp = parseVec3("--mfp", *v);
    if (auto v = args.value("eta")) o.eta = parseNumber("--eta", *v);
    return o;
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

MeshOptions meshOptionsFromArgs(const Args& args) {
    MeshOptions o;
    if (auto v = args.value("rotate")) {
        o.rotateDegrees = parseVec3("--rotate", *v);
        for (int k = 0; k < 3; ++k)
            if (std::abs(o.rotateDegrees[k]) > 360)
                fail("--rotate ", *v, ": each angle must be within [-360, 360]");
    }
    const std::string up = args.getString("mesh-up", SceneDefaults().meshUp);
    if (up != "y" && up != "z") fail("--mesh-up '", up, "': expected y or z");
    o.zUp = up == "z";
    o.creaseDegrees = args.getDouble("crease", SceneDefaults().creaseDegrees, 0, 180);
    o.atlasMode = atlasMode(args);
    o.atlas = atlasOptionsFromArgs(args);
    setOutsideAssetsAllowed(args.flag("allow-outside-assets"));
    return o;
}

std::vector<std::string> meshOptionArgs(const MeshOptions& o) {
    std::vector<std::string> a;
    if (o.rotateDegrees != glm::dvec3(0.0))
        a.insert(a.end(),
                 {"--rotate", exactText(o.rotateDegrees.x) + "," + exactText(o.rotateDegrees.y) +
                                  "," + exactText(o.rotateDegrees.z)});
    if (o.zUp) a.insert(a.end(), {"--mesh-up", "z"});
    if (o.creaseDegrees != SceneDefaults().creaseDegrees)
        a.insert(a.end(), {"--crease", exactText(o.creaseDegrees)});
    a.insert(a.end(), {"--atlas", o.atlasMode});
    return a;
}

namespace {

// What parseScene places by the object's size: the default lights where
// neither --light nor --env is given, and the default camera (framing an
// object of that diagonal) with --eye, --target and --up over it.
void placeBySize(Scene& scene, const Args& args, double size) {
    if (!args.has("light") && !scene.env) scene.lights = defaultLights(size);
    float fov = static_cast<float>(args.getDouble("fov", SceneDefaults().fovDegrees, 1.0, 170.0));
    scene.camera = defaultCamera(size, fov);
    if (auto v = args.value("eye")) scene.camera.eye = glm::vec3(parseVec3("--eye", *v));
    if (auto v = args.value("target")) scene.camera.target = glm::vec3(parseVec3("--target", *v));
    if (auto v = args.value("up")) {
        if (*v == "y" || *v == "z")  // the other up
            fail("--up ", *v, ": --up is the camera's X,Y,Z; the mesh's up axis is --mesh-up ", *v);
        scene.camera.up = glm::vec3(parseVec3("--up", *v));
    }
}

}  // namespace

Scene parseScene(const Args& args) {
    Scene scene;
    // With --size-mm file the size is known once the mesh is: loadSceneMesh
    // places again by it.
    const double size = sizeFromFile(args) ? SceneDefaults().sizeMm : sizeMmFromArgs(args);
    unitsMmFromArgs(args);
    scene.sizeMm = size;
    scene.material = materialFromArgs(args);
    meshOptionsFromArgs(args);
    const bool fileUnits = fileLightUnits(args);
    for (const std::string& l : args.values("light")) scene.lights.push_back(parseLight(l));
    if (static_cast<int>(scene.lights.size()) > kMaxLights)
        fail("too many lights: ", scene.lights.size(), " (at most ", kMaxLights, ")");
    if (auto v = args.value("env")) {
        scene.env.map = loadEnvironment(*v);
        scene.env.intensity = args.getDouble("env-intensity", 1.0, 0.0, 1e12);
        // --light-units file: the map in W/(m²·sr), as Blender and Cycles read it.
        if (fileUnits) scene.env.intensity *= kPerM2ToPerMm2;
        scene.env.rotateDegrees = args.getDouble("env-rotate", 0.0, -3600.0, 3600.0);
    } else if (args.has("env-intensity") || args.has("env-rotate")) {
        fail("--env-intensity and --env-rotate need --env FILE");
    }
    placeBySize(scene, args, size);
    applyEnvironment(scene);  // the map's sun: one more directional light
    if (static_cast<int>(scene.lights.size()) > kMaxLights)
        fail("too many lights: ", scene.lights.size() - 1, " and the environment's sun (at most ",
             kMaxLights, " in all)");
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

// A loaded mesh turned by --mesh-up and --rotate (with `view`, its file's
// cameras and lights alike), after a note when it is not closed.
void turn(Mesh& mesh, FileView* view, const MeshOptions& o) {
    noteIfOpen(mesh);
    const glm::dmat3 rotation = meshRotation(o.rotateDegrees, o.zUp);
    const glm::dvec3 centre = rotateMesh(mesh, rotation);
    if (view) rotateView(*view, rotation, centre);
}

// A turned mesh at sizeMm with its atlas, then the normals it lacks, split at
// o.creaseDegrees: after the atlas, so that neither the atlas nor its cache
// key depends on the crease (the copies share their vertex's UV).
Mesh finish(Mesh turned, double sizeMm, const MeshOptions& o) {
    Mesh mesh = atlasAtSize(std::move(turned), sizeMm, o.atlasMode, o.atlas);
    ensureNormals(mesh, o.creaseDegrees);
    return mesh;
}

}  // namespace

Mesh atlasMesh(Mesh mesh, double sizeMm, const MeshOptions& o, AtlasStats* stats) {
    turn(mesh, nullptr, o);
    return atlasAtSize(std::move(mesh), sizeMm, o.atlasMode, o.atlas, stats);
}

Mesh prepareLoadedMesh(Mesh mesh, double sizeMm, const MeshOptions& o) {
    turn(mesh, nullptr, o);
    return finish(std::move(mesh), sizeMm, o);
}

Mesh prepareMesh(const std::string& spec, double sizeMm, const MeshOptions& o) {
    return prepareLoadedMesh(loadMesh(spec), sizeMm, o);
}

namespace {

// The mesh `spec` names into `scene` (which holds the command line's
// material, camera and lights): its file's camera and lights where `use`
// lets them, its materials, then the mesh prepared at sizeMm. With
// `fileSize` (--size-mm file) the size is the file's own (fileSizeMm of
// --units `unitsMm`), and `fileSize` places the scene's defaults by it first.
void loadInto(Scene& scene, const std::string& spec, double size, const MeshOptions& o,
              const FileViewUse& use, const MaterialOverrides& overrides, ProfileModel profile,
              const std::function<void(Scene&, double)>& fileSize = {},
              std::optional<double> unitsMm = std::nullopt) {
    FileView view;
    Mesh mesh = loadMesh(spec, &view);
    turn(mesh, &view, o);
    if (fileSize) {
        size = fileSizeMm(mesh, view, unitsMm, spec);
        fileSize(scene, size);
    }
    scene.sizeMm = size;
    normalizeView(view, normalizationOf(mesh, size));
    // Before the atlas: a wrong --camera costs no waiting.
    useFileView(scene, view, use, size, mesh.name);
    keepUsedMaterials(mesh, view);
    scene.objectMaterials = objectMaterials(view.materials, scene.material, overrides, profile,
                                            view.mmPerFileUnit, mesh.name);
    scene.mesh = finish(std::move(mesh), size, o);
}

}  // namespace

FileViewUse fileViewUseFromArgs(const Args& args) {
    // The command line's camera and lights win, per kind.
    FileViewUse use;
    use.camera = !args.has("eye") && !args.has("target") && !args.has("up");
    if (args.has("camera")) use.cameraIndex = args.getInt("camera", 0, 0, 1 << 20);
    use.fov = !args.has("fov");
    use.lights = !args.has("light") && !args.has("env");
    use.fileLightUnits = fileLightUnits(args);
    use.lightsGivenBy = args.has("light") && args.has("env") ? "--light and --env given"
                        : args.has("light")                  ? "--light given"
                                                             : "--env given: it lights alone";
    return use;
}

void loadSceneMesh(Scene& scene, const Args& args) {
    const bool fromFile = sizeFromFile(args);
    const auto placeAgain = [&args](Scene& s, double size) {
        placeBySize(s, args, size);
        applyEnvironment(s);
    };
    loadInto(scene, args.getString("mesh", SceneDefaults().mesh),
             fromFile ? SceneDefaults().sizeMm : sizeMmFromArgs(args), meshOptionsFromArgs(args),
             fileViewUseFromArgs(args), materialOverridesFromArgs(args), profileModelFromArgs(args),
             fromFile ? std::function<void(Scene&, double)>(placeAgain) : nullptr,
             unitsMmFromArgs(args));
}

ViewMesh loadViewMesh(const std::string& spec, double sizeMm, const Scene& cli,
                      const MeshOptions& o, const FileViewUse& use,
                      const MaterialOverrides& overrides, ProfileModel profile) {
    Scene scene = cli;
    loadInto(scene, spec, sizeMm, o, use, overrides, profile);
    ViewMesh out;
    out.mesh = std::move(scene.mesh);
    out.materials = std::move(scene.objectMaterials);
    // The viewer's lights stay its own (it drags them); the file's camera
    // when it has one the command line left to it.
    if (use.camera &&
        !(scene.camera.eye == cli.camera.eye && scene.camera.target == cli.camera.target &&
          scene.camera.up == cli.camera.up))
        out.camera = scene.camera;
    return out;
}

Scene sceneFromArgs(const Args& args) {
    Scene scene = parseScene(args);
    loadSceneMesh(scene, args);
    return scene;
}

RenderOptions renderOptionsFromArgs(const Args& args) {
    RenderOptions o;
    // The file's light units: radiance in W/(mm²·sr) exposed as Blender's
    // exposure 0 shows W/(m²·sr) (README "The file's units and light power").
    if (fileLightUnits(args)) o.exposure = kFileLightUnitsExposure;
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
        if (!l.environment)
            a.insert(a.end(),
                     {"--light", std::string(l.type == Light::Type::Point ? "point:" : "dir:") +
                                     exact3(l.vec) + ":" + exact3(l.rgb)});
    if (scene.env)
        a.insert(a.end(),
                 {"--env", scene.env.map->path, "--env-intensity", exactText(scene.env.intensity),
                  "--env-rotate", exactText(scene.env.rotateDegrees)});
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
