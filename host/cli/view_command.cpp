// `tsis view [render options] [--script FILE] [--stats FILE.json] [--print-view]`
//
// Opens the window on the scene `tsis render` would render with the same
// options (host/view/viewer.h). --script plays a recorded sequence of UI
// events (host/view/script.h) instead of the mouse and keys; --print-view
// prints, when the window closes, the `tsis render` command line of the view
// it showed last; --stats writes the frame rate and the last frame's stats.
#include "cli/view_command.h"

#include <iostream>
#include <optional>

#include "cli/scene_options.h"
#include "gl/gl_context.h"
#include "util/args.h"
#include "util/error.h"
#include "util/output_set.h"
#include "view/viewer.h"

namespace tsis {

namespace {

std::vector<OptionSpec> viewSpecs() {
    std::vector<OptionSpec> specs = sceneOptionSpecs();
    specs.push_back(
        {"script", true, false,
         "FILE  play these UI events instead of the mouse and keys (docs/guide/commands.md)"});
    specs.push_back({"stats", true, false,
                     "FILE.json  on closing: frames, fps, UI updates/s, the last frame's stats"});
    specs.push_back(
        {"print-view", false, false, "on closing, print the tsis render command of the last view"});
    return specs;
}

// `s` as one POSIX shell word.
std::string shellWord(const std::string& s) {
    if (!s.empty() && s.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                          "0123456789-_.,:/+=@") == std::string::npos)
        return s;
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

}  // namespace

int runView(const std::vector<std::string>& argv) {
    const std::vector<OptionSpec> specs = viewSpecs();
    for (const std::string& a : argv)
        if (a == "--help" || a == "-h") {
            std::cout << usageText("tsis view [render options] [--script FILE] [--print-view]",
                                   specs);
            return 0;
        }
    Args args("view", specs, argv);
    if (!args.positional().empty()) fail("unexpected argument '", args.positional()[0], "'");
    // Every option and the script first, then the window, GL, CL and the mesh.
    const Scene scene = parseScene(args);
    ViewerConfig config;
    ViewState& s = config.state;
    s.meshSpec = args.getString("mesh", "builtin:default");
    s.sizeMm = s.meshSizeMm = args.getDouble("size-mm", 10.0, kMinSizeMm, kMaxSizeMm);
    s.material = scene.material;
    // The env's sun is not a light a drag moves: sceneOf adds it each frame.
    for (const Light& l : scene.lights)
        if (!l.environment) s.lights.push_back(l);
    s.env = scene.env;
    s.camera = s.home = scene.camera;
    s.options = renderOptionsFromArgs(args);
    config.clDevice = args.getString("cl-device", "");
    config.gl = args.getString("gl", "");
    parseGlChoice(config.gl);  // a bad --gl fails before the window opens
    // Every mesh the window opens is turned, its normals and its atlas made alike.
    const MeshOptions meshOptions = meshOptionsFromArgs(args);
    // The start-up mesh's file places the camera (as in tsis render); a mesh
    // opened later keeps the view the user has, and the lights are the viewer's.
    FileViewUse use = fileViewUseFromArgs(args);
    use.lights = false;
    use.lightsGivenBy = "tsis view has its own lights";
    const MaterialOverrides overrides = materialOverridesFromArgs(args);
    const ProfileModel profile = profileModelFromArgs(args);
    config.loadMesh = [meshOptions, scene, use, overrides, profile](const std::string& spec,
                                                                    double sizeMm) {
        return loadViewMesh(spec, sizeMm, scene, meshOptions, use, overrides, profile);
    };
    if (auto path = args.value("script")) config.script = readScript(*path);
    OutputSet outputs;
    const auto statsPath = args.value("stats");
    if (statsPath) outputs.add(*statsPath, ".json");

    const ViewerResult result = runViewer(std::move(config));

    if (statsPath) {
        outputs.write(*statsPath, [&](const std::filesystem::path& f) {
            writeText(f, dumpJson(result.stats) + "\n");
        });
    }
    outputs.commit();
    if (args.flag("print-view")) {
        const ViewState& v = result.state;
        std::vector<std::string> line = sceneArgs(sceneOf(v, nullptr), v.meshSpec, v.sizeMm);
        for (const std::string& a : renderOptionArgs(v.options)) line.push_back(a);
        for (const std::string& a : meshOptionArgs(meshOptions)) line.push_back(a);
        std::cout << "tsis render";
        for (const std::string& a : line) std::cout << ' ' << shellWord(a);
        std::cout << std::endl;
    }
    return 0;
}

}  // namespace tsis
