// Progress for long work: a single updating line on a terminal (stderr), and
// nothing at all when stderr is not a terminal (CI, pipes, files).
#pragma once

#include <chrono>
#include <string>

namespace tsis {

class Progress {
  public:
    Progress(std::string label, long long total);
    ~Progress();
    void update(long long done);  // cheap; redraws at most ~10 times a second
    void finish();

    static bool enabled();  // stderr is a terminal and TSIS_PROGRESS != 0

  private:
    std::string label_;
    long long total_;
    bool active_;
    bool finished_ = false;
    std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace tsis
