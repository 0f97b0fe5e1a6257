/* Sum pyramid of luminance in mipmap order (thesis Fig. 3.3b), all levels in
 * one float buffer: level 0 (res x res texels, row-major) first, then each
 * half-size level, the 1-texel top last. Level k starts at
 * sum_{j<k} (res >> j)^2. The pyramid is the CDF that tsis_draw descends. */
#include "tsis_shared.h"

/* Level 0: Y = dot(rgb, luma). Negative or NaN luminance counts as 0 so the
 * sums stay a valid (non-negative) distribution. */
kernel void tsis_luminance(const __global float4* flux, const int count, __global float* level0) {
    const int i = get_global_id(0);
    if (i >= count) return;
    const float4 f = flux[i];
    const float y = TSIS_LUMINANCE(f.x, f.y, f.z);
    level0[i] = fmax(y, 0.0f); /* fmax(NaN, 0) = 0 */
}

/* One level from the one below it: each texel sums its 2x2 children, added in
 * the order tsis_draw walks them (x first, then y), so the parent equals the
 * running subtraction there as closely as float allows. */
kernel void tsis_reduce(__global float* pyramid, const int src_offset, const int dst_offset,
                        const int dst_res) {
    const int i = get_global_id(0);
    if (i >= dst_res * dst_res) return;
    const int x = i % dst_res;
    const int y = i / dst_res;
    const int src_res = 2 * dst_res;
    const __global float* c = pyramid + src_offset + (2 * y) * src_res + 2 * x;
    pyramid[dst_offset + i] = ((c[0] + c[1]) + c[src_res]) + c[src_res + 1];
}
