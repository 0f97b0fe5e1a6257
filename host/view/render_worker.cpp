#include "view/render_worker.h"

#include "util/error.h"
#include "view/thread_priority.h"

namespace tsis {

std::string currentErrorMessage() {
    try {
        throw;
    } catch (const cl::Error& e) {
        return concat("OpenCL call ", e.what(), " failed with code ", e.err());
    } catch (const std::exception& e) {
        return e.what();
    } catch (...) {
        return "unknown error";
    }
}

RenderWorker::RenderWorker(const std::string& clDevice, const std::string& gl,
                           std::function<void()> wake)
    : wake_(std::move(wake)) {
    thread_ = std::thread([this, clDevice, gl] { run(clDevice, gl); });
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return started_; });
    if (!startError_.empty()) {
        lock.unlock();
        thread_.join();
        throw Error(startError_);
    }
}

RenderWorker::~RenderWorker() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
    }
    changed_.notify_all();
    thread_.join();
}

void RenderWorker::submit(FrameJob job) {
    {
        std::lock_guard lock(mutex_);
        waiting_ = std::move(job);
    }
    changed_.notify_all();
}

bool RenderWorker::busy() const {
    std::lock_guard lock(mutex_);
    return waiting_.has_value() || rendering_;
}

std::optional<FrameDone> RenderWorker::take() {
    std::lock_guard lock(mutex_);
    std::optional<FrameDone> out = std::move(done_);
    done_.reset();
    return out;
}

int RenderWorker::preparations() const {
    std::lock_guard lock(mutex_);
    return preparations_;
}

FrameDone RenderWorker::render(const FrameJob& job) {
    FrameDone done;
    done.id = job.id;
    try {
        if (job.mesh != mesh_) {
            mesh_ = job.mesh;
            scene_.mesh = *mesh_;
        }
        scene_.material = job.scene.material;
        scene_.objectMaterials = job.scene.objectMaterials;
        scene_.lights = job.scene.lights;
        scene_.env = job.scene.env;
        scene_.camera = job.scene.camera;
        done.frame = renderer_->render(scene_, job.options);
    } catch (...) {
        done.error = currentErrorMessage();
    }
    return done;
}

void RenderWorker::prepareWhileIdle(const FrameJob& job) {
    {
        std::unique_lock lock(mutex_);
        if (changed_.wait_for(lock, kPrepareAfter, [&] { return stop_ || waiting_.has_value(); }))
            return;
        rendering_ = true;
    }
    bool prepared = false;
    try {
        prepared = renderer_->prepareCameraMoves(scene_, job.options);
    } catch (...) {  // the next frame meets the same error and shows it
    }
    progress_.clear();
    std::lock_guard lock(mutex_);
    rendering_ = false;
    preparations_ += prepared ? 1 : 0;
}

bool RenderWorker::waitForBackgroundFit() {
    std::unique_lock lock(mutex_);
    while (!changed_.wait_for(lock, kFitPoll, [&] { return stop_ || waiting_.has_value(); })) {
        if (!renderer_->backgroundFitReady()) continue;
        rendering_ = true;
        return true;
    }
    return false;
}

void RenderWorker::run(const std::string& clDevice, const std::string& gl) {
    lowerThisThreadPriority();
    // The Renderer is made here: its GL context is current on this thread only.
    {
        std::lock_guard lock(mutex_);
        try {
            renderer_ = std::make_unique<Renderer>(clDevice, gl);
            renderer_->setBackgroundFits(true);
        } catch (...) {
            startError_ = currentErrorMessage();
        }
        started_ = true;
    }
    changed_.notify_all();
    if (!renderer_) return;
    ScopedProgressObserver observer(progress_.observer());
    for (;;) {
        FrameJob job;
        {
            std::unique_lock lock(mutex_);
            changed_.wait(lock, [&] { return stop_ || waiting_.has_value(); });
            if (stop_) break;
            job = std::move(*waiting_);
            waiting_.reset();
            rendering_ = true;
        }
        // A frame made while its transport was fitted in the background is
        // made again once the fit is done, unless a new job comes first.
        bool again = true;
        while (again) {
            FrameDone done = render(job);
            progress_.clear();
            const bool atPixels =
                done.error.empty() && done.frame.stats.number("pyramid_from_atlas") == 0;
            const bool pending =
                done.error.empty() && done.frame.stats.number("transport_pending") == 1;
            {
                std::lock_guard lock(mutex_);
                done_ = std::move(done);
                rendering_ = false;
            }
            if (wake_) wake_();
            again = pending && waitForBackgroundFit();
            if (!again && !pending && atPixels) prepareWhileIdle(job);
        }
    }
    renderer_.reset();  // on the thread whose context it is
}

}  // namespace tsis
