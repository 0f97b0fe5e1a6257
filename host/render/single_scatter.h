// Jensen et al. 2001's single-scattering term L⁽¹⁾ (docs/design.md "Single
// scattering"): light refracted in at xi, scattered once on the refracted
// camera ray and refracted out at xo. A renderer-level term, added once per
// frame to every profile method's radiosity (not volumetric's: its walk
// holds single scattering already), as π·L⁽¹⁾/Ft(η, cos θo) over the exit
// term's scale, so the composite's Ft/π·B·(scale) gives L⁽¹⁾ back.
#pragma once

#include <cstdint>
#include <functional>
#include <glm/vec3.hpp>
#include <vector>

#include "render/frame_graph.h"
#include "render/method.h"
#include "render/raster_passes.h"
#include "render/sparse_pixels.h"
#include "single_scatter_shared.h"

namespace tsis {

// Strata of each refracted camera ray's depth per light, each integrated in
// closed form over its middle's entry plane (single_scatter_test.cpp: two
// overshoot the walk past the shadow line; against volumetric, three are
// four's to 0.1 point on the skin1 scenes of bench/results/model_truth.md
// and two cost up to 1.4 points).
constexpr int kSingleScatterStrata = 3;

// The scatter views' texels (scatterViewResolution): the term follows the
// surface on the scale of a mean free path, finer than the shadow maps need.
constexpr double kScatterTexelsPerMfp = 4.0;
constexpr int kScatterMinResolution = 256;
// Past it a view's two maps cost more to read back than the term gains (a
// 2048² pair is 128 MB a light).
constexpr int kScatterMaxResolution = 1024;
// The sparse grid's spacing is the pyramid's rule for an ℓ this many
// smallest mean free paths: L⁽¹⁾ has no r⁻¹ peak to follow (cow in marble
// at 512², every 4th pixel against every one: 0.8 % rel. RMSE of the
// radiance, below the term's own texel steps, 1.7-2.7 % between 256² and
// 1024² views).
constexpr double kScatterGridMfp = 2.0;

// The scatter views' resolution (gl/light_view.h updateScatterView):
// kScatterTexelsPerMfp texels a smallest mean free path 1/max σt′ of the
// scene's media across the object's bounding sphere, within
// [kScatterMinResolution, kScatterMaxResolution] and at most the shadow
// maps' resolution.
int scatterViewResolution(const FrameContext& ctx);

// The kernel's medium: σs′, σt′, η and π over the exit term's scale.
TsisScatterMedium scatterMedium(const Material& m, ExitTerm exit);
// The kernel's light.
TsisScatterLight scatterLight(const Light& light);

// Where the light's ray to an interior point enters: the surface point and
// its outward normal, or lit = false where no light of the point's medium
// arrives (the light view's texel there).
struct ScatterEntry {
    bool lit = false;
    glm::dvec3 point{0.0}, normal{0.0};
};
using EntryOf = std::function<ScatterEntry(const glm::dvec3& x)>;

// A scatter view made from a shadow map (ScatterViewPass::copyDepth): the
// window depth of each texel (GL order, 1 where no surface) and the light's
// projection. The kernel's reading of it (TSIS_SCATTER_FROM_DEPTH) in
// double: the texel's point unprojected, the facet's normal from the
// neighbours' depths, one-sided towards the neighbour whose depth is nearer
// (an occluding edge or the silhouette on the other side); a texel without
// a neighbour holding a surface along either axis is none.
struct DepthView {
    const std::vector<float>* depth = nullptr;
    int resolution = 0;
    glm::dmat4 viewProj{1.0};
};
ScatterEntry depthViewTexel(const DepthView& view, int x, int y);
// The texel under x's projection (lit = false outside the view).
ScatterEntry depthViewEntry(const DepthView& view, const glm::dvec3& x);

// The kernel's R = L⁽¹⁾/Ft(η, cos θo) at xo (normal n, seen from eye) for
// one light, in double: the same strata, the entry points from `entry`.
glm::dvec3 singleScatterHost(const glm::dvec3& xo, const glm::dvec3& n, const glm::dvec3& eye,
                             const TsisScatterMedium& medium, const Light& light,
                             const EntryOf& entry, int strata);

// The frame's pass: B += to_radiosity·R at every covered point, summed over
// the lights, after the methods' radiosity came back to the host. R is
// evaluated on a sparse grid (render/sparse_pixels.h: spacing by the
// smallest mean free path, kScatterGridMfp) and interpolated between.
class SingleScatter {
  public:
    explicit SingleScatter(ClRuntime& cl);
    void addPass(FrameGraph& graph, const FrameContext& ctx, const RasterHandles& gl,
                 FrameGraphId<RadiosityImage> radiosity);

  private:
    ClRuntime& cl_;
    cl::Kernel drawn_, fromDepth_;  // views drawn, or the shadow maps' depth
    SparseInterpolation interpolation_;
    SparsePixels plan_;
    uint64_t planKey_ = 0;
    GrowingBuffer normals_, media_, out_;
    std::vector<GrowingBuffer> views_;
    uint64_t normalsOf_ = 0, viewsOf_ = 0;  // G-buffer and scatter-view versions
};

}  // namespace tsis
