#include "util/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>

#include "util/error.h"

namespace tsis {

namespace {

thread_local const ProgressObserver* tCurrentObserver = nullptr;

constexpr double kDefaultInterval = 10.0;
constexpr double kMaxInterval = 86400.0;  // a day; more would overflow the timer's wait

// TSIS_PROGRESS_INTERVAL's seconds: the default when unset or empty, none when not valid.
std::optional<double> intervalFromEnvironment() {
    const char* env = std::getenv("TSIS_PROGRESS_INTERVAL");
    if (!env || !*env) return kDefaultInterval;
    char* end = nullptr;
    const double s = std::strtod(env, &end);
    if (end == env || *end != '\0' || !(s > 0 && s <= kMaxInterval)) return std::nullopt;
    return s;
}

}  // namespace

ProgressObserver currentProgressObserver() {
    return tCurrentObserver ? *tCurrentObserver : ProgressObserver();
}

ScopedProgressObserver::ScopedProgressObserver(ProgressObserver observer)
    : observer_(std::move(observer)), previous_(tCurrentObserver) {
    tCurrentObserver = &observer_;
}

ScopedProgressObserver::~ScopedProgressObserver() {
    tCurrentObserver = previous_;
}

Progress::Mode Progress::mode() {
    const char* env = std::getenv("TSIS_PROGRESS");
    if (env && std::strcmp(env, "0") == 0) return Mode::Off;
    return ::isatty(STDERR_FILENO) == 1 ? Mode::Terminal : Mode::Lines;
}

bool Progress::enabled() {
    return mode() != Mode::Off;
}

double Progress::lineInterval() {
    return intervalFromEnvironment().value_or(kDefaultInterval);
}

void Progress::checkEnvironment() {
    if (!intervalFromEnvironment())
        fail("TSIS_PROGRESS_INTERVAL='", std::getenv("TSIS_PROGRESS_INTERVAL"),
             "' is not a number of seconds in (0, ", kMaxInterval, "]");
}

Progress::Progress(std::string label, long long total)
    : label_(std::move(label)),
      total_(total),
      observer_(tCurrentObserver ? *tCurrentObserver : ProgressObserver()),
      mode_(mode()) {
    notify(0);
    start_ = last_ = std::chrono::steady_clock::now();
    if (mode_ == Mode::Terminal) update(0);
    if (mode_ == Mode::Lines) ticker_ = std::thread([this] { tick(); });
}

Progress::~Progress() {
    finish();
}

void Progress::printLine(long long done) {
    const double secs =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double frac = total_ > 0 ? std::clamp(double(done) / double(total_), 0.0, 1.0) : 1.0;
    std::fprintf(stderr, "tsis: %s %d%% (%.0f s)\n", label_.c_str(), int(100.0 * frac), secs);
    std::fflush(stderr);
    printed_ = true;
}

void Progress::tick() {
    const auto interval = std::chrono::duration<double>(lineInterval());
    std::unique_lock lock(mutex_);
    while (!stop_.wait_for(lock, interval, [&] { return finished_.load(); }))
        printLine(done_.load());
}

void Progress::notify(long long done) {
    if (observer_)
        observer_(label_, total_ > 0 ? std::clamp(double(done) / double(total_), 0.0, 1.0) : 1.0);
}

void Progress::update(long long done) {
    done_.store(done);
    notify(done);
    if (mode_ != Mode::Terminal || finished_) return;
    std::lock_guard lock(mutex_);
    auto now = std::chrono::steady_clock::now();
    if (done != 0 && done < total_ && now - last_ < std::chrono::milliseconds(100)) return;
    last_ = now;
    double secs = std::chrono::duration<double>(now - start_).count();
    double frac = total_ > 0 ? static_cast<double>(done) / static_cast<double>(total_) : 1.0;
    std::fprintf(stderr, "\r%s %5.1f%% (%.1f s)   ", label_.c_str(), 100.0 * frac, secs);
    std::fflush(stderr);
}

void Progress::finish() {
    if (finished_) return;
    notify(total_);
    if (mode_ == Mode::Off) {
        finished_ = true;
        return;
    }
    if (mode_ == Mode::Terminal) {
        update(total_);
        finished_ = true;
        std::fprintf(stderr, "\n");
        return;
    }
    {
        std::lock_guard lock(mutex_);
        finished_ = true;
    }
    stop_.notify_all();
    if (ticker_.joinable()) ticker_.join();
    std::lock_guard lock(mutex_);
    if (printed_) printLine(total_);
}

}  // namespace tsis
