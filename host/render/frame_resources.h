// The data a frame's passes hand each other through the frame graph (each is
// the T of a FrameGraphId<T>; render/method.h lists the frame's handles).
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "cl/cl_runtime.h"
#include "gl/light_view.h"

namespace tsis {

// A CL buffer kept across frames and grown when a frame needs more.
struct GrowingBuffer {
    cl::Buffer buffer;
    size_t capacity = 0;
    cl::Buffer& reserve(const cl::Context& context, size_t bytes) {
        if (capacity < bytes || capacity == 0) {
            capacity = std::max<size_t>(bytes, 16);
            buffer = cl::Buffer(context, CL_MEM_READ_WRITE, capacity);
        }
        return buffer;
    }
};

// The methods' output on the CL side: B (float4, rgb) of each covered point,
// in `storage`, which is kept across frames. A resource the frame graph
// creates each frame, so that a method that forgets to write it fails the
// graph's check ("reads 'radiosity_cl' which no earlier pass writes").
struct RadiosityCl {
    GrowingBuffer* storage = nullptr;
};

// An atlas on the CL side: res² float4, atlas row order. `version` changes
// whenever the contents do (the flux with the lighting, the geometry with the
// mesh or the resolution), so methods can keep what they derived from it.
struct AtlasCl {
    cl::Buffer buffer;
    uint64_t version = 0;
};

// The covered camera pixels, packed.
struct SurfacePoints {
    int count = 0;
    cl::Buffer xyz;           // count float4 (xyz of each covered pixel)
    std::vector<float> host;  // the same float4s on the host
    std::vector<int> pixel;   // GL pixel index y*width+x (row 0 = bottom)
    // The albedo's exit factor of each point, rgb (render/albedo_atlas.h);
    // empty where every albedo is its medium's.
    std::vector<float> exitAlbedo;
    // The material slot of each point (SceneMedia): its texel's where a solid
    // holds several materials; else empty (its medium's, by its tag).
    std::vector<uint32_t> slot;
    // Each point's atlas coordinates (u, v), when a method asked for them
    // (FrameContext::pointUvs); else empty.
    std::vector<float> uvs;
    cl::Buffer uv;  // count float2, the same
};

// The camera's G-buffer on the CL side: width*height float4 each, GL row order.
struct CameraBuffersCl {
    cl::Buffer position;    // xyz, w = medium tag (1 + medium, mesh/media.h), 0 = uncovered
    cl::Buffer normal;      // xyz
    cl::Buffer irradiance;  // E rgb at the pixel's surface point (docs/design.md §2)
};

// The light views on the CL side: per light resolution² float4 (GL row order).
struct LightMapsCl {
    const std::vector<LightView>* views = nullptr;  // matrices in views[i].viewProj
    std::vector<cl::Buffer> flux;      // flux per texel rgb (docs/design.md §2), a = covered
    std::vector<cl::Buffer> position;  // xyz, w = distance to the light (mm)
};

// Radiosity B of every covered pixel, on the host: width*height RGBA, GL row
// order, a = 1 where covered; or where `texture` is set, a GL texture of the
// same (the lookup over the atlas, gl/passes.h RadiosityLookupPass) and
// rgba empty.
struct RadiosityImage {
    std::vector<float> rgba;
    unsigned texture = 0;
    int covered = 0;  // with `texture`, the covered pixels it holds B of
};

// A method's copy of B over the atlas on the host, for the composite to read
// B at the pixels from (render/radiosity_atlas.h): the texels' positions
// with their ring (w = medium tag, 0 for none) and B, res² float4 each, GL
// order; a pixel reads texels within maxMm of it. The keys change with the
// positions and with B.
struct AtlasRadiosity {
    const std::vector<float>* positions = nullptr;
    const std::vector<float>* radiosity = nullptr;
    int resolution = 0;
    float maxMm = 0;
    uint64_t positionsKey = 0, radiosityKey = 0;
};

}  // namespace tsis
