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
    // w = medium tag, 0 uncovered) and a ring around each chart (withRing),
    // and the grid they are evaluated on, made again when `key` changed.
    // Blocking uploads.
    void plan(const std::vector<float>& positions, int resolution, int stride, float maxCornerMm,
              float sameSurfaceMm, uint64_t key);
    // The position atlas with the uncovered texels beside a chart given the
    // chart's surface continued straight on: p1 + (p1 − p2) through the two
    // texels next to it in a row, column or diagonal (within sameSurfaceMm
    // of each other: one surface), averaged over the directions that agree.
    // B is then evaluated there too, and a point in a chart's outermost half
    // texel reads B interpolated, not held at the last texel's value.
    static std::vector<float> withRing(const std::vector<float>& positions, int resolution,
                                       float sameSurfaceMm);
    // What the gather reads and writes: the texels' positions (the atlas
    // with its ring, float4), the texels to evaluate (in groups of 8
    // neighbours) and B, an image of the same texels (float4; those without
    // a position undefined).
    const cl::Buffer& points() const { return xyz_.buffer; }
    const cl::Buffer& order() const { return interpolation_.order(); }
    int evaluated() const { return static_cast<int>(plan_.evaluate.size()); }
    int covered() const { return covered_; }
    cl::Buffer& values() { return b_.buffer; }
    // After the gather: B of the texels between the grid's, on the device.
    void interpolate() {
        interpolation_.run(b_.buffer);
        hostCurrent_ = false;
    }
    // The same on the host (AtlasRadiosity): the positions with their ring,
    // and B, read back once after each making.
    const std::vector<float>& ringPositions() const { return ring_; }
    const std::vector<float>& hostValues();

    // B of each point (float4, to `out`) bilinearly from the 2×2 texels
    // around its atlas coordinates that hold its surface (of the atlas
    // planned, with its ring: of its medium, within maxMm in space, so a
    // chart packed beside it is not read); returns the points with none,
    // which it leaves for the caller to gather (a sliver chart holds no texel
    // centre). Waits for the kernel.
    std::vector<int> lookup(const SurfacePoints& points, float maxMm, cl::Buffer& out);
    double lastInterpolateMs() const { return interpolation_.lastMs(); }
    double lastLookupMs() const;

  private:
    ClRuntime& cl_;
    cl::Kernel lookup_;
    SparsePixels plan_;
    SparseInterpolation interpolation_;
    GrowingBuffer xyz_, b_, none_;
    std::vector<float> ring_, hostB_;
    bool hostCurrent_ = false;
    int resolution_ = 0, covered_ = 0;
    uint64_t key_ = 0;
    cl::Event lookupEvent_;
};

}  // namespace tsis
