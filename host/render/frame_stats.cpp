#include "render/frame_stats.h"

#include <cmath>

namespace tsis {

void FrameStats::addStage(const std::string& name, double ms, long long bytes, double cpuMs) {
    for (Stage& s : stages)
        if (s.name == name) {
            s.ms += ms;
            if (bytes >= 0) s.bytes = (s.bytes < 0 ? 0 : s.bytes) + bytes;
            if (cpuMs >= 0) s.cpuMs = (s.cpuMs < 0 ? 0 : s.cpuMs) + cpuMs;
            return;
        }
    stages.push_back({name, ms, bytes, cpuMs});
}

void FrameStats::set(const std::string& key, Json value) {
    for (auto& [k, v] : values)
        if (k == key) {
            v = std::move(value);
            return;
        }
    values.emplace_back(key, std::move(value));
}

double FrameStats::stageMs(const std::string& name) const {
    for (const Stage& s : stages)
        if (s.name == name) return s.ms;
    return 0;
}

double FrameStats::number(const std::string& key) const {
    for (const auto& [k, v] : values)
        if (k == key) return v.is_number() ? v.get<double>() : std::nan("");
    return std::nan("");
}

void FrameStats::totalRdEvaluations() {
    const std::string key = "rd_evaluations";
    double sum = 0;
    bool parts = false;
    for (const auto& [k, v] : values) {
        if (k == key) return;
        if (v.is_number() && k.size() > key.size() && k.ends_with("_" + key)) {
            sum += v.get<double>();
            parts = true;
        }
    }
    if (parts) set(key, sum);
}

Json FrameStats::stageMsJson() const {
    Json ms = Json::object();
    for (const Stage& s : stages) ms[s.name] = s.ms;
    return ms;
}

Json FrameStats::toJson() const {
    Json root = Json::object();
    for (const auto& [k, v] : values) root[k] = v;
    Json bytes = Json::object();
    Json cpu = Json::object();
    for (const Stage& s : stages) {
        if (s.bytes >= 0) bytes[s.name] = s.bytes;
        if (s.cpuMs >= 0) cpu[s.name] = s.cpuMs;
    }
    root["ms"] = stageMsJson();
    root["bytes"] = bytes;
    root["cpu_ms"] = cpu;
    return root;
}

}  // namespace tsis
