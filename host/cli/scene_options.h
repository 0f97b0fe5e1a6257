// `tsis render` options → a Scene and RenderOptions (defaults, parsing, validation).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "atlas/atlas.h"
#include "cli/args.h"
#include "render/object_materials.h"
#include "render/render_options.h"
#include "scene/from_file.h"
#include "scene/scene.h"
#include "view/view_state.h"

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

// Options every command that renders shares (render, compare-style tools, bench).
const std::vector<OptionSpec>& sceneOptionSpecs();

// --size-mm file: the mesh file's own size (fileSizeMm).
bool sizeFromFile(const Args& args);
// --size-mm S, checked (kMinSizeMm to kMaxSizeMm).
double sizeMmFromArgs(const Args& args);
// --units m|cm|mm as mm per file unit (only with --size-mm file), if given.
std::optional<double> unitsMmFromArgs(const Args& args);
// --light-units file (checked: not with --light).
bool fileLightUnits(const Args& args);
// The exposure --light-units file defaults to: log2(10⁶), so that radiance
// in W/(mm²·sr) × 2^EV is the radiance in W/(m²·sr), which Blender shows
// as it is at its exposure 0.
constexpr float kFileLightUnitsExposure = 19.931568f;
// --size-mm file: the turned mesh's bounding-box diagonal in mm through the
// unit its format states (view, glTF: metres) or else --units; an error for
// a builtin mesh, a file without a stated unit and no --units, --units on a
// file that states one, or a size outside kMinSizeMm to kMaxSizeMm.
double fileSizeMm(const Mesh& mesh, const FileView& view, std::optional<double> unitsMm,
                  const std::string& spec);

// Material from --material (SceneDefaults::material) with --sigma-s/--sigma-a/--eta overrides.
// --albedo R,G,B with --mfp R,G,B (or --mfp alone: the material's own albedo)
// replace σs'/σa by the inversion through --profile's total reflectance.
Material materialFromArgs(const Args& args);
// What --material, --albedo, --sigma-s/-a (all: the file's materials are not
// used), --mfp and --eta say over a mesh file's materials.
MaterialOverrides materialOverridesFromArgs(const Args& args);
// --profile's model (the default's when not given).
ProfileModel profileModelFromArgs(const Args& args);

// "point:X,Y,Z:R,G,B" or "dir:X,Y,Z:R,G,B".
Light parseLight(const std::string& spec);

// The default lights for an object of bounding-box diagonal sizeMm: a back
// light that makes thin parts glow and a weaker front fill.
std::vector<Light> defaultLights(double sizeMm);
Camera defaultCamera(double sizeMm, float fovYDegrees);

// --atlas (auto|file|build) and the atlas options matching --atlas-res.
std::string atlasMode(const Args& args);
AtlasOptions atlasOptionsFromArgs(const Args& args);

// --rotate, --mesh-up, --crease, --atlas and --atlas-res, checked (those a
// command does not take keep their defaults).
MeshOptions meshOptionsFromArgs(const Args& args);
// The options that give back `o` through meshOptionsFromArgs: --rotate,
// --mesh-up and --crease where not the default, then --atlas (--atlas-res is
// a render option: renderOptionArgs).
std::vector<std::string> meshOptionArgs(const MeshOptions& o);

// Every scene option parsed and checked (material, lights, camera, mesh
// options), the mesh not yet loaded: option errors come before slow work.
Scene parseScene(const Args& args);
// A loaded (and repaired) mesh with its atlas: a note when it is not closed,
// then turned, normalised to sizeMm and given UVs by o.atlasMode (the atlas
// cache key holds the turned positions).
Mesh atlasMesh(Mesh mesh, double sizeMm, const MeshOptions& o, AtlasStats* stats = nullptr);
// atlasMesh, then the normals the file lacks, split at o.creaseDegrees: after
// the atlas, so that neither the atlas nor its cache key depends on the
// crease (the copies share their vertex's UV).
Mesh prepareLoadedMesh(Mesh mesh, double sizeMm, const MeshOptions& o);
// Loads the mesh `spec` names (a file, builtin:NAME or a data mesh name) and
// prepares it (prepareLoadedMesh).
Mesh prepareMesh(const std::string& spec, double sizeMm, const MeshOptions& o);
// prepareMesh of --mesh, --size-mm and the mesh options; a glTF's camera
// (--camera N) and lights replace the scene's where the command line gives
// none, per kind (scene/from_file.h), turned and scaled with the mesh.
void loadSceneMesh(Scene& scene, const Args& args);
// What --eye/--target/--up, --camera, --fov and --light leave to the file.
FileViewUse fileViewUseFromArgs(const Args& args);
// For `tsis view`: the mesh `spec` names, prepared at sizeMm as
// loadSceneMesh does on the command line's scene `cli`, with its file's
// materials and (where `use` lets it) its camera.
ViewMesh loadViewMesh(const std::string& spec, double sizeMm, const Scene& cli,
                      const MeshOptions& o, const FileViewUse& use,
                      const MaterialOverrides& overrides, ProfileModel profile);
// parseScene, then loadSceneMesh.
Scene sceneFromArgs(const Args& args);
// Parsed and validated through render/render_params.h's table; a parameter
// the method does not read is an error naming the methods that do. Touches no
// device or file.
RenderOptions renderOptionsFromArgs(const Args& args);

// The options that give back, through parseScene and renderOptionsFromArgs,
// this scene's material, lights and camera on the mesh `meshSpec` at sizeMm,
// and these render options (the method's parameters and the frame-wide ones
// that differ from the defaults): every number printed exactly (the shortest
// text that parses to the same value).
std::vector<std::string> sceneArgs(const Scene& scene, const std::string& meshSpec, double sizeMm);
std::vector<std::string> renderOptionArgs(const RenderOptions& options);

}  // namespace tsis
