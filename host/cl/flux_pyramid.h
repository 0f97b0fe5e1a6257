// The flux pyramid (kernels/flux_pyramid.cl): the flux atlas summed in 2×2
// blocks like the thesis' CDF pyramid, each block also keeping its area,
// flux-weighted position and a radius bounding its texels in 3D; and B at
// output points by an error-bounded descent of it (Jensen & Buhler's
// criterion on the atlas' blocks instead of an octree). --method pyramid.
#pragma once

#include <vector>

#include "cl/cl_runtime.h"
#include "tsis_shared.h"

namespace tsis {

class FluxPyramid {
  public:
    explicit FluxPyramid(ClRuntime& cl);

    // flux: res² float4 (rgb flux per texel); position: res² float4 (xyz, w > 0
    // where covered); normal: the geometry atlas' normals, w = texel area
    // (mm²). res a power of two ≤ 2^TSIS_PYRAMID_MAX_LEVELS.
    void build(const cl::Buffer& flux, const cl::Buffer& position, const cl::Buffer& normal,
               int res);

    // out[j] = (B(points[j]).rgb, 0) = Σ over the cut flux_n ⊙ f(|x_j − p_n|),
    // the points taken in groups of kPointsPerItem in the order `order` (a
    // permutation of 0…count−1; neighbours in it should be near each other),
    // f the float4 table (ProfileTable::rgba layout). A node is used whole
    // when max(radius², area/π) < epsilon·(d² + ell²) (flux_pyramid.cl); ell
    // the smallest mean free path (mm). Needs build() first.
    void gather(const cl::Buffer& points, const cl::Buffer& order, int count, float epsilon,
                float ell, const cl::Buffer& table, const TsisTableInfo& info, cl::Buffer& out);

    // Nodes used whole by the last gather, summed over all points (reads back).
    long long lastEvaluations();
    double lastBuildMs() const;   // CL profiling (waits)
    double lastGatherMs() const;  // CL profiling (waits)

    const cl::Buffer& nodes() const { return nodes_; }
    int res() const { return res_; }
    // Points per work-item: the points that share one cut.
    static constexpr int kPointsPerItem = 8;

    // A permutation of the pixels `pixels` (indices y·width + x, ascending)
    // that groups them by tiles of 4×2 pixels, so runs of 8 are neighbours.
    static std::vector<int> tileOrder(const std::vector<int>& pixels, int width);

  private:
    ClRuntime& cl_;
    cl::Kernel leaves_, reduce_, split_, gather_;
    cl::Buffer nodes_, splitTable_, evaluations_;
    size_t splitEntries_ = 0, evaluationItems_ = 0;
    int res_ = 0, lastItems_ = 0;
    std::vector<cl::Event> buildEvents_, gatherEvents_;
};

}  // namespace tsis
