// PoCL keeps its compiled kernels under $XDG_CACHE_HOME/pocl (else
// $HOME/.cache/pocl) and, when it cannot create that folder (a read-only or
// missing HOME), offers no device at all. Before the first OpenCL call tsis
// checks that folder and, when it is unusable and the user did not set
// POCL_CACHE_DIR, points PoCL at a folder it can write.
#pragma once

#include <string>

namespace tsis {

// Sets POCL_CACHE_DIR to tsis' cache folder (program_cache.h) + "/pocl", else
// to $TMPDIR/tsis-pocl-<euid>, when PoCL's default is not writable; either
// only when private (util/cache_dir.h: created 0700, refused when a link, of
// another owner or writable by others). An empty POCL_CACHE_DIR is unset
// (PoCL would abort). Returns "" when PoCL can cache, else why it cannot (for
// the "no OpenCL device" message). Idempotent.
std::string preparePoclCache();

}  // namespace tsis
