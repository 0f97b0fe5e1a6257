// The progress of work on another thread, as the window shows it: the label
// and fraction of the latest Progress (util/progress.h) that thread made.
#pragma once

#include <mutex>
#include <string>

#include "util/progress.h"

namespace tsis {

struct WorkProgress {
    std::string label;  // empty until the work reports
    double fraction = 0;
};

// Shared between the working thread (observer()) and the window (get()).
class ProgressBox {
  public:
    ProgressObserver observer() {
        return [this](const std::string& label, double fraction) {
            std::lock_guard lock(mutex_);
            value_ = {label, fraction};
        };
    }
    WorkProgress get() const {
        std::lock_guard lock(mutex_);
        return value_;
    }
    void clear() {
        std::lock_guard lock(mutex_);
        value_ = {};
    }

  private:
    mutable std::mutex mutex_;
    WorkProgress value_;
};

}  // namespace tsis
