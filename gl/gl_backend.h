// What GlContext needs of a platform: a current OpenGL 4.5 core context and
// its entry points. Two exist: OSMesa (software, always here) and EGL
// (headless: a device, else Mesa's surfaceless platform).
#pragma once

#include <memory>
#include <string>

namespace tsis {

using GlProc = void (*)();  // as gl/gl_functions.h (not included: see osmesa_backend.cpp)

class GlBackend {
  public:
    virtual ~GlBackend() = default;
    // Throws tsis::Error with the reason when the platform refuses.
    virtual void makeCurrent() = 0;
    // Leaves the thread with no context of this platform current. EGL and
    // OSMesa each think theirs still current after the other's MakeCurrent,
    // and EGL then skips re-binding it; so a switch releases the old first.
    virtual void release() = 0;
    virtual GlProc proc(const char* name) const = 0;
    // A second context of the same platform sharing this one's objects
    // (textures, buffers, programs; not framebuffers nor vertex arrays), for
    // another thread; not current anywhere. Throws tsis::Error when refused.
    virtual std::unique_ptr<GlBackend> makeShared() const = 0;
    // "osmesa", "egl-device" or "egl-surfaceless".
    virtual std::string platform() const = 0;
};

// Each throws tsis::Error with the reason (no "no GL context:" prefix) when
// it cannot make a context; the context is current on return.
std::unique_ptr<GlBackend> makeOsMesaBackend();
// The displays tried in order: hardware devices, software devices, then the
// surfaceless platform; only = "device" or "surfaceless" keeps one kind.
std::unique_ptr<GlBackend> makeEglBackend(const std::string& only = "");
// $TSIS_EGL_PLATFORM: "", "device" or "surfaceless"; tsis::Error otherwise.
std::string eglPlatformFromEnv();

}  // namespace tsis
