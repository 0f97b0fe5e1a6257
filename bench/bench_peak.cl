/* Device microbenchmarks for bench/bench_kernels.cpp: the FMA peak and the
 * memory bandwidth the production kernels are compared against. Not used by
 * the renderer.
 *
 * FMA: independent chains of x = x * a + b per work-item (enough of them to
 * cover the FMA latency); 2 flops per lane per FMA. The sum is written so the
 * chains are not optimised away. */
#define BENCH_FMA(W, floatW, LO, HI)                                                               \
    kernel void bench_fma##W(__global float* out, const int iters, const float a, const float b) { \
        const float g = (float)get_global_id(0) * 1e-7f;                                           \
        floatW x0 = (floatW)(g), x1 = (floatW)(g + 1), x2 = (floatW)(g + 2), x3 = (floatW)(g + 3); \
        floatW x4 = (floatW)(g + 4), x5 = (floatW)(g + 5), x6 = (floatW)(g + 6),                   \
               x7 = (floatW)(g + 7);                                                               \
        for (int i = 0; i < iters; ++i) {                                                          \
            x0 = fma(x0, a, b);                                                                    \
            x1 = fma(x1, a, b);                                                                    \
            x2 = fma(x2, a, b);                                                                    \
            x3 = fma(x3, a, b);                                                                    \
            x4 = fma(x4, a, b);                                                                    \
            x5 = fma(x5, a, b);                                                                    \
            x6 = fma(x6, a, b);                                                                    \
            x7 = fma(x7, a, b);                                                                    \
        }                                                                                          \
        const floatW s = ((x0 + x1) + (x2 + x3)) + ((x4 + x5) + (x6 + x7));                        \
        out[get_global_id(0)] = dot(s.LO, (float4)(1.0f)) + dot(s.HI, (float4)(1.0f));             \
    }

/* One kernel per vector width: bench_fma16, bench_fma8. */
BENCH_FMA(16, float16, lo.lo, hi.hi)
BENCH_FMA(8, float8, lo, hi)

/* Bandwidth: a copy (read + write) and a read-sum, each work-item over its own
 * contiguous chunk of `per` float16s (contiguous per work-item is what a CPU
 * device streams best). */
kernel void bench_copy(const __global float16* in, __global float16* out, const int per) {
    const size_t base = get_global_id(0) * (size_t)per;
    for (int i = 0; i < per; ++i) out[base + i] = in[base + i];
}

kernel void bench_read_sum(const __global float16* in, __global float* out, const int per) {
    const size_t base = get_global_id(0) * (size_t)per;
    float16 s0 = (float16)(0.0f), s1 = (float16)(0.0f);
    for (int i = 0; i < per; i += 2) {
        s0 += in[base + i];
        s1 += in[base + i + 1];
    }
    const float16 s = s0 + s1;
    out[get_global_id(0)] = dot(s.lo.lo, (float4)(1.0f)) + dot(s.hi.hi, (float4)(1.0f));
}
