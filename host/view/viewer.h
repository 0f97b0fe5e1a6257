// `tsis view`: the window's loop. The window's thread handles input, the
// panel and presenting; frames render on a RenderWorker's thread, the
// start-up mesh, meshes opened later and reference renders each on a
// BackgroundTask's, so no long work blocks the window.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "util/json.h"
#include "view/script.h"
#include "view/view_state.h"

namespace tsis {

struct ViewerConfig {
    ViewState state;  // the start-up view; its mesh (state.meshSpec) is loaded by the viewer
    // Loads, normalises to sizeMm and prepares (normals, atlas) the mesh a
    // spec names, with its file's materials and camera.
    std::function<ViewMesh(const std::string& spec, double sizeMm)> loadMesh;
    std::string clDevice;
    std::string gl;                                    // --gl (gl/gl_context.h)
    std::optional<std::vector<ScriptCommand>> script;  // played instead of the mouse and keys
};

struct ViewerResult {
    ViewState state;  // the view when the window closed
    // frames (rendered), fps (frames after the first per second), ui_updates
    // and ui_updates_per_s, min_ui_updates_per_s_while_busy (the slowest
    // second while a mesh loaded or a reference rendered), last_frame (its
    // --stats of `tsis render`).
    Json stats;
};

// Opens the window and runs it until it is closed. Throws tsis::Error when
// there is no display, GL context or OpenCL device, when the start-up mesh
// does not load, or when a script's file cannot be written.
ViewerResult runViewer(ViewerConfig config);

}  // namespace tsis
