// A thread with a GL context of its own that shares the caller's objects.
// llvmpipe sets up a draw's triangles on the thread that issues it (only the
// rasterisation is spread over its threads), so two mesh passes into
// different targets overlap only when two threads issue them
// (docs/design.md §11).
#pragma once

#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "gl/gl.h"
#include "gl/shader.h"

namespace tsis {

class GlContext;

class GlWorker {
  public:
    // Throws tsis::Error "no GL context: ..." when no shared context can be
    // made current on the new thread.
    explicit GlWorker(const GlContext& share);
    ~GlWorker();
    GlWorker(const GlWorker&) = delete;
    GlWorker& operator=(const GlWorker&) = delete;

    // Runs `task` on the worker's thread, its context current, and returns
    // at once (after the task before, if still running). Framebuffers and
    // vertex arrays are the worker context's own: WorkerSide.
    void start(std::function<void()> task);
    // Waits for the task started last and its GL commands (glFinish), so that
    // what it drew may be read in the caller's context; rethrows its error.
    void wait();

  private:
    void loop(std::unique_ptr<GlContext> context);

    std::mutex mutex_;
    std::condition_variable changed_;
    std::function<void()> task_;
    bool busy_ = false, quit_ = false, ready_ = false;
    std::exception_ptr error_;
    std::thread thread_;
};

// Whether a pass that sets up `triangles` (back faces culled: those left)
// gains by running on a worker beside another: llvmpipe's per-triangle setup
// runs on the issuing thread, its rasterisation on threads of its own. With
// many triangles the setup is the bound and a second thread overlaps it
// (bunny00, 75K: light views 14.2 -> 11.4 ms, the G-buffers 17.6 -> 14.6);
// with few the rasterisation already fills the cores and a second context's
// threads only compete (the default scene, 24K after culling: +0.8 ms).
constexpr size_t kWorkerMinTriangles = 30000;

// A pass' own objects on a GlWorker's thread: a framebuffer and a vertex
// array of the worker's context (neither is shared between contexts) and its
// programs (shared, but a program's uniforms are one set: the caller's thread
// sets its own copy's meanwhile). Made there on first use; freed there.
class WorkerSide {
  public:
    WorkerSide(std::string vertexFile, std::string fragmentFile,
               std::vector<std::string> features = {});
    ~WorkerSide();
    WorkerSide(const WorkerSide&) = delete;
    WorkerSide& operator=(const WorkerSide&) = delete;

    // Null: the pass draws on the caller's thread. Set before the first use.
    void setWorker(GlWorker* worker, size_t minTriangles = kWorkerMinTriangles) {
        worker_ = worker;
        minTriangles_ = minTriangles;
    }
    GlWorker* worker() const { return worker_; }
    // The worker, when a pass of `triangles` (set up) pays there; else null.
    GlWorker* workerFor(size_t triangles) const {
        return triangles >= minTriangles_ ? worker_ : nullptr;
    }
    // On the worker's thread only.
    GLuint framebuffer();
    GLuint vertexArray();
    const ShaderProgram& program(unsigned features = 0) { return programs_->get(features); }

  private:
    GlWorker* worker_ = nullptr;
    size_t minTriangles_ = kWorkerMinTriangles;
    std::unique_ptr<ShaderVariants> programs_;
    GLuint framebuffer_ = 0, vertexArray_ = 0;
};

}  // namespace tsis
