/* Several output points in the lanes of one vector (float8 or float16), for
 * kernels that sum a tabulated profile over a list of weighted positions
 * (gather.cl: importance samples; flux_tree.cl: flux tree nodes;
 * single_scatter.cl: its points, each lane's own). Define
 * TSIS_LANE_WIDTH (8 or 16) before including. OpenCL C only.
 *
 * Vectors are built from, and split into, named per-lane values, never
 * through private arrays: PoCL keeps those on the stack, and storing scalars
 * to reload them as one vector stalls store forwarding (that version took
 * about 1.3x the time). One line per macro: the embedding
 * (cmake/embed_script.cmake) breaks macros continued over several lines. */
#ifndef TSIS_LANES_H
#define TSIS_LANES_H

#include "profile.h"

#if TSIS_LANE_WIDTH == 16
#define floatW float16
#define intW int16
#define profile_indexW tsis_profile_index16
#define TSIS_LANES(F) \
    F(0) F(1) F(2) F(3) F(4) F(5) F(6) F(7) F(8) F(9) F(a) F(b) F(c) F(d) F(e) F(f)
#define TSIS_VEC_OF(P)                                                                            \
    (float16)(P##0, P##1, P##2, P##3, P##4, P##5, P##6, P##7, P##8, P##9, P##a, P##b, P##c, P##d, \
              P##e, P##f)
#define TSIS_VEC(P, m)                                                                        \
    (float16)(TSIS_LANE(P, 0, m), TSIS_LANE(P, 1, m), TSIS_LANE(P, 2, m), TSIS_LANE(P, 3, m), \
              TSIS_LANE(P, 4, m), TSIS_LANE(P, 5, m), TSIS_LANE(P, 6, m), TSIS_LANE(P, 7, m), \
              TSIS_LANE(P, 8, m), TSIS_LANE(P, 9, m), TSIS_LANE(P, a, m), TSIS_LANE(P, b, m), \
              TSIS_LANE(P, c, m), TSIS_LANE(P, d, m), TSIS_LANE(P, e, m), TSIS_LANE(P, f, m))
#elif TSIS_LANE_WIDTH == 8
#define floatW float8
#define intW int8
#define profile_indexW tsis_profile_index8
#define TSIS_LANES(F) F(0) F(1) F(2) F(3) F(4) F(5) F(6) F(7)
#define TSIS_VEC_OF(P) (float8)(P##0, P##1, P##2, P##3, P##4, P##5, P##6, P##7)
#define TSIS_VEC(P, m)                                                                       \
    (float8)(TSIS_LANE(P, 0, m), TSIS_LANE(P, 1, m), TSIS_LANE(P, 2, m), TSIS_LANE(P, 3, m), \
             TSIS_LANE(P, 4, m), TSIS_LANE(P, 5, m), TSIS_LANE(P, 6, m), TSIS_LANE(P, 7, m))
#else
#error "TSIS_LANE_WIDTH must be 8 or 16"
#endif
/* TSIS_VEC_OF(P): the lanes' scalars P0, P1, ... as one vector.
 * (P, 0, x) -> P0.x; a helper because "P##0.x" would paste a number token. */
#define TSIS_LANE(P, k, m) P##k.m

/* The lanes' points from `points` starting at `base`; past `count` lanes
 * repeat the last point (computed, never stored). Needs base, count, points. */
#define TSIS_LOAD_POINT(k) const float4 q##k = points[min(base + 0x##k, count - 1)];
/* The lanes' coordinates px, py, pz and medium tags pm (profile.h) from the
 * loaded q0, q1, ..., and the sums br, bg, bb. */
#define TSIS_LANES_XYZ                \
    const floatW px = TSIS_VEC(q, x); \
    const floatW py = TSIS_VEC(q, y); \
    const floatW pz = TSIS_VEC(q, z); \
    const floatW pm = TSIS_VEC(q, w);
#define TSIS_LANES_SUMS         \
    floatW br = (floatW)(0.0f); \
    floatW bg = (floatW)(0.0f); \
    floatW bb = (floatW)(0.0f);
#define TSIS_STORE(k) \
    if (base + 0x##k < count) out[base + 0x##k] = (float4)(br.s##k, bg.s##k, bb.s##k, 0.0f);
/* One (value, step) pair per lane and channel from the split table (profile.h):
 * OpenCL C has no gather load. Need split, size, idx. */
#define TSIS_LOAD_R(k) const float2 cr##k = split[idx.s##k];
#define TSIS_LOAD_G(k) const float2 cg##k = split[size + idx.s##k];
#define TSIS_LOAD_B(k) const float2 cb##k = split[2 * size + idx.s##k];

/* Table entry and fraction of |p - at| in every lane (profile.h): at.w is
 * the medium tag of `at`, and a lane of another medium is infinitely far. */
static inline intW tsis_lanes_index(const floatW px, const floatW py, const floatW pz,
                                    const floatW pm, const float4 at, const TsisTableInfo info,
                                    floatW* t) {
    const floatW dx = px - at.x;
    const floatW dy = py - at.y;
    const floatW dz = pz - at.z;
    const floatW r = sqrt(dx * dx + dy * dy + dz * dz);
    return profile_indexW(select((floatW)(INFINITY), r, isequal(pm, (floatW)(at.w))), info, t);
}

/* b += w * f(|p - at|) in every lane, f the split table (profile.h). */
static inline void tsis_lanes_add(const floatW px, const floatW py, const floatW pz,
                                  const floatW pm, const float4 at, const float3 w,
                                  const __global float2* split, const TsisTableInfo info,
                                  floatW* br, floatW* bg, floatW* bb) {
    const int size = (int)info.size;
    floatW t;
    const intW idx = tsis_lanes_index(px, py, pz, pm, at, info, &t);
    TSIS_LANES(TSIS_LOAD_R)
    TSIS_LANES(TSIS_LOAD_G)
    TSIS_LANES(TSIS_LOAD_B)
    *br += w.x * (TSIS_VEC(cr, x) + t * TSIS_VEC(cr, y));
    *bg += w.y * (TSIS_VEC(cg, x) + t * TSIS_VEC(cg, y));
    *bb += w.z * (TSIS_VEC(cb, x) + t * TSIS_VEC(cb, y));
}

#endif /* TSIS_LANES_H */
