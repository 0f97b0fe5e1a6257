#include "render/frame_graph.h"

#include <algorithm>

#include "util/error.h"
#include "util/timer.h"

namespace tsis {

int FrameGraph::addResource(std::string name, void* value, std::shared_ptr<void> owned,
                            bool imported) {
    resources_.push_back({std::move(name), value, std::move(owned), imported});
    return static_cast<int>(resources_.size()) - 1;
}

void FrameGraph::addPass(std::string name, const std::function<void(Builder&)>& setup,
                         std::function<void(Resources&)> run) {
    Builder b;
    setup(b);
    for (int r : b.reads_) TSIS_CHECK(r >= 0 && r < static_cast<int>(resources_.size()));
    for (int w : b.writes_) TSIS_CHECK(w >= 0 && w < static_cast<int>(resources_.size()));
    passes_.push_back({std::move(name), std::move(b.reads_), std::move(b.writes_), std::move(run)});
}

void* FrameGraph::resolve(size_t pass, int index, bool write) const {
    const Pass& p = passes_[pass];
    const std::vector<int>& declared = write ? p.writes : p.reads;
    // A pass may read what it writes (an accumulation into its output).
    const bool ok = std::count(declared.begin(), declared.end(), index) > 0 ||
                    (!write && std::count(p.writes.begin(), p.writes.end(), index) > 0);
    if (!ok)
        checkFailed(
            __FILE__, __LINE__,
            concat("frame graph: pass '", p.name, "' ", write ? "writes" : "reads", " '",
                   resources_.at(static_cast<size_t>(index)).name, "' without declaring it"));
    return resources_[static_cast<size_t>(index)].value;
}

void FrameGraph::executeIndices(FrameStats& stats, const std::vector<int>& outputs) {
    stats_ = &stats;
    const size_t n = resources_.size();
    // Cull: walk backwards from the outputs, keeping passes that write a needed resource.
    std::vector<bool> needed(n, false);
    for (int o : outputs) needed.at(static_cast<size_t>(o)) = true;
    std::vector<bool> keep(passes_.size(), false);
    for (size_t k = passes_.size(); k-- > 0;) {
        const Pass& p = passes_[k];
        if (!std::any_of(p.writes.begin(), p.writes.end(),
                         [&](int w) { return needed[static_cast<size_t>(w)]; }))
            continue;
        keep[k] = true;
        for (int r : p.reads) needed[static_cast<size_t>(r)] = true;
    }
    // Validate: every read of a kept pass is written by an earlier kept pass.
    std::vector<bool> written(n, false);
    for (size_t r = 0; r < n; ++r) written[r] = resources_[r].imported;
    for (size_t k = 0; k < passes_.size(); ++k) {
        if (!keep[k]) continue;
        for (int r : passes_[k].reads)
            if (!written[static_cast<size_t>(r)])
                checkFailed(__FILE__, __LINE__,
                            concat("frame graph: pass '", passes_[k].name, "' reads '",
                                   resources_[static_cast<size_t>(r)].name,
                                   "' which no earlier pass writes"));
        for (int w : passes_[k].writes) written[static_cast<size_t>(w)] = true;
    }
    for (int o : outputs)
        if (!written[static_cast<size_t>(o)])
            checkFailed(__FILE__, __LINE__,
                        concat("frame graph: nothing writes output '",
                               resources_[static_cast<size_t>(o)].name, "'"));
    needed_.assign(n, false);
    for (size_t k = 0; k < passes_.size(); ++k)
        if (keep[k])
            for (int r : passes_[k].reads) needed_[static_cast<size_t>(r)] = true;
    kept_ = keep;
    executed_.clear();
    for (size_t k = 0; k < passes_.size(); ++k) {
        if (!keep[k]) continue;
        if (cancel_) cancel_->check();
        Resources res(*this, k);
        Timer t;
        CpuTimer cpu;
        passes_[k].run(res);
        const double wall = t.ms();
        stats.addStage(passes_[k].name, res.deviceMs_ >= 0 ? res.deviceMs_ : wall, res.bytes_,
                       cpu.ms());
        executed_.push_back(passes_[k].name);
    }
}

Json FrameGraph::describe() const {
    auto names = [&](const std::vector<int>& indices) {
        Json list = Json::array();
        for (int i : indices) list.push_back(resources_[static_cast<size_t>(i)].name);
        return list;
    };
    Json passes = Json::array();
    for (size_t k = 0; k < passes_.size(); ++k)
        passes.push_back({{"name", passes_[k].name},
                          {"reads", names(passes_[k].reads)},
                          {"writes", names(passes_[k].writes)},
                          {"culled", k >= kept_.size() || !kept_[k]}});
    return passes;
}

}  // namespace tsis
