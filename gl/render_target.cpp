#include "gl/render_target.h"

#include "gl/gl_context.h"
#include "util/error.h"

namespace tsis {

namespace {

void setNearestClamp(GLenum target) {
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

}  // namespace

void setShadowSampling(GLenum target) {
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(target, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTexParameteri(target, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
}

RenderTarget::RenderTarget(int width, int height, std::vector<GLenum> colorFormats, bool depth)
    : width_(width), height_(height), formats_(std::move(colorFormats)) {
    colors_.resize(formats_.size());
    for (size_t i = 0; i < formats_.size(); ++i) {
        glGenTextures(1, &colors_[i]);
        glBindTexture(GL_TEXTURE_2D, colors_[i]);
        glTexStorage2D(GL_TEXTURE_2D, 1, formats_[i], width, height);
        setNearestClamp(GL_TEXTURE_2D);
    }
    if (depth) {
        glGenTextures(1, &depth_);
        glBindTexture(GL_TEXTURE_2D, depth_);
        glTexStorage2D(GL_TEXTURE_2D, 1, GL_DEPTH_COMPONENT32F, width, height);
        setShadowSampling(GL_TEXTURE_2D);
    }
    glGenFramebuffers(1, &fbo_);
    attachTo(fbo_);
    GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    TSIS_CHECK_EQ(status, static_cast<GLenum>(GL_FRAMEBUFFER_COMPLETE));
    checkGl("RenderTarget creation");
}

RenderTarget::~RenderTarget() {
    if (!colors_.empty()) glDeleteTextures(static_cast<GLsizei>(colors_.size()), colors_.data());
    if (depth_) glDeleteTextures(1, &depth_);
    if (fbo_) glDeleteFramebuffers(1, &fbo_);
}

// Binds `framebuffer` with exactly this target's textures attached (another
// target's left over on a shared one detached) and its draw buffers.
void RenderTarget::attachTo(GLuint framebuffer) const {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    constexpr size_t kAttachments = 8;  // GL_MAX_COLOR_ATTACHMENTS is at least 8
    TSIS_CHECK_LE(colors_.size(), kAttachments);
    std::vector<GLenum> drawBuffers;
    for (size_t i = 0; i < kAttachments; ++i) {
        const GLenum attachment = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i);
        glFramebufferTexture2D(GL_FRAMEBUFFER, attachment, GL_TEXTURE_2D,
                               i < colors_.size() ? colors_[i] : 0, 0);
        if (i < colors_.size()) drawBuffers.push_back(attachment);
    }
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_, 0);
    if (drawBuffers.empty())
        glDrawBuffer(GL_NONE);
    else
        glDrawBuffers(static_cast<GLsizei>(drawBuffers.size()), drawBuffers.data());
}

void RenderTarget::bind(GLuint framebuffer) {
    if (framebuffer)
        attachTo(framebuffer);
    else
        glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glViewport(0, 0, width_, height_);
}

void RenderTarget::bindAndClear(GLuint framebuffer) {
    bind(framebuffer);
    const float zero[4] = {0, 0, 0, 0};
    for (size_t i = 0; i < colors_.size(); ++i)
        glClearBufferfv(GL_COLOR, static_cast<GLint>(i), zero);
    if (depth_) {
        const float one = 1.0f;
        glClearBufferfv(GL_DEPTH, 0, &one);
    }
}

void RenderTarget::bindAndClearDepth(GLuint framebuffer) {
    TSIS_CHECK(depth_ != 0);
    bind(framebuffer);
    const float one = 1.0f;
    glClearBufferfv(GL_DEPTH, 0, &one);
}

void RenderTarget::read(int i, GLenum format, GLenum type, void* out) const {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
    glReadBuffer(GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i));
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width_, height_, format, type, out);
    checkGl("RenderTarget::read");
}

std::vector<float> RenderTarget::readRGBA(int i) const {
    std::vector<float> out(static_cast<size_t>(width_) * height_ * 4);
    read(i, GL_RGBA, GL_FLOAT, out.data());
    return out;
}

std::vector<float> RenderTarget::readDepth() const {
    std::vector<float> out(static_cast<size_t>(width_) * height_);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width_, height_, GL_DEPTH_COMPONENT, GL_FLOAT, out.data());
    checkGl("RenderTarget::readDepth");
    return out;
}

std::vector<float> RenderTarget::readRG(int i) const {
    std::vector<float> out(static_cast<size_t>(width_) * height_ * 2);
    read(i, GL_RG, GL_FLOAT, out.data());
    return out;
}

std::vector<unsigned char> RenderTarget::readRGBA8(int i) const {
    std::vector<unsigned char> out(static_cast<size_t>(width_) * height_ * 4);
    read(i, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
    return out;
}

size_t RenderTarget::bytesPerTexel(int i) const {
    switch (formats_[static_cast<size_t>(i)]) {
        case GL_RGBA32F:
            return 16;
        case GL_RGBA16F:
        case GL_RG32F:
            return 8;
        default:  // GL_R32F, GL_RGBA8
            return 4;
    }
}

FloatTexture::FloatTexture(int width, int height) : width_(width), height_(height) {
    glGenTextures(1, &id_);
    glBindTexture(GL_TEXTURE_2D, id_);
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA32F, width, height);
    setNearestClamp(GL_TEXTURE_2D);
}

FloatTexture::~FloatTexture() {
    if (id_) glDeleteTextures(1, &id_);
}

void FloatTexture::upload(const float* rgba) {
    glBindTexture(GL_TEXTURE_2D, id_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width_, height_, GL_RGBA, GL_FLOAT, rgba);
    checkGl("FloatTexture::upload");
}

}  // namespace tsis
