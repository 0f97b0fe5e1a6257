// The flux tree (kernels/flux_tree.cl): the covered texels of the flux
// atlas as the leaves of an octree over their 3D positions (built once per
// mesh and atlas resolution), each node summing its texels' flux and area
// and keeping their flux-weighted position and a radius bounding them, the
// sums made again on the device whenever the flux changes; and B at output
// points by an error-bounded descent of it (Jensen & Buhler's criterion with
// atlas texels for irradiance samples). --method pyramid.
#pragma once

#include <vector>

#include "cl/cl_runtime.h"
#include "tsis_shared.h"

namespace tsis {

class FluxTree {
  public:
    explicit FluxTree(ClRuntime& cl);

    // The tree's leaves and shape from the atlas' float4 positions (res²,
    // w > 0 where covered): the covered texels sorted by their 3D Morton
    // codes (21 bits an axis over the bounding box; ties by texel index), an
    // octree over them with single-child levels skipped. Kept until set again
    // (the positions change only with the mesh or the atlas resolution).
    void setLeaves(const std::vector<float>& positionRGBA);

    // The node sums from this atlas: flux (float4 rgb per texel), position
    // (xyz, w > 0 where covered) and the geometry atlas' normals (w = texel
    // area, mm²), the atlas setLeaves() saw. Needs setLeaves() first.
    // `fluxOnly`: the last build had this position and normal atlas (the
    // caller knows their versions), so the leaves take only the flux.
    void build(const cl::Buffer& flux, const cl::Buffer& position, const cl::Buffer& normal,
               bool fluxOnly = false);

    // out[j] = (B(points[j]).rgb, 0) = Σ over the cut flux_n ⊙ f(|x_j − p_n|),
    // the points taken in groups of kPointsPerItem in the order `order` (count
    // indices into points; neighbours in it should be near each other), f the
    // float4 table (ProfileTable::rgba layout). A node is used whole when
    // max(radius², area/π) < epsilon·(d² + ell²) (flux_tree.cl); ell the
    // smallest mean free path (mm). Needs build() first.
    void gather(const cl::Buffer& points, const cl::Buffer& order, int count, float epsilon,
                float ell, const cl::Buffer& table, const TsisTableInfo& info, cl::Buffer& out);

    // Nodes used whole by the last gather times the points per item (reads back).
    long long lastEvaluations();
    double lastBuildMs() const;   // CL profiling (waits)
    double lastGatherMs() const;  // CL profiling (waits)

    // The tree: nodes in breadth-first order, root 0; topology (first child,
    // children, texel, 0) per node, children = 0 for a leaf; the covered
    // texels in Morton order.
    const cl::Buffer& nodes() const { return nodes_; }
    const std::vector<cl_int4>& topology() const { return topology_; }
    const std::vector<int>& leafTexels() const { return leafTexels_; }
    int depth() const { return static_cast<int>(depthBegin_.size()) - 2; }
    // Points per work-item: the points that share one cut.
    static constexpr int kPointsPerItem = 8;

    // A permutation of the pixels `pixels` (indices y·width + x, ascending)
    // that groups them by tiles of 4×2 pixels, so runs of 8 are neighbours.
    static std::vector<int> tileOrder(const std::vector<int>& pixels, int width);

  private:
    ClRuntime& cl_;
    cl::Kernel update_, split_, gather_;
    cl::Buffer nodes_, topologyBuffer_, splitTable_, evaluations_;
    std::vector<cl_int4> topology_;
    std::vector<int> depthBegin_;  // first node of each depth, then the node count
    std::vector<int> leafTexels_;
    size_t splitEntries_ = 0, evaluationItems_ = 0;
    int lastItems_ = 0;
    std::vector<cl::Event> buildEvents_, gatherEvents_;
};

}  // namespace tsis
