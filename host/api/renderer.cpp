#include "tsis/renderer.h"

#include <filesystem>
#include <functional>
#include <mutex>

#include "api/api_internal.h"
#include "description/scene_params.h"
#include "image/image_io.h"
#include "render/render_params.h"
#include "render/renderer.h"
#include "util/args.h"
#include "util/fork_guard.h"
#include "util/json.h"
#include "util/output_set.h"

namespace tsis::api {

namespace {

Image fromInternal(ImageF&& image) {
    return {image.width, image.height, image.channels, std::move(image.pixels)};
}

}  // namespace

// One frame at a time, from whichever thread calls: the GL context is made
// current on the caller's thread for the frame and released after it.
struct Renderer::Impl {
    Impl(const std::string& clDevice, const std::string& gl) : renderer(clDevice, gl) {
        renderer.releaseGl();
    }
    std::timed_mutex frame;
    tsis::Renderer renderer;
};

Renderer::Renderer(const std::string& clDevice, const std::string& gl)
    : impl_(guarded([&] {
          guardForks();
          return std::make_unique<Impl>(clDevice, gl);
      })) {}

Renderer::~Renderer() {
    // In a forked child its GL and CL wait on threads that are not there.
    if (impl_ && impl_->renderer.forkedAway()) {
        (void)impl_.release();
        return;
    }
    if (impl_) {
        const std::lock_guard wait(impl_->frame);  // another thread's frame ends first
    }
}

Frame Renderer::render(const Scene& scene, const Options& options,
                       const std::function<bool()>& cancel) {
    const Args args("render", sceneOptionSpecs(), options.args());
    // A scene option would do nothing here: the scene has its own.
    for (const SceneParam& p : sceneParams())
        if (args.has(p.name))
            fail("Renderer::render: option --", p.name, " is the scene's: set it on the Scene");
    for (const char* own : {"cl-device", "gl"})
        if (args.has(own))
            fail("Renderer::render: option --", own, " is the Renderer's: give it when making one");
    RenderSettings settings = guarded([&] { return renderOptionsFromArgs(args); });
    if (!args.has("exposure")) settings.exposure = scene.renderSettings().exposure;
    return render(scene, settings, cancel);
}

Frame Renderer::render(const Scene& scene, const RenderSettings& settings,
                       const std::function<bool()>& cancel) {
    RenderOptions ro = settings;
    guarded([&] {
        validateRenderOptions(ro);
        checkParamsRead(ro);
    });
    ro.keepAovs = true;
    const std::optional<tsis::Scene> inverted = scene.impl_->withProfile(ro.profile);
    const tsis::Scene& s = inverted ? *inverted : scene.impl_->scene;
    Cancel stop(cancel);
    FrameResult r = guarded([&] {
        // Waiting for another thread's frame is cancelled as a frame is.
        std::unique_lock lock(impl_->frame, std::defer_lock);
        while (!lock.try_lock_for(Cancel::kPollInterval))
            if (cancel) stop.check();
        struct Release {
            tsis::Renderer& r;
            ~Release() { r.releaseGl(); }
        } release{impl_->renderer};
        return impl_->renderer.render(s, ro, cancel ? &stop : nullptr);
    });
    Frame f;
    f.width = r.width;
    f.height = r.height;
    f.rgb8 = std::move(r.rgb8);
    f.radiosity = fromInternal(std::move(r.radiosity));
    f.radiance = fromInternal(std::move(r.radiance));
    f.position = fromInternal(std::move(r.position));
    f.normal = fromInternal(std::move(r.normal));
    f.coverage = fromInternal(std::move(r.coverage));
    f.fluxAtlas = fromInternal(std::move(r.fluxAtlas));
    f.lavg = r.lavg;
    Json j = r.stats.toJson();
    j["mesh"] = s.mesh.name;
    j["material"] = s.material.name;
    j["lavg"] = r.lavg;
    f.statsJson = dumpJson(j);
    return f;
}

namespace {

// As the CLI writes its outputs: through a temporary, checked, renamed into
// place only when whole (util/output_set.h).
void writeOutput(const std::string& path,
                 const std::function<void(const std::filesystem::path&)>& write) {
    OutputSet outputs;
    outputs.add(path, ".png");
    requireImageFormat(outputs, path);
    outputs.write(path, write);
    outputs.commit();
}

}  // namespace

void writeImage(const Frame& frame, const std::string& path) {
    writeOutput(path, [&](const std::filesystem::path& f) {
        writeImage8(f.string(), frame.width, frame.height, 3, frame.rgb8);
    });
}

void writeImage(const Image& image, const std::string& path) {
    writeOutput(path, [&](const std::filesystem::path& f) {
        writeImageF(f.string(), {image.width, image.height, image.channels, image.pixels});
    });
}

Image readImage(const std::string& path) {
    return fromInternal(readImageF(path));
}

}  // namespace tsis::api
