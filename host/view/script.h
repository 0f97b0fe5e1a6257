// `tsis view --script FILE`: UI events played back with fixed timing. Each
// command runs once the frame of everything before it is on screen (the
// first, once the start-up view's frame is) and any mesh load or reference it
// started has finished, so a script shows the same pictures on any machine,
// however fast.
//
//   # a comment; blank lines are skipped
//   frame N              N more frames (a sampling method's progressive frames accumulate)
//   wait MS              MS milliseconds with no input (a user letting go), frames done first
//   orbit DX DY          drag the camera by DX, DY pixels (left button)
//   pan DX DY            drag with the middle button
//   zoom STEPS           wheel notches (positive: closer)
//   light-drag DX DY     drag the main light (right button)
//   set NAME VALUE       a panel setting (view_state.h: material, size-mm, method, …)
//   panel on|off         show or hide the panel
//   heatmap on|off       the reference's heat map over the image
//   open-mesh SPEC       open a mesh as the panel does (an error shows in the panel)
//   reference            compute the reference of this view, then its error
//   screenshot FILE.png  the window as shown, panel included
//   save FILE.png        the rendered image alone
//   aov DIR              the current frame's AOVs (EXR) into DIR
//   close                close the window
#pragma once

#include <string>
#include <vector>

namespace tsis {

struct ScriptCommand {
    enum class Kind {
        Frame,
        Wait,
        Orbit,
        Pan,
        Zoom,
        LightDrag,
        Set,
        Panel,
        Heatmap,
        OpenMesh,
        Reference,
        Truth,
        Screenshot,
        Save,
        Aov,
        Close
    };
    Kind kind = Kind::Frame;
    int line = 0;        // in the file, for messages
    float x = 0, y = 0;  // frame: N in x; wait: MS; orbit, pan, light-drag: DX, DY; zoom: STEPS
    bool on = false;     // panel, heatmap
    std::string name, value;  // set NAME VALUE; the path of open-mesh, screenshot, save, aov
};

// Parses and checks every line (numbers, setting names and values) before
// anything runs; throws tsis::Error "FILE:LINE: ..." at the first bad one.
std::vector<ScriptCommand> parseScript(const std::string& text, const std::string& fileName);
std::vector<ScriptCommand> readScript(const std::string& path);

}  // namespace tsis
