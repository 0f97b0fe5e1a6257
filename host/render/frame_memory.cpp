#include "render/frame_memory.h"

#include "render/renderer.h"
#include "util/error.h"
#include "util/memory.h"

namespace tsis {

namespace {

// Peak resident bytes of `tsis render` (GNU time's maxrss, default scene and
// method, docs/guide/rendering.md "Memory"), fitted as fixed + per image pixel + per atlas
// texel + per light-map texel: 1024² → 2048² adds 123 B a pixel (206 with
// --aov), atlas 512² → 2048² 227 B a texel, light maps 256² → 2048² 16 B.
constexpr double kFixed = 275e6;  // GL, CL, programs, the default mesh
constexpr double kPerPixel = 123;
constexpr double kPerAovPixel = 83;  // --aov: the float images kept on the host
constexpr double kPerAtlasTexel = 227;
constexpr double kPerLightTexel = 16;  // the default scene's two lights
// --aa N: the composite's (N² − 1) extra samples a pixel, each a position,
// a normal, a depth and a radiance texel (GL targets, host memory on llvmpipe).
constexpr double kPerExtraSample = 52;
constexpr int kAutoLightResolution = 2048;  // --light-res 0: at most this (renderer.h)

}  // namespace

uint64_t frameMemoryBytes(const RenderOptions& o) {
    const double pixels = double(o.width) * o.height;
    const int atlasRes = o.atlasResolution > 0 ? o.atlasResolution : kAtlasPackResolution;
    const double atlas = double(atlasRes) * atlasRes;
    const int lightRes = o.lightResolution > 0 ? o.lightResolution : kAutoLightResolution;
    const double light = double(lightRes) * lightRes;
    const double extraSamples = double(o.aa) * o.aa - 1;
    return static_cast<uint64_t>(
        kFixed +
        pixels * (kPerPixel + (o.keepAovs ? kPerAovPixel : 0) + extraSamples * kPerExtraSample) +
        atlas * kPerAtlasTexel + light * kPerLightTexel);
}

void requireFrameMemory(const RenderOptions& o) {
    requireMemory(frameMemoryBytes(o), availableMemoryBytes(),
                  concat("a ", o.width, "×", o.height, " frame"));
}

}  // namespace tsis
