/* Device microbenchmarks for bench/bench_kernels.cpp: the FMA peak and the
 * memory bandwidth the production kernels are compared against. Not used by
 * the renderer.
 *
 * FMA: independent chains of x = x * a + b per work-item (enough of them to
 * cover the FMA latency); 2 flops per lane per FMA. The sum is written so the
 * chains are not optimised away. */
kernel void bench_fma16(__global float* out, const int iters, const float a, const float b) {
    const float g = (float)get_global_id(0) * 1e-7f;
    float16 x0 = (float16)(g), x1 = (float16)(g + 1), x2 = (float16)(g + 2), x3 = (float16)(g + 3);
    float16 x4 = (float16)(g + 4), x5 = (float16)(g + 5), x6 = (float16)(g + 6),
            x7 = (float16)(g + 7);
    for (int i = 0; i < iters; ++i) {
        x0 = fma(x0, a, b);
        x1 = fma(x1, a, b);
        x2 = fma(x2, a, b);
        x3 = fma(x3, a, b);
        x4 = fma(x4, a, b);
        x5 = fma(x5, a, b);
        x6 = fma(x6, a, b);
        x7 = fma(x7, a, b);
    }
    const float16 s = ((x0 + x1) + (x2 + x3)) + ((x4 + x5) + (x6 + x7));
    out[get_global_id(0)] = dot(s.lo.lo, (float4)(1.0f)) + dot(s.hi.hi, (float4)(1.0f));
}

kernel void bench_fma8(__global float* out, const int iters, const float a, const float b) {
    const float g = (float)get_global_id(0) * 1e-7f;
    float8 x0 = (float8)(g), x1 = (float8)(g + 1), x2 = (float8)(g + 2), x3 = (float8)(g + 3);
    float8 x4 = (float8)(g + 4), x5 = (float8)(g + 5), x6 = (float8)(g + 6), x7 = (float8)(g + 7);
    for (int i = 0; i < iters; ++i) {
        x0 = fma(x0, a, b);
        x1 = fma(x1, a, b);
        x2 = fma(x2, a, b);
        x3 = fma(x3, a, b);
        x4 = fma(x4, a, b);
        x5 = fma(x5, a, b);
        x6 = fma(x6, a, b);
        x7 = fma(x7, a, b);
    }
    const float8 s = ((x0 + x1) + (x2 + x3)) + ((x4 + x5) + (x6 + x7));
    out[get_global_id(0)] = dot(s.lo, (float4)(1.0f)) + dot(s.hi, (float4)(1.0f));
}

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
