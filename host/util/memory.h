// The process' own memory use, for reports that follow it over long runs
// (`tsis animate --stats`) and the tests that bound it; and the memory left
// on the machine, so that work too large for it is refused before it starts.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace tsis {

// Resident set size now (VmRSS of /proc/self/status) in MiB; 0 where the
// system does not say.
double residentMegabytes();

// Bytes this process can still take: MemAvailable (/proc/meminfo), less when
// a cgroup's limit (a container) leaves less, less when TSIS_MEMORY_LIMIT_MB
// says so (a share of a machine); nullopt where the system does not say.
std::optional<uint64_t> availableMemoryBytes();

// Throws tsis::Error "WHAT needs about N GB of memory but M GB is available"
// when `needed` exceeds `available` (unknown: no check).
void requireMemory(uint64_t needed, std::optional<uint64_t> available, const std::string& what);

}  // namespace tsis
