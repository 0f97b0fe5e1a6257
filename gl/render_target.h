// A framebuffer object with float colour attachments and an optional depth
// texture (which doubles as a shadow map). Owned textures, read back as floats.
#pragma once

#include <cstddef>
#include <vector>

#include "gl/gl.h"

namespace tsis {

class RenderTarget {
  public:
    // colorFormats: internal formats (GL_RGBA32F, GL_RGBA8, …), one per attachment.
    RenderTarget(int width, int height, std::vector<GLenum> colorFormats, bool depth);
    ~RenderTarget();
    RenderTarget(const RenderTarget&) = delete;
    RenderTarget& operator=(const RenderTarget&) = delete;

    // Binds, sets the viewport and clears colour (to zero) and depth.
    // `framebuffer`: one of another context (where this target's own is not
    // valid: framebuffers are not shared, gl/gl_worker.h) to bind with this
    // target's textures attached; 0, the target's own.
    void bindAndClear(GLuint framebuffer = 0);
    // Binds and clears depth only, for readers that take coverage from it.
    void bindAndClearDepth(GLuint framebuffer = 0);
    // Binds and sets the viewport; the contents stay (a pass that writes
    // only what it will read).
    void bind(GLuint framebuffer = 0);
    int width() const { return width_; }
    int height() const { return height_; }
    GLuint color(int i) const { return colors_[static_cast<size_t>(i)]; }
    GLenum format(int i) const { return formats_[static_cast<size_t>(i)]; }
    int colorCount() const { return static_cast<int>(colors_.size()); }
    GLuint depth() const { return depth_; }

    // Attachment i as RGBA floats, GL order (row 0 = bottom).
    std::vector<float> readRGBA(int i) const;
    // The same into `out` (width · height · 4 floats), memory the caller holds.
    void readRGBA(int i, float* out) const { read(i, GL_RGBA, GL_FLOAT, out); }
    // Attachment i's first two channels as floats (for GL_RG32F), GL order.
    std::vector<float> readRG(int i) const;
    void readRG(int i, float* out) const { read(i, GL_RG, GL_FLOAT, out); }
    // Attachment i as RGBA bytes (for GL_RGBA8), GL order.
    std::vector<unsigned char> readRGBA8(int i) const;
    // The depth texture as window depths in [0, 1] (1: nothing drawn), GL
    // order; a target made with a depth.
    std::vector<float> readDepth() const;

    size_t bytesPerTexel(int i) const;

  private:
    void read(int i, GLenum format, GLenum type, void* out) const;
    void attachTo(GLuint framebuffer) const;

    int width_, height_;
    std::vector<GLenum> formats_;
    std::vector<GLuint> colors_;
    GLuint depth_ = 0, fbo_ = 0;
};

// Samples the bound depth texture at `target` as a shadow map: hardware depth
// comparison (GL_LEQUAL) with bilinear filtering (PCF), clamped to the edge.
void setShadowSampling(GLenum target);

// A 2D float texture uploaded from host data (RGBA, row 0 = bottom).
class FloatTexture {
  public:
    FloatTexture(int width, int height);
    ~FloatTexture();
    FloatTexture(const FloatTexture&) = delete;
    FloatTexture& operator=(const FloatTexture&) = delete;
    void upload(const float* rgba);
    GLuint id() const { return id_; }
    int width() const { return width_; }
    int height() const { return height_; }

  private:
    int width_, height_;
    GLuint id_ = 0;
};

}  // namespace tsis
