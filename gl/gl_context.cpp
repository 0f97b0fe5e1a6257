#include "gl/gl_context.h"

#include <GL/osmesa.h>

#include <cstdlib>

#include "gl/gl.h"
#include "util/error.h"

namespace tsis {

GlContext::GlContext() : dummy_(4) {
    if (const char* env = std::getenv("TSIS_NO_GL"); env && *env && *env != '0')
        fail("no GL context: disabled by TSIS_NO_GL");
    const int attribs[] = {OSMESA_FORMAT,
                           OSMESA_RGBA,
                           OSMESA_DEPTH_BITS,
                           0,
                           OSMESA_PROFILE,
                           OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION,
                           4,
                           OSMESA_CONTEXT_MINOR_VERSION,
                           5,
                           0};
    OSMesaContext ctx = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!ctx) fail("no GL context: OSMesa could not create an OpenGL 4.5 core context");
    ctx_ = ctx;
    makeCurrent();
}

GlContext::~GlContext() {
    if (ctx_) OSMesaDestroyContext(static_cast<OSMesaContext>(ctx_));
}

void GlContext::makeCurrent() {
    if (!OSMesaMakeCurrent(static_cast<OSMesaContext>(ctx_), dummy_.data(), GL_UNSIGNED_BYTE, 1, 1))
        fail("no GL context: OSMesaMakeCurrent failed");
}

std::string GlContext::renderer() const {
    auto str = [](GLenum e) {
        const GLubyte* s = glGetString(e);
        return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
    };
    return str(GL_RENDERER) + " / " + str(GL_VERSION);
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
