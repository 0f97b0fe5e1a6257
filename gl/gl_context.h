// An offscreen OpenGL 4.5 core context through OSMesa (software, llvmpipe).
// All passes render into framebuffer objects; the OSMesa buffer is 1×1.
#pragma once

#include <string>
#include <vector>

namespace tsis {

class GlContext {
  public:
    // Throws tsis::Error "no GL context: ..." when OSMesa cannot make one.
    GlContext();
    ~GlContext();
    GlContext(const GlContext&) = delete;
    GlContext& operator=(const GlContext&) = delete;

    void makeCurrent();
    std::string renderer()
        const;  // "llvmpipe (LLVM 15.0.6, 256 bits) / 4.5 (Core Profile) Mesa ..."
    // GL_MAX_TEXTURE_SIZE: the widest render target.
    int maxTextureSize() const;

  private:
    void* ctx_ = nullptr;  // OSMesaContext
    std::vector<unsigned char> dummy_;
};

// Throws (a bug) with the GL error name when glGetError reports one.
void checkGl(const char* where);

}  // namespace tsis
