#include "render/frame_graph.h"

#include <algorithm>
#include <set>

#include "util/error.h"
#include "util/timer.h"

namespace tsis {

void FrameGraph::addPass(Pass pass) {
    passes_.push_back(std::move(pass));
}

void FrameGraph::execute(const std::vector<std::string>& outputs, FrameStats& stats) {
    // Cull: walk backwards from the outputs, keeping passes that write a needed resource.
    std::set<std::string> needed(outputs.begin(), outputs.end());
    std::vector<bool> keep(passes_.size(), false);
    for (size_t k = passes_.size(); k-- > 0;) {
        const Pass& p = passes_[k];
        bool contributes = std::any_of(p.writes.begin(), p.writes.end(),
                                       [&](const std::string& w) { return needed.count(w) > 0; });
        if (!contributes) continue;
        keep[k] = true;
        needed.insert(p.reads.begin(), p.reads.end());
    }
    // Validate: every read of a kept pass is written by an earlier kept pass.
    std::set<std::string> written;
    for (size_t k = 0; k < passes_.size(); ++k) {
        if (!keep[k]) continue;
        for (const std::string& r : passes_[k].reads)
            if (!written.count(r))
                checkFailed(__FILE__, __LINE__,
                            concat("frame graph: pass '", passes_[k].name, "' reads '", r,
                                   "' which no earlier pass writes"));
        written.insert(passes_[k].writes.begin(), passes_[k].writes.end());
    }
    for (const std::string& o : outputs)
        if (!written.count(o))
            checkFailed(__FILE__, __LINE__, concat("frame graph: nothing writes output '", o, "'"));
    needed_.clear();
    for (size_t k = 0; k < passes_.size(); ++k)
        if (keep[k]) needed_.insert(passes_[k].reads.begin(), passes_[k].reads.end());
    executed_.clear();
    for (size_t k = 0; k < passes_.size(); ++k) {
        if (!keep[k]) continue;
        Timer t;
        passes_[k].run();
        if (!passes_[k].recordsOwnTime) stats.addStage(passes_[k].name, t.ms());
        executed_.push_back(passes_[k].name);
    }
}

}  // namespace tsis
