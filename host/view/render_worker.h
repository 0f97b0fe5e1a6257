// The thread that renders the window's frames. It owns a Renderer (its own
// OSMesa context and OpenCL queue, the same passes and methods as `tsis
// render`) and renders the newest frame asked of it, so that the window's
// thread never waits for a frame and a frame asked for while another renders
// replaces any older one still waiting.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "render/renderer.h"
#include "view/work_progress.h"

namespace tsis {

struct FrameJob {
    uint64_t id = 0;
    std::shared_ptr<const Mesh> mesh;  // the scene's mesh (shared: copied only when it changes)
    Scene scene;                       // without its mesh
    RenderOptions options;
};

struct FrameDone {
    uint64_t id = 0;
    FrameResult frame;
    std::string error;  // a failed frame: the one-line message, and no image
};

// The one-line message of the exception being handled (inside a catch):
// tsis::Error's, an OpenCL call's, any other's what().
std::string currentErrorMessage();

class RenderWorker {
  public:
    // Starts the thread and waits for its Renderer: throws the tsis::Error of
    // a missing GL context or OpenCL device. wake() runs on the worker's
    // thread whenever a frame is done.
    RenderWorker(const std::string& clDevice, const std::string& gl, std::function<void()> wake);
    ~RenderWorker();  // finishes the frame in hand, then stops
    RenderWorker(const RenderWorker&) = delete;
    RenderWorker& operator=(const RenderWorker&) = delete;

    void submit(FrameJob job);
    bool busy() const;  // a job waiting or in hand
    // The newest finished frame, once.
    std::optional<FrameDone> take();
    WorkProgress progress() const { return progress_.get(); }
    // How many times the worker prepared camera moves while idle (below).
    int preparations() const;

    // After a frame that gathered B at its pixels (a light or material
    // change, not a camera move), the worker waits this long for the next
    // job; none coming (the user let go of the light), it makes pyramid's
    // copy of B over the atlas (Renderer::prepareCameraMoves) while the frame
    // is shown, so that the first orbit costs what the next ones do.
    static constexpr std::chrono::milliseconds kPrepareAfter{150};

    // After a frame made while its object transport was fitted in the
    // background (Renderer::setBackgroundFits: the window stays interactive
    // while a new material's fit runs), the worker looks this often whether
    // the fit is done, and then makes that frame again.
    static constexpr std::chrono::milliseconds kFitPoll{20};

  private:
    void run(const std::string& clDevice, const std::string& gl);
    // Waits for the background fit: true when it is done (the frame is to be
    // made again), false when a job came first or the worker stops.
    bool waitForBackgroundFit();
    FrameDone render(const FrameJob& job);
    // Idle after `job`'s frame: prepares its camera moves unless a job comes
    // within kPrepareAfter or the worker stops.
    void prepareWhileIdle(const FrameJob& job);

    std::function<void()> wake_;
    ProgressBox progress_;
    mutable std::mutex mutex_;
    std::condition_variable changed_;
    std::optional<FrameJob> waiting_;
    bool rendering_ = false, stop_ = false;
    std::optional<FrameDone> done_;
    std::string startError_;
    bool started_ = false;
    int preparations_ = 0;
    // Owned by the thread: the renderer and the scene with its current mesh.
    std::unique_ptr<Renderer> renderer_;
    std::shared_ptr<const Mesh> mesh_;
    Scene scene_;
    std::thread thread_;
};

}  // namespace tsis
