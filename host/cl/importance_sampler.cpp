#include "cl/importance_sampler.h"

#include <bit>
#include <cmath>

#include "cl/launch.h"
#include "util/error.h"

namespace tsis {
namespace {

// One fixed work-group size for every launch: PoCL compiles a kernel again for
// each new local size, and the global sizes here vary with res and n.

size_t bufferBytes(const cl::Buffer& b) {
    return b.getInfo<CL_MEM_SIZE>();
}

}  // namespace

ImportanceSampler::ImportanceSampler(ClRuntime& cl)
    : cl_(cl),
      luminance_(cl.kernel("pyramid.cl", "tsis_luminance")),
      reduce_(cl.kernel("pyramid.cl", "tsis_reduce")),
      draw_(cl.kernel("sample.cl", "tsis_draw")) {}

size_t ImportanceSampler::levelOffset(int res, int level) {
    size_t offset = 0;
    for (int k = 0; k < level; ++k) offset += size_t(res >> k) * size_t(res >> k);
    return offset;
}

size_t ImportanceSampler::pyramidSize(int res) {
    return levelOffset(res, std::countr_zero(static_cast<unsigned>(res)) + 1);
}

float ImportanceSampler::seedOffset(uint32_t seed, uint32_t sampleSet) {
    // lowbias32 (Chris Wellons' hash prospector): good avalanche, so nearby
    // seeds give unrelated offsets. The constant keeps seed 0 off ξ = 0 (the
    // hash maps 0 to 0).
    uint32_t h = seed ^ 0x9e3779b9u;
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    const double golden = 0.6180339887498949;  // (√5 − 1)/2
    const double xi = static_cast<double>(h >> 8) / 16777216.0 + golden * sampleSet;
    const float f = static_cast<float>(xi - std::floor(xi));
    return f < 1.0f ? f : 0.0f;
}

void ImportanceSampler::buildPyramid(const cl::Buffer& flux, int res) {
    TSIS_CHECK(res >= 1 && std::has_single_bit(static_cast<unsigned>(res)));
    TSIS_CHECK_GE(bufferBytes(flux), size_t(res) * res * sizeof(cl_float4));
    const int levels = std::countr_zero(static_cast<unsigned>(res));
    if (res != res_) {
        pyramid_ = cl::Buffer(cl_.context(), CL_MEM_READ_WRITE, pyramidSize(res) * sizeof(float));
        res_ = res;
    }
    cl::CommandQueue& q = cl_.queue();
    pyramidEvents_.assign(levels + 1, cl::Event());

    const int count = res * res;
    setKernelArgs(luminance_, flux, count, pyramid_);
    enqueue1D(q, luminance_, size_t(count), kLocalSize, &pyramidEvents_[0]);
    // In-order queue: each level sees the one below it finished.
    for (int k = 1; k <= levels; ++k) {
        const int dstRes = res >> k;
        setKernelArgs(reduce_, pyramid_, static_cast<cl_int>(levelOffset(res, k - 1)),
                      static_cast<cl_int>(levelOffset(res, k)), dstRes);
        enqueue1D(q, reduce_, size_t(dstRes) * dstRes, kLocalSize, &pyramidEvents_[k]);
    }
}

double ImportanceSampler::totalLuminance() {
    TSIS_CHECK_GT(res_, 0);  // buildPyramid first
    float top = 0.0f;
    cl_.queue().enqueueReadBuffer(pyramid_, CL_TRUE, (pyramidSize(res_) - 1) * sizeof(float),
                                  sizeof(float), &top);
    return top;
}

void ImportanceSampler::draw(const cl::Buffer& flux, const cl::Buffer& position, int res, int n,
                             uint32_t seed, cl::Buffer& samples, uint32_t sampleSet) {
    drawWithOffset(flux, position, res, n, seedOffset(seed, sampleSet), samples);
}

void ImportanceSampler::drawWithOffset(const cl::Buffer& flux, const cl::Buffer& position, int res,
                                       int n, float xi, cl::Buffer& samples) {
    TSIS_CHECK(xi >= 0.0f && xi < 1.0f);
    TSIS_CHECK_EQ(res, res_);  // buildPyramid(flux, res) first
    TSIS_CHECK_GE(n, 0);
    const size_t texels = size_t(res) * res;
    TSIS_CHECK_GE(bufferBytes(flux), texels * sizeof(cl_float4));
    TSIS_CHECK_GE(bufferBytes(position), texels * sizeof(cl_float4));
    drawEvent_ = cl::Event();
    if (n == 0) return;
    TSIS_CHECK_GE(bufferBytes(samples), size_t(n) * sizeof(TsisSample));
    setKernelArgs(draw_, pyramid_, flux, position,
                  static_cast<cl_int>(std::countr_zero(static_cast<unsigned>(res))), n, xi,
                  samples);
    enqueue1D(cl_.queue(), draw_, size_t(n), kLocalSize, &drawEvent_);
}

double ImportanceSampler::lastPyramidMs() const {
    return eventMilliseconds(pyramidEvents_);
}

double ImportanceSampler::lastDrawMs() const {
    return drawEvent_() ? eventMilliseconds(drawEvent_) : 0.0;
}

}  // namespace tsis
