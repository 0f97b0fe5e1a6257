#include "util/cancel.h"

#include "util/error.h"

namespace tsis {

Cancel::Cancel(std::function<bool()> poll)
    : poll_(std::move(poll)), owner_(std::this_thread::get_id()) {}

bool Cancel::stopping() noexcept {
    if (requested_.load(std::memory_order_relaxed)) return true;
    if (!poll_ || std::this_thread::get_id() != owner_) return false;
    const auto now = std::chrono::steady_clock::now();
    if (now < nextPoll_) return false;
    nextPoll_ = now + kPollInterval;
    bool stop = true;
    try {
        stop = poll_();
    } catch (...) {
    }
    if (stop) request();
    return stop;
}

void Cancel::check() {
    if (stopping()) throw Cancelled();
}

}  // namespace tsis
