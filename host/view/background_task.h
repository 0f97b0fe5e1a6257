// One piece of long work (a mesh's atlas, a reference render) on its own
// thread, so that the window stays responsive; its progress and result are
// polled by the window's thread.
#pragma once

#include <atomic>
#include <exception>
#include <functional>
#include <thread>
#include <utility>

#include "view/thread_priority.h"
#include "view/work_progress.h"

namespace tsis {

template <typename T>
class BackgroundTask {
  public:
    // Starts work() now; wake() runs on the task's thread when it has finished.
    BackgroundTask(std::function<T()> work, std::function<void()> wake) {
        thread_ = std::thread([this, work = std::move(work), wake = std::move(wake)] {
            lowerThisThreadPriority();
            {
                ScopedProgressObserver observer(progress_.observer());
                try {
                    result_ = work();
                } catch (...) {
                    error_ = std::current_exception();
                }
            }
            done_ = true;
            if (wake) wake();
        });
    }
    // Waits for the work: it cannot be stopped half-way.
    ~BackgroundTask() { thread_.join(); }
    BackgroundTask(const BackgroundTask&) = delete;
    BackgroundTask& operator=(const BackgroundTask&) = delete;

    bool done() const { return done_; }
    WorkProgress progress() const { return progress_.get(); }
    // After done(): the result, or the work's exception rethrown.
    T take() {
        if (error_) std::rethrow_exception(error_);
        return std::move(result_);
    }

  private:
    ProgressBox progress_;
    T result_{};
    std::exception_ptr error_;
    std::atomic<bool> done_{false};
    std::thread thread_;  // last: starts after the members it uses exist
};

}  // namespace tsis
