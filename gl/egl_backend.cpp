// EGL without a window: eglGetPlatformDisplayEXT on a device
// (EGL_EXT_platform_device: a GPU, or Mesa's software device) or on Mesa's
// surfaceless platform, and a configless OpenGL 4.5 core context made current
// with no surface (EGL_KHR_surfaceless_context): every pass draws into
// framebuffer objects. libEGL is GLVND's, so the vendor is whichever driver
// owns the device.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdlib>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "gl/gl_backend.h"
#include "util/error.h"
#include "util/loaded_libraries.h"

namespace tsis {

namespace {

// One EGLDisplay is handed out per device (or platform) and eglTerminate ends
// every context on it, so a display is terminated when its last context goes.
std::mutex gDisplaysMutex;
std::map<EGLDisplay, int> gDisplayUsers;

bool hasExtension(const char* list, const std::string& name) {
    if (!list) return false;
    const std::string s = std::string(" ") + list + " ";
    return s.find(" " + name + " ") != std::string::npos;
}

std::string eglErrorText() {
    char buf[32];
    std::snprintf(buf, sizeof buf, "EGL error 0x%04x", static_cast<unsigned>(eglGetError()));
    return buf;
}

struct Candidate {
    EGLDisplay display;
    std::string platform;  // "egl-device" or "egl-surfaceless"
    std::string what;      // for the error: "device 0 (software)"
};

// The displays to try, best first; `why` collects what was not offered.
std::vector<Candidate> candidates(const std::string& want, std::string& why) {
    const char* clientExt = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!clientExt) {
        why = "libEGL offers no client extensions (" + eglErrorText() + ")";
        return {};
    }
    auto getDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!getDisplay) {
        why = "libEGL has no eglGetPlatformDisplayEXT";
        return {};
    }
    std::vector<Candidate> hardware, software;
    auto queryDevices =
        reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    auto deviceString = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(
        eglGetProcAddress("eglQueryDeviceStringEXT"));
    if (want != "surfaceless" && hasExtension(clientExt, "EGL_EXT_platform_device") &&
        queryDevices && deviceString) {
        EGLDeviceEXT devices[16];
        EGLint n = 0;
        if (!queryDevices(16, devices, &n)) n = 0;
        for (EGLint i = 0; i < n; ++i) {
            const bool isSoftware =
                hasExtension(deviceString(devices[i], EGL_EXTENSIONS), "EGL_MESA_device_software");
            EGLDisplay d = getDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
            if (d == EGL_NO_DISPLAY) continue;
            (isSoftware ? software : hardware)
                .push_back(
                    {d, "egl-device", concat("device ", i, isSoftware ? " (software)" : "")});
        }
        if (n == 0) why += "no EGL device; ";
    }
    std::vector<Candidate> all = hardware;
    all.insert(all.end(), software.begin(), software.end());
    if (want != "device" && hasExtension(clientExt, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay d = getDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (d != EGL_NO_DISPLAY) all.push_back({d, "egl-surfaceless", "surfaceless platform"});
    }
    if (all.empty())
        why += want.empty() ? "no EGL device nor surfaceless platform"
                            : "no EGL " + want + " display (TSIS_EGL_PLATFORM)";
    return all;
}

class EglBackend final : public GlBackend {
  public:
    explicit EglBackend(const std::string& only) {
        std::string why;
        for (const Candidate& c : candidates(only, why)) {
            std::string reason = tryDisplay(c);
            if (reason.empty()) return;
            why += c.what + ": " + reason + "; ";
        }
        if (why.size() >= 2 && why.compare(why.size() - 2, 2, "; ") == 0)
            why.resize(why.size() - 2);
        fail("EGL: ", why);
    }
    ~EglBackend() override {
        eglBindAPI(EGL_OPENGL_API);  // eglGetCurrentContext answers for the bound API
        if (eglGetCurrentContext() == ctx_)
            eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display_, ctx_);
        release(display_);
    }
    EglBackend(const EglBackend&) = delete;
    EglBackend& operator=(const EglBackend&) = delete;

    std::unique_ptr<GlBackend> makeShared() const override {
        return std::unique_ptr<GlBackend>(new EglBackend(*this, Shared{}));
    }

    void makeCurrent() override {
        // The API is bound per thread: another thread may make this current.
        eglBindAPI(EGL_OPENGL_API);
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx_))
            fail("eglMakeCurrent failed (", eglErrorText(), ")");
    }
    void release() override {
        eglBindAPI(EGL_OPENGL_API);
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    }
    GlProc proc(const char* name) const override { return eglGetProcAddress(name); }
    std::string platform() const override { return platform_; }

  private:
    struct Shared {};
    EglBackend(const EglBackend& share, Shared)
        : display_(share.display_), config_(share.config_), platform_(share.platform_) {
        std::lock_guard lock(gDisplaysMutex);
        eglBindAPI(EGL_OPENGL_API);
        ctx_ = eglCreateContext(display_, config_, share.ctx_, kContextAttribs);
        if (ctx_ == EGL_NO_CONTEXT) fail("EGL: no shared context (", eglErrorText(), ")");
        ++gDisplayUsers[display_];
    }

    static constexpr EGLint kContextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                                 4,
                                                 EGL_CONTEXT_MINOR_VERSION,
                                                 5,
                                                 EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                                 EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                                 EGL_NONE};

    // Empty when `c` gave a current context (kept), else why not.
    std::string tryDisplay(const Candidate& c) {
        std::lock_guard lock(gDisplaysMutex);
        EGLint major = 0, minor = 0;
        if (!eglInitialize(c.display, &major, &minor)) return "eglInitialize: " + eglErrorText();
        ++gDisplayUsers[c.display];
        std::string reason = tryContext(c.display);
        if (reason.empty()) {
            display_ = c.display;
            platform_ = c.platform;
        } else if (--gDisplayUsers[c.display] == 0) {
            gDisplayUsers.erase(c.display);
            eglTerminate(c.display);
        }
        return reason;
    }

    std::string tryContext(EGLDisplay d) {
        const char* ext = eglQueryString(d, EGL_EXTENSIONS);
        if (!hasExtension(ext, "EGL_KHR_surfaceless_context"))
            return "no EGL_KHR_surfaceless_context";
        if (!eglBindAPI(EGL_OPENGL_API)) return "no desktop OpenGL (" + eglErrorText() + ")";
        // Configless where offered; else any config that renders OpenGL.
        EGLConfig config = EGL_NO_CONFIG_KHR;
        if (!hasExtension(ext, "EGL_KHR_no_config_context") &&
            !hasExtension(ext, "EGL_MESA_configless_context")) {
            const EGLint want[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
            EGLint n = 0;
            if (!eglChooseConfig(d, want, &config, 1, &n) || n < 1)
                return "no config that renders OpenGL";
        }
        EGLContext ctx = eglCreateContext(d, config, EGL_NO_CONTEXT, kContextAttribs);
        if (ctx == EGL_NO_CONTEXT) return "no OpenGL 4.5 core context (" + eglErrorText() + ")";
        if (!eglMakeCurrent(d, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
            std::string e = "eglMakeCurrent: " + eglErrorText();
            eglDestroyContext(d, ctx);
            return e;
        }
        ctx_ = ctx;
        config_ = config;
        // GLVND unloads its vendors at exit: keep them mapped, so what Mesa
        // keeps for the process stays reachable (util/loaded_libraries.h).
        static std::once_flag once;
        std::call_once(once, keepLoadedLibrariesMapped);
        return "";
    }

    static void release(EGLDisplay d) {
        std::lock_guard lock(gDisplaysMutex);
        if (--gDisplayUsers[d] > 0) return;
        gDisplayUsers.erase(d);
        eglTerminate(d);
    }

    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLConfig config_ = EGL_NO_CONFIG_KHR;
    EGLContext ctx_ = EGL_NO_CONTEXT;
    std::string platform_;
};

}  // namespace

std::string eglPlatformFromEnv() {
    const char* env = std::getenv("TSIS_EGL_PLATFORM");
    std::string v = env ? env : "";
    if (!v.empty() && v != "device" && v != "surfaceless")
        fail("TSIS_EGL_PLATFORM=", v, ": expected device or surfaceless");
    return v;
}

std::unique_ptr<GlBackend> makeEglBackend(const std::string& only) {
    return std::make_unique<EglBackend>(only);
}

}  // namespace tsis
