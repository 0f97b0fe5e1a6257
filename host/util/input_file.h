// The one checked open for every file tsis reads (meshes, .mtl libraries,
// textures, glTF buffers and images, environment maps, images to compare):
//  * regular files only: a FIFO would block the read forever and a device
//    such as /dev/zero never ends, so both are refused at once (directly or
//    through a link), before any byte is read;
//  * a size limit per kind (docs/guide/rendering.md "Input files"), checked on the opened file
//    and again while reading: no unbounded read;
//  * an asset's own files (an OBJ's mtllib and map_Kd, a glTF's buffers and
//    images) only inside the asset's folder, links resolved, unless the user
//    opted in (--allow-outside-assets, the library's option of that name).
#pragma once

#include <cstdint>
#include <string>

namespace tsis {

// Size limits (bytes) of what is read whole.
inline constexpr uint64_t kMaxMeshFileBytes = 4ull << 30;       // a mesh, a glTF buffer
inline constexpr uint64_t kMaxLibraryFileBytes = 256ull << 20;  // an .mtl library
inline constexpr uint64_t kMaxImageFileBytes = 1ull
                                               << 30;  // a texture, an env map, a compare input

// "" when `path` (links followed) is a regular file, else what it is instead
// ("is a directory", "is a FIFO, not a regular file", or why it cannot be examined).
std::string notRegularFile(const std::string& path);

// Throws tsis::Error "<what> '<path>': <problem>" unless `path` is a regular file.
void requireRegularFile(const std::string& path, const std::string& what);

// The bytes of a regular file of at most `maxBytes`. The checks are made on
// the opened file (opened without blocking on a FIFO), so nothing swapped in
// after them is read. Throws tsis::Error "<what> '<path>': <problem>".
std::string readRegularFile(const std::string& path, const std::string& what,
                            uint64_t maxBytes = kMaxMeshFileBytes);

// Whether an asset's files may lie outside its folder (default: no). Set once
// from the command line or the library's options, before loading.
void setOutsideAssetsAllowed(bool allowed);
bool outsideAssetsAllowed();

// The file `name` (relative to `folder`, or absolute) that an asset in
// `folder` refers to, links resolved; throws tsis::Error "<what> '<path>' not
// found" when it does not exist, or "… lies outside the asset's folder …"
// when, unless outsideAssetsAllowed(), it lies
// outside `folder` (an absolute path, "../", a link leading out).
std::string assetFile(const std::string& folder, const std::string& name, const std::string& what);

}  // namespace tsis
