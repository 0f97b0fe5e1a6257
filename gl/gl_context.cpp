#include "gl/gl_context.h"

#include <cstdlib>
#include <utility>

#include "gl/gl.h"
#include "gl/gl_backend.h"
#include "util/error.h"

namespace tsis {

namespace {

GlProc loadFrom(const char* name, void* backend) {
    return static_cast<const GlBackend*>(backend)->proc(name);
}

// The backend whose context is current on this thread (GlBackend::release).
thread_local GlBackend* tCurrentBackend = nullptr;

void releaseCurrent() {
    if (tCurrentBackend) tCurrentBackend->release();
    tCurrentBackend = nullptr;
    tCurrentGl = nullptr;
}

}  // namespace

GlChoice parseGlChoice(const std::string& text) {
    const char* env = std::getenv("TSIS_GL");
    const bool fromEnv = text.empty() && env && *env;
    const std::string v = fromEnv ? env : text;
    if (v.empty() || v == "auto") return GlChoice::Auto;
    if (v == "osmesa") return GlChoice::OsMesa;
    if (v == "egl") return GlChoice::Egl;
    fail(fromEnv ? "TSIS_GL=" : "--gl ", v, ": expected auto, osmesa or egl");
}

const char* glChoiceName(GlChoice c) {
    switch (c) {
        case GlChoice::OsMesa:
            return "osmesa";
        case GlChoice::Egl:
            return "egl";
        case GlChoice::Auto:
            break;
    }
    return "auto";
}

GlContext::GlContext(GlChoice choice) {
    if (const char* env = std::getenv("TSIS_NO_GL"); env && *env && *env != '0')
        fail("no GL context: disabled by TSIS_NO_GL");
    const std::string eglOnly = eglPlatformFromEnv();
    releaseCurrent();  // the new context becomes current
    try {
        switch (choice) {
            case GlChoice::OsMesa:
                backend_ = makeOsMesaBackend();
                break;
            case GlChoice::Egl:
                backend_ = makeEglBackend(eglOnly);
                break;
            case GlChoice::Auto:
                // EGL first (a GPU where there is one); OSMesa when EGL gives
                // no context, with both reasons when neither does.
                try {
                    backend_ = makeEglBackend(eglOnly);
                } catch (const Error& egl) {
                    try {
                        backend_ = makeOsMesaBackend();
                    } catch (const Error& osmesa) {
                        fail(egl.what(), "; OSMesa: ", osmesa.what());
                    }
                }
                break;
        }
    } catch (const Error& e) {
        fail("no GL context: ", e.what());
    }
    if (const char* missing = loadGlFunctions(gl_, loadFrom, backend_.get()))
        fail("no GL context: ", backend_->platform(), " has no ", missing);
    tCurrentBackend = backend_.get();
    tCurrentGl = &gl_;
}

GlContext::GlContext(std::unique_ptr<GlBackend> backend) : backend_(std::move(backend)) {
    if (const char* missing = loadGlFunctions(gl_, loadFrom, backend_.get()))
        fail("no GL context: ", backend_->platform(), " has no ", missing);
}

std::unique_ptr<GlContext> GlContext::makeShared() const {
    try {
        return std::unique_ptr<GlContext>(new GlContext(backend_->makeShared()));
    } catch (const Error& e) {
        fail("no GL context: ", e.what());
    }
}

GlContext::~GlContext() {
    release();
}

void GlContext::makeCurrent() {
    if (tCurrentBackend != backend_.get()) releaseCurrent();
    try {
        backend_->makeCurrent();
    } catch (const Error& e) {
        fail("no GL context: ", e.what());
    }
    tCurrentBackend = backend_.get();
    tCurrentGl = &gl_;
}

void GlContext::release() {
    if (tCurrentBackend == backend_.get()) releaseCurrent();
}

namespace {

std::string glString(GLenum e) {
    const GLubyte* s = glGetString(e);
    return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
}

}  // namespace

std::string GlContext::renderer() const {
    return glString(GL_RENDERER) + " / " + glString(GL_VERSION);
}

std::string GlContext::vendor() const {
    return glString(GL_VENDOR);
}

std::string GlContext::platform() const {
    return backend_->platform();
}

int GlContext::maxTextureSize() const {
    GLint n = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &n);
    return n;
}

void checkGl(const char* where) {
    GLenum e = glGetError();
    if (e == GL_NO_ERROR) return;
    const char* name = "unknown";
    switch (e) {
        case GL_INVALID_ENUM:
            name = "GL_INVALID_ENUM";
            break;
        case GL_INVALID_VALUE:
            name = "GL_INVALID_VALUE";
            break;
        case GL_INVALID_OPERATION:
            name = "GL_INVALID_OPERATION";
            break;
        case GL_INVALID_FRAMEBUFFER_OPERATION:
            name = "GL_INVALID_FRAMEBUFFER_OPERATION";
            break;
        case GL_OUT_OF_MEMORY:
            name = "GL_OUT_OF_MEMORY";
            break;
    }
    checkFailed(__FILE__, __LINE__, concat("OpenGL error ", name, " after ", where));
}

}  // namespace tsis
