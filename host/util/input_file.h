// Inputs tsis reads whole (meshes, glTF buffers, images to compare) must be
// regular files: a FIFO would block the read forever and a device such as
// /dev/zero never ends, so both are refused at once, before any byte is read.
#pragma once

#include <string>

namespace tsis {

// "" when `path` (links followed) is a regular file, else what it is instead
// ("is a directory", "is a FIFO, not a regular file", or why it cannot be examined).
std::string notRegularFile(const std::string& path);

// Throws tsis::Error "<what> '<path>': <problem>" unless `path` is a regular file.
void requireRegularFile(const std::string& path, const std::string& what);

// The bytes of a regular file. The check is made on the opened file (opened
// without blocking on a FIFO), so nothing swapped in after it is read.
// Throws tsis::Error "<what> '<path>': <problem>".
std::string readRegularFile(const std::string& path, const std::string& what);

}  // namespace tsis
