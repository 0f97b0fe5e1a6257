// Stopping long work early: a frame's caller (Ctrl-C in Python, a C++ caller's
// own flag) asks through a Cancel; the work asks it whether to stop between
// pieces (a pass, a chunk of pixels) and ends with tsis::Cancelled.
#pragma once

#include <atomic>
#include <chrono>
#include <functional>
#include <thread>

namespace tsis {

class Cancel {
  public:
    // How often `poll` is asked at most.
    static constexpr std::chrono::milliseconds kPollInterval{50};

    // poll: asked on the thread that made this Cancel only (Python's signal
    // check must run there), at most every kPollInterval; true stops the work.
    // It must not throw (one that does counts as true).
    explicit Cancel(std::function<bool()> poll = {});
    Cancel(const Cancel&) = delete;
    Cancel& operator=(const Cancel&) = delete;

    // From any thread.
    void request() noexcept { requested_.store(true, std::memory_order_relaxed); }
    // Whether to stop: polls on the making thread (when due), else reads what
    // was asked. Cheap, never throws, from any thread: for inner loops, which
    // then return early and leave the throw to check().
    bool stopping() noexcept;
    // Throws tsis::Cancelled when stopping().
    void check();

  private:
    std::function<bool()> poll_;
    std::thread::id owner_;
    std::chrono::steady_clock::time_point nextPoll_;  // the owner's only
    std::atomic<bool> requested_{false};
};

}  // namespace tsis
