/* B at each camera point from the pyramid's radiosity atlas
 * (render/radiosity_atlas.h): bilinear over the 2x2 texels around the point's
 * atlas coordinates, each only where it is covered, of the point's medium and
 * within sqrt(max_mm2) of it in space (a texel of another chart packed beside
 * it is not its surface), the weights of those that count renormalised; with
 * none of the four, the nearest such texel of the 4x4 around (a point in a
 * chart's outermost half texel). None at all: 0.
 * atlas_xyz: the position atlas (w = medium tag, 0 uncovered), atlas_b: B
 * of the same texels. w of the output: 0, as the gather writes it. */
#include "tsis_shared.h"

/* The index of texel (x, y) when it counts for point p (covered, of its
 * medium, within sqrt(max_mm2)), else -1; *d2 its squared distance. */
static inline int tsis_atlas_texel(const int x, const int y, const int res,
                                   const __global float4* atlas_xyz, const float4 p,
                                   const float max_mm2, float* d2) {
    if (x < 0 || y < 0 || x >= res || y >= res) return -1;
    const int k = y * res + x;
    const float4 q = atlas_xyz[k];
    const float3 d = q.xyz - p.xyz;
    *d2 = dot(d, d);
    return q.w == p.w && *d2 < max_mm2 ? k : -1;
}

kernel void tsis_radiosity_atlas_lookup(const __global float2* uv, const __global float4* points,
                                        const int count, const __global float4* atlas_xyz,
                                        const __global float4* atlas_b, const int res,
                                        const float max_mm2, __global float4* out) {
    const int i = get_global_id(0);
    if (i >= count) return;
    const float4 p = points[i];
    const float2 f = uv[i] * (float)res - 0.5f;
    const float2 f0 = floor(f);
    const float2 t = f - f0;
    const int x0 = (int)f0.x, y0 = (int)f0.y;
    /* The 2x2 texels, clamped into the atlas (a clamped texel repeats one
     * already counted or is far from the point: its weight is kept or 0). */
    const int xa = clamp(x0, 0, res - 1), xb = clamp(x0 + 1, 0, res - 1);
    const int ya = clamp(y0, 0, res - 1), yb = clamp(y0 + 1, 0, res - 1);
    const int k[4] = {ya * res + xa, ya * res + xb, yb * res + xa, yb * res + xb};
    const float w[4] = {(1.0f - t.x) * (1.0f - t.y), t.x * (1.0f - t.y), (1.0f - t.x) * t.y,
                        t.x * t.y};
    float4 sum = (float4)(0.0f);
    float weights = 0.0f, d2;
    for (int j = 0; j < 4; ++j) {
        const float4 q = atlas_xyz[k[j]];
        const float3 d = q.xyz - p.xyz;
        const float wj = q.w == p.w && dot(d, d) < max_mm2 ? w[j] : 0.0f;
        sum += wj * atlas_b[k[j]];
        weights += wj;
    }
    if (weights > 0.0f) {
        out[i] = (float4)(sum.xyz / weights, 0.0f);
        return;
    }
    float best = INFINITY;
    float4 nearest = (float4)(0.0f);
    for (int dy = -1; dy <= 2; ++dy)
        for (int dx = -1; dx <= 2; ++dx) {
            const int k = tsis_atlas_texel(x0 + dx, y0 + dy, res, atlas_xyz, p, max_mm2, &d2);
            if (k >= 0 && d2 < best) {
                best = d2;
                nearest = atlas_b[k];
            }
        }
    out[i] = (float4)(nearest.xyz, 0.0f);
}
