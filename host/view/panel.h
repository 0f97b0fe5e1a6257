// The ImGui panel of `tsis view`: the settings (method, material, size, N,
// resolutions, progressive accumulation, the light's auto-orbit), the
// environment (map file, rotation, intensity), the last
// frame's cost, the reference's error, files and opening a mesh.
#pragma once

#include <optional>
#include <string>

#include "render/frame_stats.h"
#include "view/view_state.h"
#include "view/work_progress.h"

namespace tsis {

// What the panel shows but does not change.
struct PanelInfo {
    std::string mesh;  // name, triangles
    // The file's materials (fileMaterialLines), shown beside the sliders'.
    std::vector<std::string> fileMaterials;
    bool sceneMaterialUsed = true;
    double fps = 0;         // frames rendered per second, lately
    double frameMsP99 = 0;  // the session's 99th-percentile frame (renderer ms)
    int accumulated = 0;
    const FrameStats* stats = nullptr;  // the last frame's
    std::string frameError;
    WorkProgress frameProgress;  // of a frame that reports (a reference, an atlas), else empty
    bool meshLoading = false;
    WorkProgress meshProgress;
    std::string meshError;
    bool referenceRunning = false;
    WorkProgress referenceProgress;
    double referenceSeconds = 0;
    std::optional<double> relRmse;  // of the shown frame against the reference
    double heatScale = 0;           // relative error at the top of the heat map's colours
    bool referenceStale = false;    // a reference of an earlier view
    // The model against volumetric transport (render/truth_check.h).
    bool truthRunning = false;
    std::optional<double> truthError;  // pooled rel. RMSE, the reference's noise taken out
    double truthNoise = 0;
    bool truthStale = false;
    std::string status;  // the last file written, or why not
    bool statusIsError = false;
};

// What the user types into the panel; kept between frames.
struct PanelFields {
    char meshPath[512] = "";
    char envPath[512] = "";
    std::string envError;  // why the last map did not load
    char screenshotPath[512] = "tsis-view.png";
    char savePath[512] = "tsis-view-render.png";
    char aovDir[512] = "tsis-view-aov";
    bool heatmap = true;
};

// The buttons pressed this frame.
struct PanelActions {
    bool openMesh = false, reference = false, screenshot = false, save = false, aov = false;
};

// Draws the panel at x (window pixels) over the window's height, width wide;
// edits `state` in place.
PanelActions drawPanel(ViewState& state, PanelFields& fields, const PanelInfo& info, float x,
                       float width, float height);

}  // namespace tsis
