#include "util/memory.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "util/error.h"

namespace tsis {

double residentMegabytes() {
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);)
        if (line.rfind("VmRSS:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;  // kB
    return 0.0;
}

namespace {

// The first number in `file`, if it holds one ("max" does not).
std::optional<uint64_t> numberIn(const char* file) {
    std::ifstream in(file);
    unsigned long long v = 0;
    if (in >> v) return v;
    return std::nullopt;
}

std::string gigabytes(uint64_t bytes) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f GB", bytes / 1e9);
    return buf;
}

}  // namespace

std::optional<uint64_t> availableMemoryBytes() {
    std::optional<uint64_t> avail;
    std::ifstream meminfo("/proc/meminfo");
    for (std::string line; std::getline(meminfo, line);)
        if (line.rfind("MemAvailable:", 0) == 0) avail = std::stoull(line.substr(13)) * 1024;
    auto lower = [&](std::optional<uint64_t> limit, std::optional<uint64_t> used) {
        if (!limit || !used) return;
        const uint64_t left = *limit > *used ? *limit - *used : 0;
        if (!avail || left < *avail) avail = left;
    };
    // This process' memory cgroup: "0::/PATH" (v2) or "N:memory:/PATH" (v1).
    std::ifstream groups("/proc/self/cgroup");
    for (std::string line; std::getline(groups, line);) {
        std::string dir;
        if (line.rfind("0::", 0) == 0) {
            dir = "/sys/fs/cgroup" + line.substr(3);
            lower(numberIn((dir + "/memory.max").c_str()),
                  numberIn((dir + "/memory.current").c_str()));
        } else if (const size_t at = line.find(":memory:"); at != std::string::npos) {
            dir = "/sys/fs/cgroup/memory" + line.substr(at + 8);
            lower(numberIn((dir + "/memory.limit_in_bytes").c_str()),
                  numberIn((dir + "/memory.usage_in_bytes").c_str()));
        }
    }
    if (const char* env = std::getenv("TSIS_MEMORY_LIMIT_MB"); env && *env) {
        char* end = nullptr;
        const double mb = std::strtod(env, &end);
        if (end == env || *end != '\0' || !(mb >= 0 && mb < 1e12))
            fail("TSIS_MEMORY_LIMIT_MB='", env, "' is not a number of megabytes");
        const uint64_t limit = static_cast<uint64_t>(mb * 1e6);
        if (!avail || limit < *avail) avail = limit;
    }
    return avail;
}

void requireMemory(uint64_t needed, std::optional<uint64_t> available, const std::string& what) {
    if (available && needed > *available)
        fail(what, " needs about ", gigabytes(needed), " of memory but ", gigabytes(*available),
             " is available");
}

}  // namespace tsis
