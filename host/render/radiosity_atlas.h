// The pyramid's copy of B over the atlas (docs/design.md §6 "B over the
// atlas"). A frame that only moves the camera keeps the flux, so B on the
// surface is the one the last frames gathered; made once over the atlas'
// covered texels (on a grid of every s-th texel, interpolated between where
// the cell is one surface: render/sparse_pixels.h, the atlas as the image),
// it gives each new pixel its B from the texels around its atlas coordinates
// (kernels/radiosity_atlas.cl) instead of a gather at every new pixel.
#pragma once

#include <cstdint>
#include <vector>

#include "cl/cl_runtime.h"
#include "render/frame_resources.h"
#include "render/sparse_pixels.h"

namespace tsis {

class RadiosityAtlas {
  public:
    explicit RadiosityAtlas(ClRuntime& cl);

    // The covered texels of the position atlas (res² float4 on the host,
    // w = medium tag, 0 uncovered) and the grid they are evaluated on,
    // made again when `key` changed. Blocking uploads.
    void plan(const std::vector<float>& positions, int resolution, int stride, float maxCornerMm,
              uint64_t key);
    // What the gather writes, over the position atlas as its points: the
    // texels to evaluate (in groups of 8 neighbours) and B, an image of the
    // atlas' texels (float4; uncovered ones undefined).
    const cl::Buffer& order() const { return order_.buffer; }
    int evaluated() const { return static_cast<int>(plan_.evaluate.size()); }
    int covered() const { return covered_; }
    cl::Buffer& values() { return b_.buffer; }
    // After the gather: B of the texels between the grid's, on the device.
    void interpolate() { interpolation_.run(b_.buffer); }

    // B of each point (float4, count of them) from its atlas coordinates
    // (points.uv) and position, to `out`; texels of the position atlas (the
    // one planned) farther than maxMm from a point are not its surface.
    // Enqueues without waiting.
    void lookup(const SurfacePoints& points, const cl::Buffer& positionAtlas, float maxMm,
                cl::Buffer& out);
    double lastInterpolateMs() const { return interpolation_.lastMs(); }
    double lastLookupMs() const;

  private:
    ClRuntime& cl_;
    cl::Kernel lookup_;
    SparsePixels plan_;
    SparseInterpolation interpolation_;
    GrowingBuffer order_, b_;
    int resolution_ = 0, covered_ = 0;
    uint64_t key_ = 0;
    cl::Event lookupEvent_;
};

}  // namespace tsis
