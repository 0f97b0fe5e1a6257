// Background threads (frames, meshes, references) yield the cores to the
// window's thread, so that the window keeps its update rate while PoCL and
// llvmpipe keep every core busy.
#pragma once

namespace tsis {

// Lowers the calling thread's priority (Linux: its nice value, by 10). The
// threads it creates afterwards inherit it: PoCL's and llvmpipe's workers,
// when their OpenCL and OSMesa contexts are made on this thread. Best effort:
// where the system refuses, nothing changes.
void lowerThisThreadPriority();

}  // namespace tsis
