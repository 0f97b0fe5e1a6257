// The process' own memory use, for reports that follow it over long runs
// (`tsis animate --stats`) and the tests that bound it.
#pragma once

namespace tsis {

// Resident set size now (VmRSS of /proc/self/status) in MiB; 0 where the
// system does not say.
double residentMegabytes();

}  // namespace tsis
