// An offscreen OpenGL 4.5 core context, through EGL (headless: a GPU's
// device, else Mesa's software device or surfaceless platform) or OSMesa
// (software, llvmpipe). All passes render into framebuffer objects.
#pragma once

#include <memory>
#include <string>

#include "gl/gl_functions.h"

namespace tsis {

class GlBackend;

// --gl: auto (EGL when a display gives a context, else OSMesa), osmesa, egl.
enum class GlChoice { Auto, OsMesa, Egl };
// "" → $TSIS_GL → auto; tsis::Error "--gl X: ..." (or "TSIS_GL=X: ...") otherwise.
GlChoice parseGlChoice(const std::string& text);
const char* glChoiceName(GlChoice c);

class GlContext {
  public:
    // Throws tsis::Error "no GL context: ..." when the chosen platform (both,
    // for auto) cannot make one. The context is current on return.
    explicit GlContext(GlChoice choice = GlChoice::Auto);
    ~GlContext();
    GlContext(const GlContext&) = delete;
    GlContext& operator=(const GlContext&) = delete;

    // Makes the context and its entry points (gl/gl.h) current on this thread.
    void makeCurrent();
    // Leaves this thread with no context current if this one is, so that
    // another thread may make it current (EGL refuses a context current
    // elsewhere; OSMesa's would be drawn into from two threads).
    void release();
    // A context sharing this one's objects (textures, buffers, programs — not
    // framebuffers nor vertex arrays), current nowhere: for another thread
    // (gl/gl_worker.h). Throws tsis::Error "no GL context: ..." when refused.
    std::unique_ptr<GlContext> makeShared() const;
    // "llvmpipe (LLVM 15.0.6, 256 bits) / 4.5 (Core Profile) Mesa ..."
    std::string renderer() const;
    std::string vendor() const;  // GL_VENDOR: "Mesa", "NVIDIA Corporation", …
    // "osmesa", "egl-device" or "egl-surfaceless".
    std::string platform() const;
    // GL_MAX_TEXTURE_SIZE: the widest render target.
    int maxTextureSize() const;

  private:
    explicit GlContext(std::unique_ptr<GlBackend> backend);
    std::unique_ptr<GlBackend> backend_;
    GlFunctions gl_;
};

// Throws (a bug) with the GL error name when glGetError reports one.
void checkGl(const char* where);

}  // namespace tsis
