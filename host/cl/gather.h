// The gather B(xo_j) = Σ_i w_i ⊙ f(|xo_j − x_i|) of a tabulated radial profile
// f over weighted samples: the global term (f = Rd·Wg), plain TSIS (f = Rd)
// and, with dense samples, the reference. Kernel: kernels/gather.cl.
#pragma once

#include <vector>

#include "cl/cl_runtime.h"
#include "tsis_shared.h"

namespace tsis {

class Gatherer {
  public:
    // Output points per work-item: 1 (one point per work-item, scalar on PoCL)
    // or 8/16 (points in vector lanes; vectorises on CPU devices). The default
    // measured fastest on PoCL here (bench/bench_kernels.cpp): 8 ≈ 16 ≈ 1.8× of 1.
    static constexpr int kDefaultPointsPerItem = 8;
    // Vector widths only: the (value, step) pairs of r, g, b in one 32-byte
    // row per table entry instead of three tables (kernels/gather.cl).
    static constexpr bool kDefaultInterleaved = false;
    explicit Gatherer(ClRuntime& cl, int pointsPerItem = kDefaultPointsPerItem,
                      bool interleaved = kDefaultInterleaved);

    // points: count float4 (xyz, w ignored); samples: n TsisSample; table:
    // info.size float4 entries (ProfileTable::rgba); out: count float4 (B rgb, 0).
    void run(const cl::Buffer& points, int count, const cl::Buffer& samples, int n,
             const cl::Buffer& table, const TsisTableInfo& info, cl::Buffer& out);

    double lastMs() const;  // CL profiling of the last run (waits for it)
    long long lastEvaluations() const { return lastEvaluations_; }  // count * n

  private:
    ClRuntime& cl_;
    int width_;
    bool interleaved_;
    cl::Kernel split_;  // per-channel (value, step) table, for width > 1
    cl::Kernel gather_;
    cl::Buffer splitTable_;
    size_t splitEntries_ = 0;
    std::vector<cl::Event> events_;
    long long lastEvaluations_ = 0;
};

}  // namespace tsis
