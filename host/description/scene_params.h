// The scene's options, each declared once as render/render_params.h declares
// the render's: its name, help, how its text sets a SceneDescription and how
// a description writes it back. `tsis render`'s specs and help, the parse of
// a command line into a description, and the replay of a scene as options
// (sceneArgs) are all made from this table.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "description/scene_description.h"
#include "render/render_options.h"
#include "util/args.h"

namespace tsis {

struct SceneParam {
    std::string name;  // the option without dashes: "size-mm"
    std::string help;  // "S|file  bounding-box diagonal in mm ..."
    bool flag = false;
    bool repeatable = false;
    // Parses `value` into the description; tsis::Error naming --name when it
    // is malformed or out of range. A repeatable adds one more.
    std::function<void(SceneDescription&, const std::string& value)> set;
    // The values as typed, each the shortest text that parses back to exactly
    // the same value; empty when the description does not give it.
    std::function<std::vector<std::string>(const SceneDescription&)> text;
};

const std::vector<SceneParam>& sceneParams();
// nullptr when no row has this name.
const SceneParam* findSceneParam(const std::string& name);

// Every option a command that renders takes: the scene's, --method, the
// render parameters (render/render_params.h), --cl-device and --gl.
const std::vector<OptionSpec>& sceneOptionSpecs();

// The description the scene options among `args` give, each value checked.
SceneDescription sceneDescriptionFromArgs(const Args& args);
// The options that give back `d` through sceneDescriptionFromArgs.
std::vector<std::string> descriptionArgs(const SceneDescription& d);

// --profile's model (the default's when not given).
ProfileModel profileModelFromArgs(const Args& args);
// "point:X,Y,Z:R,G,B" or "dir:X,Y,Z:R,G,B".
Light parseLight(const std::string& spec);
// The --light text of `l`, every number exact: parseLight gives `l` back.
std::string lightText(const Light& l);

// The scene of the scene options among `args`, the mesh not yet loaded
// (placedScene): option errors come before slow work.
Scene parseScene(const Args& args);
// loadSceneMesh of the description `args` give.
void loadSceneMesh(Scene& scene, const Args& args);
// parseScene, then loadSceneMesh.
Scene sceneFromArgs(const Args& args);
// Parsed and validated through render/render_params.h's table; a parameter
// the method does not read is an error naming the methods that do. Touches no
// device or file.
RenderOptions renderOptionsFromArgs(const Args& args);

// The options that give back, through parseScene and renderOptionsFromArgs,
// this scene's lights and camera as they were used (a file's included) on
// the description `d`'s mesh, its material as `d` gives it (none: the
// file's materials stay the file's), and these render options (the method's
// parameters and the frame-wide ones that differ from the defaults): every
// number printed exactly.
std::vector<std::string> sceneArgs(const Scene& scene, const SceneDescription& d);
std::vector<std::string> renderOptionArgs(const RenderOptions& options);

}  // namespace tsis
