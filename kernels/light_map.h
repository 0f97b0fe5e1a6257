/* A light's view of the object as the light-view methods (ltsm, tsm, mis) read
 * it: the projection of the light-view flux and position maps (GL row order,
 * texel (x, y) at index y * res + x) and the size of a texel on the plane
 * perpendicular to the light's axis. Shared by host (C++) and kernels. */
#ifndef TSIS_LIGHT_MAP_H
#define TSIS_LIGHT_MAP_H

#include "tsis_shared.h"

typedef struct {
    float view_proj[16]; /* column-major, as glm stores it */
    /* mm per texel on the plane perpendicular to the light's axis at clip w:
     * point light 2 tan(half fov) / res (w = distance along the axis),
     * directional light the texel size (w = 1). */
    float tau_per_w;
    int res;
    float pad0, pad1;
} TsisLightMapInfo;

TSIS_CHECK_SIZE(TsisLightMapInfo, 80);
TSIS_CHECK_OFFSET(TsisLightMapInfo, view_proj, 0);
TSIS_CHECK_OFFSET(TsisLightMapInfo, tau_per_w, 64);
TSIS_CHECK_OFFSET(TsisLightMapInfo, res, 68);
TSIS_CHECK_OFFSET(TsisLightMapInfo, pad0, 72);
TSIS_CHECK_OFFSET(TsisLightMapInfo, pad1, 76);

#ifdef __OPENCL_VERSION__

/* (x, y) in continuous texel coordinates (texel centres at i + 0.5) and clip w
 * of the point p; a texel at p's depth is tau_per_w * w mm wide. */
static inline float3 tsis_light_project(const TsisLightMapInfo* l, const float3 p) {
    const float* m = l->view_proj;
    const float cx = m[0] * p.x + m[4] * p.y + m[8] * p.z + m[12];
    const float cy = m[1] * p.x + m[5] * p.y + m[9] * p.z + m[13];
    const float cw = m[3] * p.x + m[7] * p.y + m[11] * p.z + m[15];
    const float s = 0.5f * (float)l->res / cw;
    return (float3)(cx * s + 0.5f * (float)l->res, cy * s + 0.5f * (float)l->res, cw);
}

/* Index of the texel containing continuous texel coordinates (x, y), or -1
 * outside the map. */
static inline int tsis_light_texel(const TsisLightMapInfo* l, const float x, const float y) {
    const float fx = floor(x);
    const float fy = floor(y);
    if (!(fx >= 0.0f && fy >= 0.0f && fx < (float)l->res && fy < (float)l->res)) return -1;
    return (int)fy * l->res + (int)fx;
}

/* The flux and the lit surface point at continuous texel coordinates (x, y):
 * a bilinear mix of the four texels around them (texels off the map hold no
 * light). Returns the mixed flux (rgb) and, in *point, the luminance-weighted
 * mean of their positions (w = the summed luminance weight; 0 where no light
 * landed), so the point moves continuously with (x, y) across a texel. Only
 * texels of `medium` count (the flux's a is its tag, 1 + medium,
 * mesh/media.h): light does not cross between media. */
static inline float3 tsis_light_bilinear(const TsisLightMapInfo* l, const __global float4* flux,
                                         const __global float4* position, const float x,
                                         const float y, const float medium, float4* point) {
    const float fx = floor(x - 0.5f);
    const float fy = floor(y - 0.5f);
    const float tx = x - 0.5f - fx;
    const float ty = y - 0.5f - fy;
    float3 phi = (float3)(0.0f);
    float4 p = (float4)(0.0f);
    for (int k = 0; k < 4; ++k) {
        const float w = ((k & 1) ? tx : 1.0f - tx) * ((k & 2) ? ty : 1.0f - ty);
        const int t = tsis_light_texel(l, fx + (float)(k & 1) + 0.5f, fy + (float)(k >> 1) + 0.5f);
        if (t < 0 || w <= 0.0f) continue;
        const float4 f = flux[t];
        if (f.w != medium) continue;
        const float y_lum = w * TSIS_LUMINANCE(f.x, f.y, f.z);
        phi += w * f.xyz;
        p += (float4)(y_lum * position[t].xyz, y_lum);
    }
    *point = p;
    return phi;
}

#endif /* __OPENCL_VERSION__ */

#endif /* TSIS_LIGHT_MAP_H */
