// OSMesa: an OpenGL 4.5 core context of Mesa's software rasterizer, made
// current on a 1×1 RGBA buffer (every pass draws into framebuffer objects).
// GL/osmesa.h brings GL/gl.h's prototypes, so this file does not include
// gl/gl.h (nor anything that does).
#include <GL/osmesa.h>

#include <vector>

#include "gl/gl_backend.h"
#include "util/error.h"

namespace tsis {

namespace {

class OsMesaBackend final : public GlBackend {
  public:
    explicit OsMesaBackend(OSMesaContext share = nullptr) : buffer_(4) {
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
        ctx_ = OSMesaCreateContextAttribs(attribs, share);
        if (!ctx_) fail("OSMesa could not create an OpenGL 4.5 core context");
    }
    ~OsMesaBackend() override { OSMesaDestroyContext(ctx_); }
    OsMesaBackend(const OsMesaBackend&) = delete;
    OsMesaBackend& operator=(const OsMesaBackend&) = delete;

    void makeCurrent() override {
        if (!OSMesaMakeCurrent(ctx_, buffer_.data(), GL_UNSIGNED_BYTE, 1, 1))
            fail("OSMesaMakeCurrent failed");
    }
    void release() override { OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0); }
    GlProc proc(const char* name) const override { return OSMesaGetProcAddress(name); }
    std::unique_ptr<GlBackend> makeShared() const override {
        return std::make_unique<OsMesaBackend>(ctx_);
    }
    std::string platform() const override { return "osmesa"; }

  private:
    OSMesaContext ctx_ = nullptr;
    std::vector<unsigned char> buffer_;
};

}  // namespace

std::unique_ptr<GlBackend> makeOsMesaBackend() {
    auto b = std::make_unique<OsMesaBackend>();
    b->makeCurrent();
    return b;
}

}  // namespace tsis
