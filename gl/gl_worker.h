// A thread with a GL context of its own that shares the caller's objects.
// llvmpipe sets up a draw's triangles on the thread that issues it (only the
// rasterisation is spread over its threads), so two mesh passes into
// different targets overlap only when two threads issue them
// (docs/design.md §11).
#pragma once

#include <condition_variable>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>

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
    // at once. Framebuffers and vertex arrays are the worker context's own:
    // a task makes (and frees) those it draws with.
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

}  // namespace tsis
