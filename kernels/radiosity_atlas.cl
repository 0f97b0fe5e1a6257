/* B at each camera point from the pyramid's radiosity atlas
 * (render/radiosity_atlas.h): bilinear over the 2x2 texels around the point's
 * atlas coordinates that hold its surface, renormalised. mask[i] bit j says
 * texel j (x0 y0, x1 y0, x0 y1, x1 y1) does (the host tests it,
 * RadiosityAtlas::surfaceTexels); a point with none is gathered at its pixel
 * instead and left alone here. atlas_b: B of every atlas texel. w of the
 * output: 0, as the gather writes it. */
#include "tsis_shared.h"

kernel void tsis_radiosity_atlas_lookup(const __global float2* uv, const __global uchar* mask,
                                        const int count, const __global float4* atlas_b,
                                        const int res, __global float4* out) {
    const int i = get_global_id(0);
    if (i >= count) return;
    const uchar m = mask[i];
    if (m == 0) return;
    const float2 f = uv[i] * (float)res - 0.5f;
    const float2 f0 = floor(f);
    const float2 t = f - f0;
    /* Clamped into the atlas: a texel out of it is never in the mask. */
    const int xa = clamp((int)f0.x, 0, res - 1), xb = clamp((int)f0.x + 1, 0, res - 1);
    const int ya = clamp((int)f0.y, 0, res - 1), yb = clamp((int)f0.y + 1, 0, res - 1);
    const int k[4] = {ya * res + xa, ya * res + xb, yb * res + xa, yb * res + xb};
    const float w[4] = {(1.0f - t.x) * (1.0f - t.y), t.x * (1.0f - t.y), (1.0f - t.x) * t.y,
                        t.x * t.y};
    float4 sum = (float4)(0.0f), any = (float4)(0.0f);
    float weights = 0.0f, n = 0.0f;
    for (int j = 0; j < 4; ++j) {
        if (!((m >> j) & 1)) continue;
        const float4 b = atlas_b[k[j]];
        sum += w[j] * b;
        weights += w[j];
        any += b;
        n += 1.0f;
    }
    /* The point's own texels all at weight 0 (on the far edge of its cell):
     * their mean. */
    const float4 v = weights > 0.0f ? sum / weights : any / n;
    out[i] = (float4)(v.xyz, 0.0f);
}
