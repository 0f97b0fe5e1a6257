#include "util/progress.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace tsis {

bool Progress::enabled() {
    const char* env = std::getenv("TSIS_PROGRESS");
    if (env && std::strcmp(env, "0") == 0) return false;
    return ::isatty(STDERR_FILENO) == 1;
}

Progress::Progress(std::string label, long long total)
    : label_(std::move(label)), total_(total), active_(enabled()) {
    start_ = last_ = std::chrono::steady_clock::now();
    if (active_) update(0);
}

Progress::~Progress() {
    finish();
}

void Progress::update(long long done) {
    if (!active_ || finished_) return;
    auto now = std::chrono::steady_clock::now();
    if (done != 0 && done < total_ && now - last_ < std::chrono::milliseconds(100)) return;
    last_ = now;
    double secs = std::chrono::duration<double>(now - start_).count();
    double frac = total_ > 0 ? static_cast<double>(done) / static_cast<double>(total_) : 1.0;
    std::fprintf(stderr, "\r%s %5.1f%% (%.1f s)   ", label_.c_str(), 100.0 * frac, secs);
    std::fflush(stderr);
}

void Progress::finish() {
    if (!active_ || finished_) return;
    update(total_);
    finished_ = true;
    std::fprintf(stderr, "\n");
}

}  // namespace tsis
