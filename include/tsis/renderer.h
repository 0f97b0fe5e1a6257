// Renders frames of a Scene with typed RenderSettings, or with the render
// options by name (method, samples, width, height, …: Options). One Renderer keeps its GL context,
// OpenCL programs and light maps across frames: make it once, render many.
//
// Threads: a Renderer may be used from any thread; its frames run one at a
// time (a second thread's render() waits for the first's), its GL context
// current on the calling thread for the frame only. Renderers of their own
// render in parallel. Processes: OpenCL's and GL's threads are not copied by
// fork(), so in a child forked after a Renderer was made, render() and making
// a new Renderer throw tsis::Error at once (fork before making any, or start
// processes by spawning); the child's copy of a Renderer is then leaked.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "tsis/options.h"
#include "tsis/render_settings.h"
#include "tsis/scene.h"

namespace tsis::api {

// A linear float image, channels interleaved, row 0 = top.
struct Image {
    int width = 0, height = 0, channels = 0;
    std::vector<float> pixels;
};

struct Frame {
    int width = 0, height = 0;
    std::vector<uint8_t> rgb8;  // tone-mapped sRGB, row 0 = top
    // The AOVs `tsis render --aov` writes: radiosity and radiance (RGB),
    // position (mm) and normal (XYZ), coverage (1 channel), the flux atlas.
    Image radiosity, radiance, position, normal, coverage, fluxAtlas;
    float lavg = 0;         // log-average luminance of the covered pixels
    std::string statsJson;  // what `tsis render --stats` writes: stage timings, counts
};

class Renderer {
  public:
    // clDevice: a substring of the OpenCL device's name ("": $TSIS_CL_DEVICE,
    // else PoCL); gl: "egl", "osmesa" or "auto" (EGL when it gives a context,
    // else OSMesa; "": $TSIS_GL, else auto). Throws tsis::Error when GL or
    // OpenCL is missing.
    explicit Renderer(const std::string& clDevice = "", const std::string& gl = "");
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // The scene options among `options` are checked, not used (the scene has
    // them). cancel (optional) is called on this thread between pieces of the
    // frame's work, at most every 50 ms: true stops the frame with
    // tsis::Cancelled, and the Renderer stays usable. It is asked while
    // render() waits for another thread's frame too.
    Frame render(const Scene& scene, const Options& options = {},
                 const std::function<bool()>& cancel = {});
    // The same frame from typed settings (Options::renderSettings() gives the
    // settings of options; Scene::renderSettings() a scene's defaults). Throws
    // tsis::Error for a value out of its range or a field off its default
    // that settings.method does not read.
    Frame render(const Scene& scene, const RenderSettings& settings,
                 const std::function<bool()>& cancel = {});

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// Writes the tone-mapped frame as an 8-bit image (PNG; the format by extension).
void writeImage(const Frame& frame, const std::string& path);
// Writes a linear image (EXR).
void writeImage(const Image& image, const std::string& path);
Image readImage(const std::string& path);

}  // namespace tsis::api
