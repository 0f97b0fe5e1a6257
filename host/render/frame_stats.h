// What a frame cost: per-stage milliseconds, bytes across GL↔CL, counters.
// Written by --stats FILE.json.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "util/json.h"

namespace tsis {

struct FrameStats {
    struct Stage {
        std::string name;
        double ms = 0;
        long long bytes = -1;  // transfers only
        double cpuMs = -1;     // process CPU time (all threads) over the stage; -1: not measured
    };
    std::vector<Stage> stages;  // in execution order
    std::vector<std::pair<std::string, Json>> values;

    void addStage(const std::string& name, double ms, long long bytes = -1, double cpuMs = -1);
    void set(const std::string& key, Json value);
    double stageMs(const std::string& name) const;  // 0 when absent
    // A number set with set(); NaN when absent or not a number.
    double number(const std::string& key) const;
    // A method made of parts (the hybrid's global_ and local_) reports each
    // part's "<prefix>rd_evaluations"; their sum becomes "rd_evaluations".
    void totalRdEvaluations();
    Json toJson() const;
    // Each stage's ms by name: toJson()'s "ms".
    Json stageMsJson() const;
};

}  // namespace tsis
