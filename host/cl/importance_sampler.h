// Texture-space importance sampling of the flux atlas (thesis ch. 3.2): a sum
// pyramid of luminance in mipmap order, then N samples by descending it
// (Algorithm 3.1 as corrected in docs/design.md §3). Kernels: kernels/pyramid.cl,
// kernels/sample.cl.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "cl/cl_runtime.h"
#include "tsis_shared.h"

namespace tsis {

class ImportanceSampler {
  public:
    explicit ImportanceSampler(ClRuntime& cl);

    // flux: res*res float4 texels (rgb flux, a unused), index y*res + x; res a
    // power of two ≥ 1. Builds the pyramid of Y = dot(rgb, luma) (negative or
    // NaN Y counts as 0): level 0 = res², level k = (res>>k)², top = 1 texel.
    void buildPyramid(const cl::Buffer& flux, int res);
    double totalLuminance();  // ΣY, the pyramid's top (one 4-byte read)

    // n samples with u_i = frac((i + ξ)/n), ξ = seedOffset(seed, sampleSet).
    // samples[i] = {position[texel].xyz, texel, w = Φ(texel)·ΣY/(n·Y(texel))};
    // all weights 0 when ΣY = 0. Needs buildPyramid(flux, res) first.
    void draw(const cl::Buffer& flux, const cl::Buffer& position, int res, int n, uint32_t seed,
              cl::Buffer& samples, uint32_t sampleSet = 0);
    // The same with ξ given (0 ≤ xi < 1): for tests and for callers that
    // choose their own offset sequence.
    void drawWithOffset(const cl::Buffer& flux, const cl::Buffer& position, int res, int n,
                        float xi, cl::Buffer& samples);

    const cl::Buffer& pyramid() const { return pyramid_; }
    double lastPyramidMs() const;  // CL profiling, all levels (waits for them)
    double lastDrawMs() const;     // waits for the draw

    // Start of level k in pyramid() (in floats) and the pyramid's length.
    static size_t levelOffset(int res, int level);
    static size_t pyramidSize(int res);
    // ξ for a seed: the top 24 bits of a 32-bit integer hash, over 2^24, moved
    // by sampleSet times the golden ratio's fraction (mod 1). Successive sets'
    // offsets stay evenly spread, so the union of K sets is stratified like one
    // set of K·n samples (progressive accumulation averages them).
    static float seedOffset(uint32_t seed, uint32_t sampleSet = 0);

  private:
    ClRuntime& cl_;
    cl::Kernel luminance_;
    cl::Kernel reduce_;
    cl::Kernel draw_;
    cl::Buffer pyramid_;
    int res_ = 0;
    std::vector<cl::Event> pyramidEvents_;
    cl::Event drawEvent_;
};

}  // namespace tsis
