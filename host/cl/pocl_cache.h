// PoCL keeps its compiled kernels under $XDG_CACHE_HOME/pocl (else
// $HOME/.cache/pocl) and, when it cannot create that folder (a read-only or
// missing HOME), offers no device at all. Before the first OpenCL call tsis
// checks that folder and, when it is unusable and the user did not set
// POCL_CACHE_DIR, points PoCL at a folder it can write.
#pragma once

#include <string>

namespace tsis {

// Sets POCL_CACHE_DIR to tsis' cache folder (program_cache.h) + "/pocl", else
// to a folder under the system's temporary folder, when PoCL's default is not
// writable. Returns "" when PoCL can cache, else why it cannot (for the "no
// OpenCL device" message). Idempotent.
std::string preparePoclCache();

}  // namespace tsis
