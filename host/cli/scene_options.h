// What the CLI's commands add to the scene description (description/): the
// Args shorthands its commands use, and `tsis view`'s mesh and printed line.
#pragma once

#include <string>
#include <vector>

#include "description/mesh_preparation.h"
#include "description/scene_description.h"
#include "description/scene_params.h"
#include "util/args.h"
#include "view/view_state.h"

namespace tsis {

// The material the scene options among `args` give (resolveMaterial through --profile).
Material materialFromArgs(const Args& args);
MaterialOverrides materialOverridesFromArgs(const Args& args);
// --size-mm S, checked (kMinSizeMm to kMaxSizeMm); the default for --size-mm file.
double sizeMmFromArgs(const Args& args);
// --rotate, --mesh-up, --crease, --atlas and --atlas-res, checked (those a
// command does not take keep their defaults).
MeshOptions meshOptionsFromArgs(const Args& args);
// What --eye/--target/--up, --camera, --fov and --light leave to the file.
FileViewUse fileViewUseFromArgs(const Args& args);
// The options that give back `o` through meshOptionsFromArgs: --rotate,
// --mesh-up and --crease where not the default, then --atlas (--atlas-res is
// a render option: renderOptionArgs).
std::vector<std::string> meshOptionArgs(const MeshOptions& o);

// The options that give back this scene's material (σ and η, with its preset's
// name when it is one), lights and camera on the mesh `meshSpec` at sizeMm,
// every number printed exactly: `tsis view`'s printed line, whose material is
// the panel's.
std::vector<std::string> sceneArgs(const Scene& scene, const std::string& meshSpec, double sizeMm);

// For `tsis view`: the mesh `spec` names, prepared at sizeMm as
// loadSceneMesh does on the command line's scene `cli`, with its file's
// materials and (where `use` lets it) its camera.
ViewMesh loadViewMesh(const std::string& spec, double sizeMm, const Scene& cli,
                      const MeshOptions& o, const FileViewUse& use,
                      const MaterialOverrides& overrides, ProfileModel profile);

}  // namespace tsis
