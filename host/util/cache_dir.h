// tsis' cache folder (compiled CL programs, atlases, PoCL's kernels when its
// own folder is not writable): $TSIS_CACHE_DIR, else $XDG_CACHE_HOME/tsis,
// else $HOME/.cache/tsis; empty when none of them is set.
//
// PoCL dlopen()s the kernels it finds in its cache, and program binaries are
// handed to the driver as they are: a cache folder another user can write is
// a way to run code as this user. So a folder tsis picks itself is used only
// when it is private (privateDirectory); one the user names (TSIS_CACHE_DIR,
// POCL_CACHE_DIR) is taken as given.
#pragma once

#include <string>

namespace tsis {

// Where the cache lives (no file system access).
std::string cacheDirectory();

// cacheDirectory() ready for use: a folder from $TSIS_CACHE_DIR as it is;
// one derived from XDG_CACHE_HOME or HOME made private (privateDirectory),
// else "" (no cache) with one note on stderr saying why.
std::string usableCacheDirectory();

// Creates `dir` (mode 0700; its parent must exist) or accepts it as it is when
// lstat shows a real directory (not a link) owned by the effective user that
// no one else can write; its mode is then tightened to 0700. Returns "" when
// the folder is private and writable, else why not ("it is a symbolic link",
// "it belongs to uid 65534", …).
std::string privateDirectory(const std::string& dir);

}  // namespace tsis
