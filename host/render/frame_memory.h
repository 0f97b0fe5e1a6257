// What a frame needs in memory, roughly, before it is rendered: a frame too
// large for the machine (8192² takes about 8 GB) is refused at once with one
// line, instead of being killed by the system part way.
#pragma once

#include <cstdint>

#include "render/render_options.h"

namespace tsis {

// Bytes of a frame of `o` (the process' peak resident set, less the mesh):
// a fit of measured peaks (docs/guide/rendering.md "Memory"), on the generous side.
uint64_t frameMemoryBytes(const RenderOptions& o);

// Throws tsis::Error when frameMemoryBytes(o) exceeds the memory available
// (util/memory.h: MemAvailable, a cgroup's limit, TSIS_MEMORY_LIMIT_MB).
void requireFrameMemory(const RenderOptions& o);

}  // namespace tsis
