/* Gather: B(xo_j) = sum_i w_i * f(|xo_j - x_i|) over a set of weighted samples.
 * One kernel for every use: f is whatever table the host passes (Rd, Rd*Wg,
 * ...) and the samples any TsisSample set (importance samples, dense reference
 * samples). Output: (B.rgb, 0) per point.
 *
 * TSIS_GATHER_WIDTH = output points per work-item:
 *   1     one point per work-item, float4 table. PoCL cannot vectorise across
 *         work-items through the sample loop, so this runs scalar.
 *   8/16  that many points in the lanes of float8/float16 vectors, table split
 *         per channel into (value, step) pairs (tsis_profile_split): the
 *         arithmetic vectorises; the table reads stay one load per lane and
 *         channel. */
#include "profile.h"

#ifndef TSIS_GATHER_WIDTH
#define TSIS_GATHER_WIDTH 8
#endif

/* TSIS_GATHER_INTERLEAVED (vector widths only): one float8 row per entry,
 * (value, step) of r, g, b and two pad floats, instead of three float2 rows
 * a table apart: one 32-byte load per lane instead of three 8-byte ones from
 * three places in a table larger than L1. */
#ifndef TSIS_GATHER_INTERLEAVED
#define TSIS_GATHER_INTERLEAVED 0
#endif

/* The split table from the float4 table; global size = info.size. */
kernel void tsis_profile_split(const __global float4* table, const TsisTableInfo info,
                               __global float2* split) {
    const int k = get_global_id(0);
#if TSIS_GATHER_INTERLEAVED
    if (k < (int)info.size) tsis_profile_interleave_entry(table, info, k, (__global float8*)split);
#else
    if (k < (int)info.size) tsis_profile_split_entry(table, info, k, split);
#endif
}

#if TSIS_GATHER_WIDTH == 1

kernel void tsis_gather(const __global float4* points, const int count,
                        const __global TsisSample* samples, const int n,
                        const __global float4* table, const TsisTableInfo info,
                        __global float4* out) {
    const int j = get_global_id(0);
    if (j >= count) return;
    const float4 xo = points[j];
    float3 b = (float3)(0.0f);
    for (int i = 0; i < n; ++i) {
        const TsisSample s = samples[i];
        const float3 d = xo.xyz - (float3)(s.px, s.py, s.pz);
        const float4 f = tsis_profile(table, info, tsis_medium_distance(d, xo.w, s.medium));
        b += (float3)(s.wr, s.wg, s.wb) * f.xyz;
    }
    out[j] = (float4)(b, 0.0f);
}

#elif TSIS_GATHER_WIDTH == 8 || TSIS_GATHER_WIDTH == 16

#define TSIS_LANE_WIDTH TSIS_GATHER_WIDTH
#include "lanes.h"

#define TSIS_LOAD_ROW(k) const float8 e##k = rows[idx.s##k];

/* Global size = ceil(count / TSIS_GATHER_WIDTH) (rounded up to the local size). */
kernel void tsis_gather(const __global float4* points, const int count,
                        const __global TsisSample* samples, const int n,
                        const __global float2* split, const TsisTableInfo info,
                        __global float4* out) {
    const int base = get_global_id(0) * TSIS_GATHER_WIDTH;
    if (base >= count) return;
    TSIS_LANES(TSIS_LOAD_POINT)
    TSIS_LANES_XYZ
    TSIS_LANES_SUMS
    for (int i = 0; i < n; ++i) {
        const TsisSample s = samples[i];
#if TSIS_GATHER_INTERLEAVED
        const __global float8* rows = (const __global float8*)split;
        floatW t;
        const intW idx =
            tsis_lanes_index(px, py, pz, pm, (float4)(s.px, s.py, s.pz, s.medium), info, &t);
        TSIS_LANES(TSIS_LOAD_ROW)
        br += s.wr * (TSIS_VEC(e, s0) + t * TSIS_VEC(e, s1));
        bg += s.wg * (TSIS_VEC(e, s2) + t * TSIS_VEC(e, s3));
        bb += s.wb * (TSIS_VEC(e, s4) + t * TSIS_VEC(e, s5));
#else
        tsis_lanes_add(px, py, pz, pm, (float4)(s.px, s.py, s.pz, s.medium),
                       (float3)(s.wr, s.wg, s.wb), split, info, &br, &bg, &bb);
#endif
    }
    TSIS_LANES(TSIS_STORE)
}

#else
#error "TSIS_GATHER_WIDTH must be 1, 8 or 16"
#endif
