#include "render/gl_cl_sharing.h"

#include <algorithm>
#include <cctype>

namespace tsis {

namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

bool hasWord(const std::string& list, const std::string& word) {
    return (" " + list + " ").find(" " + word + " ") != std::string::npos;
}

// "nvidia", "amd", "intel" or "" from what a driver calls itself. Mesa names
// the GPU in the renderer ("AMD Radeon RX 6800 (navi21, …)", "Mesa Intel(R)
// UHD Graphics") and rusticl in the device name; older Mesa's vendor is "X.Org".
std::string vendorFamily(const std::string& text) {
    const std::string s = lower(text);
    if (s.find("nvidia") != std::string::npos) return "nvidia";
    if (s.find("advanced micro devices") != std::string::npos ||
        s.find("radeon") != std::string::npos || s.find("amd") != std::string::npos)
        return "amd";
    if (s.find("intel") != std::string::npos) return "intel";
    return "";
}

bool softwareRenderer(const std::string& renderer) {
    const std::string s = lower(renderer);
    for (const char* sw : {"llvmpipe", "softpipe", "swrast", "software rasterizer", "lavapipe"})
        if (s.find(sw) != std::string::npos) return true;
    return false;
}

}  // namespace

GlClSharing chooseGlClSharing(const GlSharingSide& gl, const ClSharingSide& cl) {
    if (gl.platform.rfind("egl-", 0) != 0)
        return {false, "no: GL is " + gl.platform + ", not an EGL context CL can share"};
    if (softwareRenderer(gl.renderer))
        return {false, "no: GL renders in software (" + gl.renderer + ")"};
    if (!cl.gpu) return {false, "no: the CL device is not a GPU"};
    if (!hasWord(cl.extensions, "cl_khr_gl_sharing"))
        return {false, "no: the CL device has no cl_khr_gl_sharing"};
    const std::string glFamily = vendorFamily(gl.vendor + " " + gl.renderer);
    const std::string clFamily =
        vendorFamily(cl.platformVendor + " " + cl.platformName + " " + cl.deviceName);
    if (glFamily.empty() || glFamily != clFamily)
        return {false, "no: GL (" + gl.vendor + ") and CL (" + cl.platformVendor +
                           ") are not one vendor's GPU"};
    return {true, "yes: GL and CL on " + glFamily};
}

ClSharingSide clSharingSide(const cl::Device& device) {
    const cl::Platform platform(device.getInfo<CL_DEVICE_PLATFORM>());
    ClSharingSide s;
    s.platformName = platform.getInfo<CL_PLATFORM_NAME>();
    s.platformVendor = platform.getInfo<CL_PLATFORM_VENDOR>();
    s.deviceName = device.getInfo<CL_DEVICE_NAME>();
    s.extensions = device.getInfo<CL_DEVICE_EXTENSIONS>();
    s.gpu = (device.getInfo<CL_DEVICE_TYPE>() & CL_DEVICE_TYPE_GPU) != 0;
    return s;
}

}  // namespace tsis
