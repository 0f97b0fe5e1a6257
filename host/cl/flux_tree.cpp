#include "cl/flux_tree.h"

#include <algorithm>
#include <glm/common.hpp>
#include <glm/gtc/type_precision.hpp>
#include <glm/vec3.hpp>
#include <limits>
#include <numeric>
#include <tuple>
#include <utility>

#include "cl/launch.h"
#include "util/error.h"

namespace tsis {
namespace {

constexpr size_t kLocalGather = 4;  // as the lane gather (cl/gather.cpp)

}  // namespace

FluxTree::FluxTree(ClRuntime& cl)
    : cl_(cl),
      update_(cl.kernel("flux_tree.cl", "tsis_flux_tree_update")),
      split_(cl.kernel("gather.cl", "tsis_profile_split")),
      gather_(cl.kernel("flux_tree.cl", "tsis_flux_tree_gather")) {}

void FluxTree::setLeaves(const std::vector<float>& positionRGBA) {
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (size_t i = 0; i + 3 < positionRGBA.size(); i += 4)
        if (positionRGBA[i + 3] > 0) {
            const glm::vec3 p(positionRGBA[i], positionRGBA[i + 1], positionRGBA[i + 2]);
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
    // 21 bits of x, y and z interleaved: a 63-bit Morton code.
    auto spread = [](uint64_t v) {
        v &= 0x1fffff;
        v = (v | (v << 32)) & 0x001f00000000ffffull;
        v = (v | (v << 16)) & 0x001f0000ff0000ffull;
        v = (v | (v << 8)) & 0x100f00f00f00f00full;
        v = (v | (v << 4)) & 0x10c30c30c30c30c3ull;
        v = (v | (v << 2)) & 0x1249249249249249ull;
        return v;
    };
    const glm::vec3 scale = 2097151.0f / glm::max(hi - lo, glm::vec3(1e-30f));
    // Sorted by medium (the position's w, mesh/media.h), then code, then texel.
    struct Leaf {
        int medium;
        uint64_t code;
        int texel;
        bool operator<(const Leaf& o) const {
            return std::tie(medium, code, texel) < std::tie(o.medium, o.code, o.texel);
        }
    };
    std::vector<Leaf> keyed;
    for (size_t i = 0; i + 3 < positionRGBA.size(); i += 4) {
        if (!(positionRGBA[i + 3] > 0)) continue;
        const glm::vec3 q =
            (glm::vec3(positionRGBA[i], positionRGBA[i + 1], positionRGBA[i + 2]) - lo) * scale;
        const glm::u64vec3 c(glm::clamp(q + 0.5f, glm::vec3(0.0f), glm::vec3(2097151.0f)));
        keyed.push_back({static_cast<int>(positionRGBA[i + 3]),
                         spread(c.x) | (spread(c.y) << 1) | (spread(c.z) << 2),
                         static_cast<int>(i / 4)});
    }
    std::sort(keyed.begin(), keyed.end());
    leafTexels_.clear();
    for (const Leaf& k : keyed) leafTexels_.push_back(k.texel);

    // Breadth first, so children are contiguous and each depth is a range.
    struct Range {
        size_t begin, end;
        int shift, depth;
    };
    std::vector<Range> queue = {{0, std::max<size_t>(keyed.size(), 1), 63, 0}};
    topology_.clear();
    depthBegin_.clear();
    for (size_t q = 0; q < queue.size(); ++q) {
        const Range r = queue[q];
        if (depthBegin_.size() <= size_t(r.depth)) depthBegin_.push_back(static_cast<int>(q));
        if (keyed.empty()) {
            // An atlas without texels: one leaf of texel 0, which is uncovered.
            topology_.push_back({{0, 0, 0, 0}});
            continue;
        }
        const int medium = keyed[r.begin].medium == keyed[r.end - 1].medium ? keyed[r.begin].medium
                                                                            : 0;  // several
        if (r.end - r.begin == 1) {
            topology_.push_back({{0, 0, keyed[r.begin].texel, medium}});
            continue;
        }
        std::vector<Range> children;
        if (medium == 0) {
            // Several media: one child each, or up to 8 runs of them.
            std::vector<size_t> starts;
            for (size_t k = r.begin; k < r.end; ++k)
                if (k == r.begin || keyed[k].medium != keyed[k - 1].medium) starts.push_back(k);
            const size_t parts = std::min<size_t>(8, starts.size());
            for (size_t k = 0; k < parts; ++k) {
                const size_t b = starts[starts.size() * k / parts];
                const size_t e = k + 1 < parts ? starts[starts.size() * (k + 1) / parts] : r.end;
                children.push_back({b, e, 63, r.depth + 1});
            }
        }
        // The next 3 bits that do not all agree split the range by octant.
        for (int shift = r.shift - 3; shift >= 0 && children.empty(); shift -= 3) {
            auto octant = [&](size_t k) { return (keyed[k].code >> shift) & 7; };
            if (octant(r.begin) == octant(r.end - 1)) continue;
            for (size_t b = r.begin; b < r.end;) {
                size_t e = b;
                while (e < r.end && octant(e) == octant(b)) ++e;
                children.push_back({b, e, shift, r.depth + 1});
                b = e;
            }
        }
        if (children.empty()) {  // texels that share a code: up to 8 even parts
            const size_t n = r.end - r.begin, parts = std::min<size_t>(8, n);
            for (size_t k = 0; k < parts; ++k)
                children.push_back(
                    {r.begin + n * k / parts, r.begin + n * (k + 1) / parts, 0, r.depth + 1});
        }
        topology_.push_back(
            {{static_cast<int>(queue.size()), static_cast<int>(children.size()), -1, medium}});
        queue.insert(queue.end(), children.begin(), children.end());
    }
    depthBegin_.push_back(static_cast<int>(queue.size()));
    TSIS_CHECK_LE(depthBegin_.size(), size_t(TSIS_FLUX_TREE_MAX_DEPTH + 2));
    topologyBuffer_ = cl::Buffer(cl_.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                                 topology_.size() * sizeof(cl_int4), topology_.data());
    nodes_ = cl::Buffer(cl_.context(), CL_MEM_READ_WRITE, topology_.size() * sizeof(TsisFluxNode));
}

void FluxTree::build(const cl::Buffer& flux, const cl::Buffer& position, const cl::Buffer& normal,
                     bool fluxOnly) {
    TSIS_CHECK(!topology_.empty());  // setLeaves() first
    cl::CommandQueue& q = cl_.queue();
    buildEvents_.clear();
    // The deepest nodes first: each depth reads the one below it (in-order queue).
    for (size_t d = depthBegin_.size() - 1; d-- > 0;) {
        const int begin = depthBegin_[d], end = depthBegin_[d + 1];
        setKernelArgs(update_, flux, position, normal, topologyBuffer_, begin, end,
                      fluxOnly ? 1 : 0, nodes_);
        buildEvents_.emplace_back();
        enqueue1D(q, update_, size_t(end - begin), kLocalSize, &buildEvents_.back());
    }
}

std::vector<int> FluxTree::tileOrder(const std::vector<int>& pixels, int width) {
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

void FluxTree::gather(const cl::Buffer& points, const cl::Buffer& order, int count, float epsilon,
                      float ell, const cl::Buffer& table, const TsisTableInfo& info,
                      cl::Buffer& out) {
    TSIS_CHECK(!topology_.empty());  // setLeaves() and build() first
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
    setKernelArgs(gather_, points, order, count, nodes_, topologyBuffer_, epsilon, ell * ell,
                  splitTable_, info, out, evaluations_);
    gatherEvents_.emplace_back();
    enqueue1D(q, gather_, size_t(lastItems_), kLocalGather, &gatherEvents_.back());
}

long long FluxTree::lastEvaluations() {
    if (lastItems_ == 0 || gatherEvents_.empty()) return 0;
    std::vector<cl_int> used(size_t(lastItems_), 0);
    cl_.queue().enqueueReadBuffer(evaluations_, CL_TRUE, 0, used.size() * sizeof(cl_int),
                                  used.data());
    // Each node used whole is evaluated for all the item's lanes.
    return std::accumulate(used.begin(), used.end(), 0LL) * kPointsPerItem;
}

double FluxTree::lastBuildMs() const {
    return eventMilliseconds(buildEvents_);
}

double FluxTree::lastGatherMs() const {
    return eventMilliseconds(gatherEvents_);
}

}  // namespace tsis
