// Keeps every shared library loaded now mapped until exit. Drivers loaded
// with dlopen (GLFW's GLX, GLVND's EGL vendors) are unloaded at exit or on
// terminate, and what they keep for the process then looks leaked from a
// module that is gone, which no LeakSanitizer suppression can name. One more
// reference to each keeps that state reachable, and the library named.
#pragma once

namespace tsis {

void keepLoadedLibrariesMapped();

}  // namespace tsis
