#include "render/gl_cl_sharing.h"

#include <gtest/gtest.h>

namespace tsis {
namespace {

// What the drivers report (GL_VENDOR, GL_RENDERER; CL platform, vendor, device).
const GlSharingSide kNvidiaGl{"egl-device", "NVIDIA Corporation", "NVIDIA H200/PCIe/SSE2"};
const GlSharingSide kRadeonGl{"egl-device", "AMD",
                              "AMD Radeon RX 6800 (navi21, LLVM 15.0.6, DRM 3.49, 6.1.0)"};
const GlSharingSide kLlvmpipeGl{"egl-device", "Mesa",
                                "llvmpipe (LLVM 15.0.6, 256 bits) / 4.5 (Core Profile) Mesa"};
const ClSharingSide kNvidiaCl{
    "NVIDIA CUDA", "NVIDIA Corporation", "NVIDIA H200",
    "cl_khr_global_int32_base_atomics cl_khr_gl_sharing cl_nv_pragma_unroll", true};
const ClSharingSide kRocmCl{"AMD Accelerated Parallel Processing", "Advanced Micro Devices, Inc.",
                            "gfx1030", "cl_khr_fp64 cl_khr_gl_sharing cl_amd_media_ops", true};
const ClSharingSide kPoclCl{"Portable Computing Language", "The pocl project",
                            "pthread-skylake-avx512-Intel(R) Xeon(R) Processor",
                            "cl_khr_byte_addressable_store cl_khr_fp64", false};

TEST(GlClSharing, OneVendorsGpuWithTheExtensionShares) {
    EXPECT_TRUE(chooseGlClSharing(kNvidiaGl, kNvidiaCl).share);
    EXPECT_TRUE(chooseGlClSharing(kRadeonGl, kRocmCl).share);
    EXPECT_EQ(chooseGlClSharing(kNvidiaGl, kNvidiaCl).reason, "yes: GL and CL on nvidia");
}

TEST(GlClSharing, SurfacelessEglSharesToo) {
    GlSharingSide gl = kRadeonGl;
    gl.platform = "egl-surfaceless";
    EXPECT_TRUE(chooseGlClSharing(gl, kRocmCl).share);
}

TEST(GlClSharing, OsMesaNeverShares) {
    GlSharingSide gl = kNvidiaGl;
    gl.platform = "osmesa";
    const GlClSharing s = chooseGlClSharing(gl, kNvidiaCl);
    EXPECT_FALSE(s.share);
    EXPECT_NE(s.reason.find("osmesa"), std::string::npos) << s.reason;
}

// This machine: EGL on Mesa's software device, PoCL on the CPU.
TEST(GlClSharing, SoftwareGlDoesNotShare) {
    const GlClSharing s = chooseGlClSharing(kLlvmpipeGl, kPoclCl);
    EXPECT_FALSE(s.share);
    EXPECT_NE(s.reason.find("software"), std::string::npos) << s.reason;
}

TEST(GlClSharing, ACpuDeviceDoesNotShareEvenOfTheGlVendor) {
    const GlSharingSide intelGl{"egl-device", "Intel", "Mesa Intel(R) UHD Graphics 620 (KBL GT2)"};
    ClSharingSide cl = kPoclCl;  // "…Intel(R) Xeon(R)…": the vendor's name, but a CPU
    cl.extensions += " cl_khr_gl_sharing";
    EXPECT_FALSE(chooseGlClSharing(intelGl, cl).share);
}

TEST(GlClSharing, WithoutTheExtensionNoSharing) {
    ClSharingSide cl = kNvidiaCl;
    cl.extensions =
        "cl_khr_global_int32_base_atomics cl_khr_gl_sharing_ext";  // a word, not a prefix
    const GlClSharing s = chooseGlClSharing(kNvidiaGl, cl);
    EXPECT_FALSE(s.share);
    EXPECT_NE(s.reason.find("cl_khr_gl_sharing"), std::string::npos) << s.reason;
}

TEST(GlClSharing, GlAndClOfDifferentVendorsDoNotShare) {
    EXPECT_FALSE(chooseGlClSharing(kNvidiaGl, kRocmCl).share);
    EXPECT_FALSE(chooseGlClSharing(kRadeonGl, kNvidiaCl).share);
}

// Mesa's rusticl names the GPU in the device; older Mesa's GL vendor is "X.Org".
TEST(GlClSharing, MesaOnAmdMatchesByTheGpusName) {
    const GlSharingSide gl{"egl-device", "X.Org", "AMD Radeon RX 580 Series (polaris10, LLVM 15)"};
    const ClSharingSide rusticl{"rusticl", "Mesa/X.org", "AMD Radeon RX 580 Series (polaris10)",
                                "cl_khr_byte_addressable_store cl_khr_gl_sharing", true};
    EXPECT_TRUE(chooseGlClSharing(gl, rusticl).share);
}

}  // namespace
}  // namespace tsis
