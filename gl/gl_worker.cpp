#include "gl/gl_worker.h"

#include <utility>

#include "gl/gl.h"
#include "gl/gl_context.h"

namespace tsis {

GlWorker::GlWorker(const GlContext& share) {
    std::unique_ptr<GlContext> context = share.makeShared();
    thread_ = std::thread(&GlWorker::loop, this, std::move(context));
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [this] { return ready_; });
    if (error_) {
        lock.unlock();
        thread_.join();
        std::rethrow_exception(error_);
    }
}

GlWorker::~GlWorker() {
    {
        std::lock_guard lock(mutex_);
        quit_ = true;
    }
    changed_.notify_all();
    if (thread_.joinable()) thread_.join();
}

void GlWorker::start(std::function<void()> task) {
    std::unique_lock lock(mutex_);
    // One task at a time: one started and never waited for (its caller
    // threw) runs out first; its error, if any, goes with that frame.
    changed_.wait(lock, [this] { return !busy_; });
    error_ = nullptr;
    task_ = std::move(task);
    busy_ = true;
    changed_.notify_all();
}

void GlWorker::wait() {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [this] { return !busy_; });
    if (std::exception_ptr e = std::exchange(error_, nullptr)) std::rethrow_exception(e);
}

// The context is made current, used and destroyed on this thread alone.
void GlWorker::loop(std::unique_ptr<GlContext> context) {
    try {
        context->makeCurrent();
    } catch (...) {
        std::lock_guard lock(mutex_);
        error_ = std::current_exception();
        quit_ = true;
    }
    {
        std::lock_guard lock(mutex_);
        ready_ = true;
    }
    changed_.notify_all();
    for (;;) {
        std::function<void()> task;
        {
            std::unique_lock lock(mutex_);
            changed_.wait(lock, [this] { return busy_ || quit_; });
            if (!busy_) break;
            task = std::move(task_);
        }
        std::exception_ptr error;
        try {
            task();
            glFinish();
        } catch (...) {
            error = std::current_exception();
        }
        {
            std::lock_guard lock(mutex_);
            error_ = error;
            busy_ = false;
        }
        changed_.notify_all();
    }
    context.reset();
}

WorkerSide::WorkerSide(std::string vertexFile, std::string fragmentFile,
                       std::vector<std::string> features)
    : programs_(std::make_unique<ShaderVariants>(std::move(vertexFile), std::move(fragmentFile),
                                                 std::move(features))) {}

WorkerSide::~WorkerSide() {
    if (!worker_ || (!framebuffer_ && !vertexArray_)) return;
    worker_->start([this] {
        if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
        if (vertexArray_) glDeleteVertexArrays(1, &vertexArray_);
        programs_.reset();
    });
    try {
        worker_->wait();
    } catch (const std::exception&) {  // freeing: nothing left to report to
    }
}

GLuint WorkerSide::framebuffer() {
    if (!framebuffer_) glGenFramebuffers(1, &framebuffer_);
    return framebuffer_;
}

GLuint WorkerSide::vertexArray() {
    if (!vertexArray_) glGenVertexArrays(1, &vertexArray_);
    return vertexArray_;
}

}  // namespace tsis
