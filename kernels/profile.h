/* Lookup of a tabulated radial profile f(r) (Rd, Rd*Wl, Rd*Wg; layout in
 * tsis_shared.h), shared by every gather-type kernel so that all of them
 * interpolate like ProfileTable::lookup on the host (same float operations; a
 * compiler may fuse a + t * d into one FMA). OpenCL C only. */
#ifndef TSIS_PROFILE_H
#define TSIS_PROFILE_H

#include "tsis_shared.h"

/* f(r) from the float4 table: linear interpolation, 0 at and beyond r_max and
 * for NaN (the negated comparison catches both). */
static inline float4 tsis_profile(const __global float4* table, const TsisTableInfo info,
                                  const float r) {
    const float x = r * info.inv_step;
    if (!(x < (float)(info.size - 1))) return (float4)(0.0f);
    const int i = (int)x;
    const float t = x - (float)i;
    const float4 a = table[i];
    const float4 b = table[i + 1];
    return a + t * (b - a);
}

/* Light under the surface never crosses between media (docs/design.md §2):
 * points of different media (tags 1 + medium in a float4's w, mesh/media.h)
 * are infinitely far apart, where every table is 0. */
static inline float tsis_medium_distance(const float3 d, const float ma, const float mb) {
    return ma == mb ? sqrt(dot(d, d)) : INFINITY;
}

/* The same table split per channel into (value, step) pairs for vector-lane
 * gathers: entry c * size + k = (f_k[c], f_{k+1}[c] - f_k[c]), the last entry
 * of each channel (0, 0). Interpolation becomes one FMA, an out-of-range r
 * maps to the zero entry instead of a branch, and each lane loads 8 bytes per
 * channel. Built by tsis_profile_split (gather.cl). */
static inline void tsis_profile_split_entry(const __global float4* table, const TsisTableInfo info,
                                            const int k, __global float2* split) {
    const int n = (int)info.size;
    float4 a = (float4)(0.0f);
    float4 d = (float4)(0.0f);
    if (k < n - 1) {
        a = table[k];
        d = table[k + 1] - a;
    }
    split[k] = (float2)(a.x, d.x);
    split[n + k] = (float2)(a.y, d.y);
    split[2 * n + k] = (float2)(a.z, d.z);
}

/* The same pairs interleaved: row k = (value, step) of r, g, b, then 0, 0
 * (TSIS_GATHER_INTERLEAVED in gather.cl). */
static inline void tsis_profile_interleave_entry(const __global float4* table,
                                                 const TsisTableInfo info, const int k,
                                                 __global float8* rows) {
    float4 a = (float4)(0.0f);
    float4 d = (float4)(0.0f);
    if (k < (int)info.size - 1) {
        a = table[k];
        d = table[k + 1] - a;
    }
    rows[k] = (float8)(a.x, d.x, a.y, d.y, a.z, d.z, 0.0f, 0.0f);
}

/* Entry index and fraction for distances in vector lanes (the gather's layout
 * of several output points per work-item); out of range gives (size - 1, 0):
 * the zero entry. One function per width: the embedding (cmake/embed_script.cmake)
 * breaks macros continued over several lines. */
static inline int8 tsis_profile_index8(const float8 r, const TsisTableInfo info, float8* frac) {
    const float8 x = r * info.inv_step;
    const int8 in = isless(x, (float8)((float)(info.size - 1)));
    const float8 xc = select((float8)(0.0f), x, in);
    const int8 i = convert_int8(xc);
    *frac = xc - convert_float8(i);
    return select((int8)((int)info.size - 1), i, in);
}

static inline int16 tsis_profile_index16(const float16 r, const TsisTableInfo info, float16* frac) {
    const float16 x = r * info.inv_step;
    const int16 in = isless(x, (float16)((float)(info.size - 1)));
    const float16 xc = select((float16)(0.0f), x, in);
    const int16 i = convert_int16(xc);
    *frac = xc - convert_float16(i);
    return select((int16)((int)info.size - 1), i, in);
}

#endif /* TSIS_PROFILE_H */
