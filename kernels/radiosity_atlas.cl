/* B at each camera point from the pyramid's radiosity atlas
 * (render/radiosity_atlas.h): bilinear over the 2x2 texels around the point's
 * atlas coordinates that hold its surface (covered or of the ring, of its
 * medium and within sqrt(max_mm2) in space: a texel of another chart packed
 * beside it is not), renormalised. A point with none (none[i] = 1) is left
 * alone, for the host to gather at its pixel. atlas_xyz: the atlas' texel
 * positions (w = medium tag, 0 for none), atlas_b: B of the same texels.
 * w of the output: 0, as the gather writes it. */
#include "tsis_shared.h"

kernel void tsis_radiosity_atlas_lookup(const __global float2* uv, const __global float4* points,
                                        const int count, const __global float4* atlas_xyz,
                                        const __global float4* atlas_b, const int res,
                                        const float max_mm2, __global float4* out,
                                        __global uchar* none) {
    const int i = get_global_id(0);
    if (i >= count) return;
    const float4 p = points[i];
    const float2 f = uv[i] * (float)res - 0.5f;
    const float2 f0 = floor(f);
    const float2 t = f - f0;
    const int x0 = (int)f0.x, y0 = (int)f0.y;
    float4 sum = (float4)(0.0f), any = (float4)(0.0f);
    float weights = 0.0f, n = 0.0f;
    for (int j = 0; j < 4; ++j) {
        const int x = x0 + (j & 1), y = y0 + (j >> 1);
        if (x < 0 || y < 0 || x >= res || y >= res) continue;
        const int k = y * res + x;
        const float4 q = atlas_xyz[k];
        const float3 d = q.xyz - p.xyz;
        if (q.w != p.w || !(dot(d, d) < max_mm2)) continue;
        const float w = ((j & 1) ? t.x : 1.0f - t.x) * ((j >> 1) ? t.y : 1.0f - t.y);
        const float4 b = atlas_b[k];
        sum += w * b;
        weights += w;
        any += b;
        n += 1.0f;
    }
    none[i] = n == 0.0f;
    if (n == 0.0f) return;
    /* Its own texels all at weight 0 (on the far edge of its cell): their mean. */
    const float4 v = weights > 0.0f ? sum / weights : any / n;
    out[i] = (float4)(v.xyz, 0.0f);
}
