// What a scene is as the user describes it (the CLI's options, the API's
// types): each part as given, or absent for "the default" or "the file's".
// The room below both the command line and the library (docs/design.md §6
// "Library"): buildScene turns a description into the Scene a frame renders,
// with the defaults (lights, camera) placed by the object's size and the
// mesh prepared as `tsis render` prepares it. A description keeps what was
// said, not what it resolved to: albedo + mean free path stay so, inverted
// through the profile of the render that uses them (resolveMaterial), and a
// file's materials stay the file's unless a material is given.
#pragma once

#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "atlas/atlas.h"
#include "mesh/mesh.h"
#include "render/object_materials.h"
#include "render/render_options.h"
#include "scene/from_file.h"
#include "scene/scene.h"

namespace tsis {

// What a scene is when its options are not given (RenderOptions holds the
// render's own defaults); the help text prints them from here.
struct SceneDefaults {
    std::string mesh = "builtin:default";
    double sizeMm = 10;
    std::string material = "skin1";
    float fovDegrees = 35;
    std::string atlasMode = "auto";
    double creaseDegrees = kDefaultCreaseDegrees;
    std::string meshUp = "y";
};

// How a loaded mesh is made ready: turned (--mesh-up, --rotate), its normals
// (--crease) and its atlas (--atlas, --atlas-res).
struct MeshOptions {
    glm::dvec3 rotateDegrees{0.0};
    bool zUp = false;
    double creaseDegrees = SceneDefaults().creaseDegrees;
    std::string atlasMode = SceneDefaults().atlasMode;
    AtlasOptions atlas;
};

// The mesh and how it is placed: the file (or builtin:NAME), its size and unit.
struct MeshDescription {
    std::optional<std::string> spec;   // SceneDefaults::mesh
    std::optional<double> sizeMm;      // the bounding-box diagonal; SceneDefaults::sizeMm
    bool sizeFromFile = false;         // --size-mm file: the file's own size
    std::optional<std::string> units;  // --units m|cm|mm: the file's unit (with sizeFromFile)
    std::optional<glm::dvec3> rotateDegrees;
    std::optional<bool> zUp;
    std::optional<double> creaseDegrees;
    std::optional<std::string> atlasMode;
    std::optional<int> atlasResolution;  // RenderOptions::atlasResolution
    bool allowOutsideAssets = false;
};

// The material of every triangle without a file material and, when one of
// preset/σ/albedo is given, of every triangle (MaterialOverrides::replaceAll).
struct MaterialDescription {
    std::optional<std::string> preset;              // SceneDefaults::material
    std::optional<glm::dvec3> sigmaSPrime, sigmaA;  // 1/mm, over the preset's
    std::optional<double> eta;                      // over the preset's (and the file's)
    std::optional<glm::dvec3> albedo, mfpMm;        // the artist's parameters
    bool any() const { return preset || sigmaSPrime || sigmaA || eta || albedo || mfpMm; }
};

// One object of a scene of several (Scene::fromObjects, description/objects.h).
struct ObjectDescription {
    std::string spec;                    // a mesh file or builtin:NAME; empty: `arrays`
    std::shared_ptr<const Mesh> arrays;  // a mesh given as arrays (repaired), in mm
    // Scaled, then turned (degrees about X, then Y, then Z), then moved, in
    // the scene's millimetres; a file's positions in its stated unit (glTF:
    // metres), else as millimetres.
    double scale = 1;
    glm::dvec3 rotateDegrees{0.0}, translateMm{0.0};
    // Its material over all of its triangles; none: its file's materials,
    // where it has none the scene's.
    std::optional<MaterialDescription> material;
    // An albedo texture over `material` (read through the object's own
    // texture coordinates; the albedo, if given, scales it); empty: none.
    std::string albedoTexture;
};

struct EnvironmentDescription {
    std::string path;  // a lat-long radiance map (.exr, .hdr); empty: not given (an error)
    std::optional<double> intensity, rotateDegrees;
    // The map given as pixels (the library's Environment): `path` only names it.
    std::shared_ptr<const EnvironmentMap> map;
};

struct CameraDescription {
    std::optional<glm::vec3> eye, target, up;  // default: framed from the front
    std::optional<float> fovDegrees;           // SceneDefaults::fovDegrees
    std::optional<int> fileCamera;             // the mesh file's camera N
};

struct SceneDescription {
    MeshDescription mesh;  // with objects: how their one mesh is made ready (no spec)
    // Objects each placed and given its material (empty: mesh.spec alone).
    // The description's material then fills only what no object or file gives.
    std::vector<ObjectDescription> objects;
    MaterialDescription material;
    std::vector<Light> lights;  // empty: the file's, else the defaults (none with an env)
    std::optional<EnvironmentDescription> env;
    CameraDescription camera;
    bool fileLightUnits = false;  // --light-units file
};

// The exposure --light-units file defaults to: log2(10⁶), so that radiance
// in W/(mm²·sr) × 2^EV is the radiance in W/(m²·sr), which Blender shows
// as it is at its exposure 0.
constexpr float kFileLightUnitsExposure = 19.931568f;

// The material `m` describes, checked (σ, η, albedo with mfp), albedo + mfp
// inverted through `profile`'s total reflectance.
Material resolveMaterial(const MaterialDescription& m, ProfileModel profile);
// What the material says over a mesh file's materials.
MaterialOverrides overridesOf(const MaterialDescription& m);
MeshOptions meshOptionsOf(const MeshDescription& m);
// The mesh's size when the file does not give it (sizeFromFile: placed again).
double nominalSizeMm(const MeshDescription& m);
// --units as mm per file unit, if given.
std::optional<double> unitsMmOf(const MeshDescription& m);
std::string meshSpecOf(const MeshDescription& m);
// What the description left to the mesh file's camera and lights.
FileViewUse fileViewUseOf(const SceneDescription& d);

// The default lights for an object of bounding-box diagonal sizeMm: a back
// light that makes thin parts glow and a weaker front fill.
std::vector<Light> defaultLights(double sizeMm);
Camera defaultCamera(double sizeMm, float fovYDegrees);

struct FileMaterials;  // description/mesh_preparation.h

// Every part resolved and checked except the mesh (material, lights,
// environment, camera): errors come before slow work.
Scene placedScene(const SceneDescription& d, ProfileModel profile);
// The mesh loaded into a placedScene: the file's camera and lights where the
// description leaves them to it, its materials, the mesh prepared at its size.
// `kept` (optional): the file's materials as read.
void loadSceneMesh(Scene& scene, const SceneDescription& d, ProfileModel profile,
                   FileMaterials* kept = nullptr);
// placedScene, then loadSceneMesh.
Scene buildScene(const SceneDescription& d, ProfileModel profile, FileMaterials* kept = nullptr);

}  // namespace tsis
