// Whether the GL→CL hand-off may share the render targets with OpenCL
// (cl_khr_gl_sharing: clCreateFromGLTexture on one GPU) instead of reading
// them back through the host (gl_cl_staging.h). Only the decision is made
// here; the hand-off copies in every case so far (docs/design.md, "GL and CL
// on a GPU"), and --stats reports the decision as gl_cl_sharing.
#pragma once

#include <CL/opencl.hpp>
#include <string>

namespace tsis {

struct GlSharingSide {
    std::string platform;  // GlContext::platform(): "osmesa", "egl-device", …
    std::string vendor, renderer;
};

struct ClSharingSide {
    std::string platformName, platformVendor, deviceName;
    std::string extensions;  // CL_DEVICE_EXTENSIONS, space-separated
    bool gpu = false;        // CL_DEVICE_TYPE_GPU
};

struct GlClSharing {
    bool share = false;
    std::string reason;  // "yes: GL and CL on NVIDIA", "no: GL renders in software (llvmpipe)"
};

// Shares only when GL is an EGL context on a hardware renderer, the CL
// device is a GPU offering cl_khr_gl_sharing, and both are of one vendor
// (NVIDIA, AMD or Intel). Which GPU of that vendor the GL context is on is
// asked of CL when its context is made (clGetGLContextInfoKHR), not here.
GlClSharing chooseGlClSharing(const GlSharingSide& gl, const ClSharingSide& cl);

// The CL side of a device, as its platform and device report it.
ClSharingSide clSharingSide(const cl::Device& device);

}  // namespace tsis
