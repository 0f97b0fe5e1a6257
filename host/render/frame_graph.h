// A small frame graph (after Filament's): each pass declares the resources it
// reads and writes; running is separate. execute() culls passes that do not
// contribute to the requested outputs, checks that every read was written by
// an earlier pass (or is a declared input), and times each pass.
#pragma once

#include <functional>
#include <set>
#include <string>
#include <vector>

#include "render/frame_stats.h"

namespace tsis {

class FrameGraph {
  public:
    struct Pass {
        std::string name;
        std::vector<std::string> reads, writes;
        std::function<void()> run;
        // Stage name(s) the pass records itself (CL events, byte counts); when
        // false the graph records host wall time under `name`.
        bool recordsOwnTime = false;
    };

    void addPass(Pass pass);
    // Runs the passes needed for `outputs`, in the order they were added.
    void execute(const std::vector<std::string>& outputs, FrameStats& stats);
    // Names of the passes the last execute() ran (for tests and --stats).
    const std::vector<std::string>& executed() const { return executed_; }
    // Whether a pass that execute() runs reads `resource`: valid from the
    // start of execute(), so a pass can skip work that nothing will read.
    bool isRead(const std::string& resource) const { return needed_.count(resource) > 0; }

  private:
    std::vector<Pass> passes_;
    std::set<std::string> needed_;
    std::vector<std::string> executed_;
};

}  // namespace tsis
