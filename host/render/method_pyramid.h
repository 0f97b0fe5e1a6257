// --method pyramid: error-bounded integration over the flux tree, an octree of
// the flux atlas' texels (beyond the thesis, docs/design.md §6; cl/flux_tree.h,
// kernels/flux_tree.cl). "pyramid" is the user's name for the method; the
// tree is not a pyramid (the CDF pyramid is tsis').
//
// The thesis draws N samples from the flux atlas' sum pyramid; Jensen &
// Buhler sum an octree of irradiance samples top-down, using a node whole
// when it is small as seen from the point. This method does the second on the
// first's data: the atlas texels are the leaves of an octree over their
// positions (their 3D Morton codes sorted once per mesh and atlas resolution,
// up to 8 children a node, so atlas neighbours from unrelated charts never
// share a node); each node keeps flux, area, flux-weighted position and a radius
// bounding it, rebuilt on the device each time the flux atlas changes, and
// every group of 8 neighbouring pixels descends it with the criterion
// max(radius², area/π) < ε·(d² + ℓ²), ℓ the smallest mean free path. No
// random numbers (the same image for any --seed), no Rp or K to tune, and the
// error falls with ε (--pyramid-epsilon) at a cost that grows like 1/ε.
//
// B is evaluated on a grid of every s-th pixel and interpolated between where
// the cell is one surface (render/sparse_pixels.h): s = --pyramid-stride, or
// by default the largest of 1, 2, 4 whose grid spacing at the target's
// distance is at most ℓ/4, so the interpolation spans a fraction of the
// scale on which B changes.
#pragma once

#include "cl/flux_tree.h"
#include "render/method.h"
#include "render/profile_table_cache.h"
#include "render/radiosity_atlas.h"
#include "render/sparse_pixels.h"

namespace tsis {

class PyramidMethod : public Method {
  public:
    explicit PyramidMethod(ClRuntime& cl);
    const char* name() const override { return "pyramid"; }
    void addPasses(FrameGraph& graph, const FrameContext& ctx) override;
    // The copy over the atlas when made for this frame's surface; with
    // --pyramid-cache camera only while the camera moves (a still view
    // gathers at its pixels), never with off.
    const AtlasRadiosity* atlasRadiosity(const FrameContext& ctx) override;

    // B over the atlas: a point reads texels within this many texel sides.
    static constexpr double kLookupTexels = 4;

  private:
    // Each returns its device milliseconds.
    double build(const FrameContext& ctx, const AtlasCl& flux, const AtlasCl& position,
                 const AtlasCl& normal, FrameStats& stats);
    double gather(const FrameContext& ctx, const SurfacePoints& points, cl::Buffer& radiosity,
                  FrameStats& stats);
    // B at the `count` points order[] names (FluxTree::gather with this
    // frame's table), to out; its device ms.
    double gatherTree(const cl::Buffer& points, const cl::Buffer& order, int count, float epsilon,
                      double ell, cl::Buffer& out);
    double gatherAtPixels(const FrameContext& ctx, const SurfacePoints& points, double ell,
                          cl::Buffer& radiosity, FrameStats& stats);
    double gatherFromAtlas(const FrameContext& ctx, const SurfacePoints& points,
                           uint64_t surfaceKey, double ell, cl::Buffer& radiosity,
                           FrameStats& stats);

    ClRuntime& cl_;
    FluxTree tree_;
    ProfileTableCache rd_;
    uint64_t leavesVersion_ = 0;  // the position atlas' version of the leaf order (0: none)
    // What the node sums were made from (the flux atlas' version,
    // leavesVersion_, the normal atlas' version: its areas).
    uint64_t builtFluxVersion_ = 0, builtLeavesVersion_ = 0, builtNormalVersion_ = 0;
    // The last plan of the pixels to evaluate and to interpolate, and what it
    // was made from (the points, the image size, the grid): on the device in
    // interpolation_.
    SparseInterpolation interpolation_;
    SparsePixels plan_;
    uint64_t planKey_ = 0;
    // What the last frame's B was made of (the surface's B: sums, table,
    // ε, ℓ): a frame with the same surface key whose camera moved
    // (FrameContext::cameraMoved) only moved the camera.
    uint64_t lastSurfaceKey_ = 0, tableVersion_ = 0;
    // B over the atlas (render/radiosity_atlas.h), made for atlasKey_ from
    // the position atlas' host copy; texelMm_ the mean texel's side.
    RadiosityAtlas atlas_;
    std::vector<float> atlasPositions_;
    double texelMm_ = 0;
    uint64_t atlasKey_ = 0;
    GrowingBuffer offAtlas_;  // the points the copy has no texel for, to gather
    // What the copy was made for (copyKey: the lighting, the profile, the
    // options), and the copy as atlasRadiosity hands it on (set when made).
    static uint64_t copyKey(const FrameContext& ctx);
    uint64_t copyKey_ = 0;
    AtlasRadiosity host_;
};

}  // namespace tsis
