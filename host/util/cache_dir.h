// tsis' cache folder (compiled CL programs, atlases, PoCL's kernels when its
// own folder is not writable): $TSIS_CACHE_DIR, else $XDG_CACHE_HOME/tsis,
// else $HOME/.cache/tsis; empty when none of them is set.
#pragma once

#include <string>

namespace tsis {

std::string cacheDirectory();

}  // namespace tsis
