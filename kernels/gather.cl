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
    const float3 xo = points[j].xyz;
    float3 b = (float3)(0.0f);
    for (int i = 0; i < n; ++i) {
        const TsisSample s = samples[i];
        const float3 d = xo - (float3)(s.px, s.py, s.pz);
        const float4 f = tsis_profile(table, info, sqrt(dot(d, d)));
        b += (float3)(s.wr, s.wg, s.wb) * f.xyz;
    }
    out[j] = (float4)(b, 0.0f);
}

#elif TSIS_GATHER_WIDTH == 8 || TSIS_GATHER_WIDTH == 16

/* Vectors are built from, and split into, named per-lane values, never
 * through private arrays: PoCL keeps those on the stack, and storing scalars
 * to reload them as one vector stalls store forwarding (that version took
 * about 1.3x the time). */
#if TSIS_GATHER_WIDTH == 16
#define floatW float16
#define intW int16
#define profile_indexW tsis_profile_index16
#define TSIS_LANES(F) F(0) F(1) F(2) F(3) F(4) F(5) F(6) F(7) F(8) F(9) F(a) F(b) F(c) F(d) F(e) F(f)
#define TSIS_VEC(P, m) (float16)(TSIS_LANE(P, 0, m), TSIS_LANE(P, 1, m), TSIS_LANE(P, 2, m), TSIS_LANE(P, 3, m), TSIS_LANE(P, 4, m), TSIS_LANE(P, 5, m), TSIS_LANE(P, 6, m), TSIS_LANE(P, 7, m), TSIS_LANE(P, 8, m), TSIS_LANE(P, 9, m), TSIS_LANE(P, a, m), TSIS_LANE(P, b, m), TSIS_LANE(P, c, m), TSIS_LANE(P, d, m), TSIS_LANE(P, e, m), TSIS_LANE(P, f, m))
#else
#define floatW float8
#define intW int8
#define profile_indexW tsis_profile_index8
#define TSIS_LANES(F) F(0) F(1) F(2) F(3) F(4) F(5) F(6) F(7)
#define TSIS_VEC(P, m) (float8)(TSIS_LANE(P, 0, m), TSIS_LANE(P, 1, m), TSIS_LANE(P, 2, m), TSIS_LANE(P, 3, m), TSIS_LANE(P, 4, m), TSIS_LANE(P, 5, m), TSIS_LANE(P, 6, m), TSIS_LANE(P, 7, m))
#endif
/* (P, 0, x) -> P0.x; a helper because "P##0.x" would paste a number token. */
#define TSIS_LANE(P, k, m) P##k.m

/* Past the end of the points, lanes repeat the last point (never written). */
#define TSIS_LOAD_POINT(k) const float4 q##k = points[min(base + 0x##k, count - 1)];
#define TSIS_LOAD_R(k) const float2 cr##k = split[idx.s##k];
#define TSIS_LOAD_G(k) const float2 cg##k = split[size + idx.s##k];
#define TSIS_LOAD_B(k) const float2 cb##k = split[2 * size + idx.s##k];
#define TSIS_LOAD_ROW(k) const float8 e##k = rows[idx.s##k];
#define TSIS_STORE(k) if (base + 0x##k < count) out[base + 0x##k] = (float4)(br.s##k, bg.s##k, bb.s##k, 0.0f);

/* Global size = ceil(count / TSIS_GATHER_WIDTH) (rounded up to the local size). */
kernel void tsis_gather(const __global float4* points, const int count,
                        const __global TsisSample* samples, const int n,
                        const __global float2* split, const TsisTableInfo info,
                        __global float4* out) {
    const int base = get_global_id(0) * TSIS_GATHER_WIDTH;
    if (base >= count) return;
    const int size = (int)info.size;
    const __global float8* rows = (const __global float8*)split;
    TSIS_LANES(TSIS_LOAD_POINT)
    const floatW px = TSIS_VEC(q, x);
    const floatW py = TSIS_VEC(q, y);
    const floatW pz = TSIS_VEC(q, z);

    floatW br = (floatW)(0.0f);
    floatW bg = (floatW)(0.0f);
    floatW bb = (floatW)(0.0f);
    for (int i = 0; i < n; ++i) {
        const TsisSample s = samples[i];
        const floatW dx = px - s.px;
        const floatW dy = py - s.py;
        const floatW dz = pz - s.pz;
        floatW t;
        const intW idx = profile_indexW(sqrt(dx * dx + dy * dy + dz * dz), info, &t);
#if TSIS_GATHER_INTERLEAVED
        TSIS_LANES(TSIS_LOAD_ROW)
        br += s.wr * (TSIS_VEC(e, s0) + t * TSIS_VEC(e, s1));
        bg += s.wg * (TSIS_VEC(e, s2) + t * TSIS_VEC(e, s3));
        bb += s.wb * (TSIS_VEC(e, s4) + t * TSIS_VEC(e, s5));
#else
        /* No gather load in OpenCL C: one (value, step) pair per lane and channel. */
        TSIS_LANES(TSIS_LOAD_R)
        TSIS_LANES(TSIS_LOAD_G)
        TSIS_LANES(TSIS_LOAD_B)
        br += s.wr * (TSIS_VEC(cr, x) + t * TSIS_VEC(cr, y));
        bg += s.wg * (TSIS_VEC(cg, x) + t * TSIS_VEC(cg, y));
        bb += s.wb * (TSIS_VEC(cb, x) + t * TSIS_VEC(cb, y));
#endif
    }
    TSIS_LANES(TSIS_STORE)
}

#else
#error "TSIS_GATHER_WIDTH must be 1, 8 or 16"
#endif
