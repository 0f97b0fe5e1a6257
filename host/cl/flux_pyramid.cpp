#include "cl/flux_pyramid.h"

#include <algorithm>
#include <bit>
#include <numeric>

#include "cl/importance_sampler.h"
#include "cl/launch.h"
#include "util/error.h"

namespace tsis {
namespace {

constexpr size_t kLocal = 64;       // build kernels
constexpr size_t kLocalGather = 4;  // as the lane gather (cl/gather.cpp)

}  // namespace

FluxPyramid::FluxPyramid(ClRuntime& cl)
    : cl_(cl),
      leaves_(cl.kernel("flux_pyramid.cl", "tsis_flux_leaves")),
      reduce_(cl.kernel("flux_pyramid.cl", "tsis_flux_reduce")),
      split_(cl.kernel("gather.cl", "tsis_profile_split")),
      gather_(cl.kernel("flux_pyramid.cl", "tsis_flux_pyramid_gather")) {}

void FluxPyramid::build(const cl::Buffer& flux, const cl::Buffer& position,
                        const cl::Buffer& normal, int res) {
    TSIS_CHECK(res >= 1 && std::has_single_bit(static_cast<unsigned>(res)));
    const int levels = std::countr_zero(static_cast<unsigned>(res));
    TSIS_CHECK_LE(levels, TSIS_PYRAMID_MAX_LEVELS);
    const size_t texels = size_t(res) * res;
    for (const cl::Buffer* b : {&flux, &position, &normal})
        TSIS_CHECK_GE(b->getInfo<CL_MEM_SIZE>(), texels * sizeof(cl_float4));
    if (res != res_) {
        nodes_ = cl::Buffer(cl_.context(), CL_MEM_READ_WRITE,
                            ImportanceSampler::pyramidSize(res) * sizeof(TsisFluxNode));
        res_ = res;
    }
    cl::CommandQueue& q = cl_.queue();
    buildEvents_.assign(levels + 1, cl::Event());
    setKernelArgs(leaves_, flux, position, normal, static_cast<cl_int>(texels), nodes_);
    enqueue1D(q, leaves_, texels, kLocal, &buildEvents_[0]);
    for (int k = 1; k <= levels; ++k) {
        const int dstRes = res >> k;
        setKernelArgs(reduce_, nodes_,
                      static_cast<cl_int>(ImportanceSampler::levelOffset(res, k - 1)),
                      static_cast<cl_int>(ImportanceSampler::levelOffset(res, k)), dstRes);
        enqueue1D(q, reduce_, size_t(dstRes) * dstRes, kLocal, &buildEvents_[k]);
    }
}

std::vector<int> FluxPyramid::tileOrder(const std::vector<int>& pixels, int width) {
    constexpr int kTileW = 4, kTileH = 2;  // kTileW·kTileH = kPointsPerItem
    static_assert(kTileW * kTileH == kPointsPerItem);
    const int tilesPerRow = (width + kTileW - 1) / kTileW;
    auto tile = [&](int pixel) {
        return static_cast<long long>(pixel / width / kTileH) * tilesPerRow +
               pixel % width / kTileW;
    };
    std::vector<int> order(pixels.size());
    std::iota(order.begin(), order.end(), 0);
    // Stable: within a tile the pixels keep their row-major order.
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return tile(pixels[a]) < tile(pixels[b]); });
    return order;
}

void FluxPyramid::gather(const cl::Buffer& points, const cl::Buffer& order, int count,
                         float epsilon, float ell, const cl::Buffer& table,
                         const TsisTableInfo& info, cl::Buffer& out) {
    TSIS_CHECK_GT(res_, 0);  // build() first
    TSIS_CHECK_GE(count, 0);
    TSIS_CHECK_GE(info.size, 2u);
    gatherEvents_.clear();
    lastItems_ = (count + kPointsPerItem - 1) / kPointsPerItem;
    if (count == 0) return;
    TSIS_CHECK_GE(points.getInfo<CL_MEM_SIZE>(), size_t(count) * sizeof(cl_float4));
    TSIS_CHECK_GE(order.getInfo<CL_MEM_SIZE>(), size_t(count) * sizeof(cl_int));
    TSIS_CHECK_GE(out.getInfo<CL_MEM_SIZE>(), size_t(count) * sizeof(cl_float4));
    cl::CommandQueue& q = cl_.queue();
    if (splitEntries_ < info.size) {
        splitTable_ =
            cl::Buffer(cl_.context(), CL_MEM_READ_WRITE, size_t(info.size) * 3 * sizeof(cl_float2));
        splitEntries_ = info.size;
    }
    if (evaluationItems_ < size_t(lastItems_)) {
        evaluations_ = cl::Buffer(cl_.context(), CL_MEM_READ_WRITE, lastItems_ * sizeof(cl_int));
        evaluationItems_ = lastItems_;
    }
    setKernelArgs(split_, table, info, splitTable_);
    gatherEvents_.emplace_back();
    enqueue1D(q, split_, info.size, 64, &gatherEvents_.back());
    const int levels = std::countr_zero(static_cast<unsigned>(res_));
    setKernelArgs(gather_, points, order, count, nodes_, res_, levels, epsilon, ell * ell,
                  splitTable_, info, out, evaluations_);
    gatherEvents_.emplace_back();
    enqueue1D(q, gather_, size_t(lastItems_), kLocalGather, &gatherEvents_.back());
}

long long FluxPyramid::lastEvaluations() {
    if (lastItems_ == 0 || gatherEvents_.empty()) return 0;
    std::vector<cl_int> used(size_t(lastItems_), 0);
    cl_.queue().enqueueReadBuffer(evaluations_, CL_TRUE, 0, used.size() * sizeof(cl_int),
                                  used.data());
    // Each node used whole is evaluated for all the item's lanes.
    return std::accumulate(used.begin(), used.end(), 0LL) * kPointsPerItem;
}

double FluxPyramid::lastBuildMs() const {
    return eventMilliseconds(buildEvents_);
}

double FluxPyramid::lastGatherMs() const {
    return eventMilliseconds(gatherEvents_);
}

}  // namespace tsis
