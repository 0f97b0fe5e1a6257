// Progress for long work, on stderr. On a terminal: a single updating line.
// Otherwise (CI, pipes, files): once the work has run for an interval (10 s,
// or TSIS_PROGRESS_INTERVAL seconds, 0 < s ≤ 86400), one line per interval from a timer
// thread, so a stage that calls update() rarely still shows it is alive, and a
// last line at finish(); work shorter than the interval prints nothing. Lines
// read `tsis: LABEL P% (T s)`, P an integer percent, T elapsed seconds.
// TSIS_PROGRESS=0 turns both off.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

namespace tsis {

// Also told of every update of the Progress objects its thread creates
// (label, fraction done in [0, 1]); called from any thread, so it must be
// cheap and thread-safe. The window of `tsis view` shows background work so.
using ProgressObserver = std::function<void(const std::string& label, double fraction)>;

// Installs an observer for the Progress objects created on this thread while it lives.
class ScopedProgressObserver {
  public:
    explicit ScopedProgressObserver(ProgressObserver observer);
    ~ScopedProgressObserver();
    ScopedProgressObserver(const ScopedProgressObserver&) = delete;
    ScopedProgressObserver& operator=(const ScopedProgressObserver&) = delete;

  private:
    ProgressObserver observer_;
    const ProgressObserver* previous_;
};

// This thread's observer (none: empty), for work it hands to another thread.
ProgressObserver currentProgressObserver();

class Progress {
  public:
    Progress(std::string label, long long total);
    ~Progress();
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;
    void update(long long done);  // cheap; thread-safe
    void finish();

    enum class Mode { Off, Terminal, Lines };
    static Mode mode();            // from TSIS_PROGRESS and whether stderr is a terminal
    static bool enabled();         // mode() != Off
    static double lineInterval();  // seconds between lines in Lines mode
    // Throws tsis::Error when TSIS_PROGRESS_INTERVAL is set but is not a
    // number of seconds in (0, 86400] (the CLI checks it first; lineInterval()
    // then never meets a bad value, else it takes the default).
    static void checkEnvironment();

  private:
    void printLine(long long done);
    void tick();

    void notify(long long done);

    std::string label_;
    long long total_;
    ProgressObserver observer_;  // the creating thread's (ScopedProgressObserver), or none
    Mode mode_;
    std::atomic<long long> done_{0};
    std::atomic<bool> finished_{false};
    bool printed_ = false;  // Lines mode: a line went out (guarded by mutex_)
    std::chrono::steady_clock::time_point start_, last_;
    std::mutex mutex_;
    std::condition_variable stop_;
    std::thread ticker_;
};

}  // namespace tsis
