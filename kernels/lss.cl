/* Local subsurface scattering in image space (Mertens et al. 2003),
 * --method lss: per covered pixel, M samples on a disk of the image plane
 * around it, radii drawn by importance of Rd on the plane, irradiance E from
 * the camera's G-buffer:
 *   B(xo) = 1/M sum_k E(x_k) Rd(|xo - x_k|) A(x_k) / (p(r_k) s_o^2)
 * with A the surface area pixel k covers, p the density per mm^2 of the
 * sampled radius and s_o the size of a pixel at xo's depth (mm), so a sample
 * r_k mm out lands r_k / s_o pixels away. Light the camera does not see is
 * missed: that is the method. */
#include "hash.h"
#include "profile.h"

/* Per pixel of the G-buffer: where it is (xyz, w its medium tag 1 + medium,
 * mesh/media.h, where covered: samples of another medium add nothing) and its
 * irradiance times its surface area in units of (pixel_angle)^2:
 * a = d^3 / (rho max(|n . w|, min_cos)), d the depth along the view
 * direction, rho the distance to the eye, w the unit ray (a pixel's solid
 * angle times rho^2 is pixel_angle^2 d^3 / rho). Uncovered pixels get zeros,
 * so samples landing there add nothing without a branch. */
kernel void tsis_lss_prepare(const __global float4* gpos, const __global float4* gnormal,
                             const __global float4* girr, const int pixels, const TsisCamera cam,
                             __global float4* pos, __global float4* ea) {
    const int i = get_global_id(0);
    if (i >= pixels) return;
    const float4 p = gpos[i];
    if (!(p.w > 0.0f)) {
        pos[i] = (float4)(0.0f);
        ea[i] = (float4)(0.0f);
        return;
    }
    const float3 v = p.xyz - (float3)(cam.ex, cam.ey, cam.ez);
    const float rho = length(v);
    const float d = dot(v, (float3)(cam.fx, cam.fy, cam.fz));
    const float c = max(fabs(dot(normalize(gnormal[i].xyz), v / rho)), cam.min_cos);
    pos[i] = p;
    ea[i] = (float4)(girr[i].xyz * (d * d * d / (rho * c)), 0.0f);
}

/* Per-lane loads for TSIS_LSS_LANES 8: vectors are built from named values,
 * never through private arrays (PoCL keeps those on the stack; see gather.cl).
 * One line per macro: the embedding breaks continued macros. */
#define LSS_LANES(F) F(0) F(1) F(2) F(3) F(4) F(5) F(6) F(7)
#define LSS_LANE(P, k, m) P##k.m
#define LSS_VEC(P, m)                                                                    \
    (float8)(LSS_LANE(P, 0, m), LSS_LANE(P, 1, m), LSS_LANE(P, 2, m), LSS_LANE(P, 3, m), \
             LSS_LANE(P, 4, m), LSS_LANE(P, 5, m), LSS_LANE(P, 6, m), LSS_LANE(P, 7, m))
#define LSS_LOAD_RADII(k) const float2 ra##k = (float2)(radii[i.s##k], radii[i.s##k + 1]);
#define LSS_LOAD_PIXEL(k)            \
    const float4 p##k = pos[q.s##k]; \
    const float4 e##k = ea[q.s##k];
#define LSS_LOAD_ROWS(k)               \
    const float4 ta##k = rd[row.s##k]; \
    const float4 tb##k = rd[next.s##k];

static inline float lss_sum8(const float8 v) {
    const float4 a = v.lo + v.hi;
    return a.x + a.y + a.z + a.w;
}

/* TSIS_LSS_LANES = samples of one pixel processed together:
 *   1  one sample per iteration (scalar under PoCL: it does not vectorise
 *      across work-items through the sample loop);
 *   8  eight samples in the lanes of float8 vectors, one load per lane for
 *      what differs between samples (radius cells, pixels, table rows). */
#ifndef TSIS_LSS_LANES
#define TSIS_LSS_LANES 8
#endif

/* One output point per work-item. dirs: M unit directions (golden-angle
 * spiral, padded with zeros to a multiple of 8); radii: entries + 1 points of
 * the inverse CDF r(u) (LssMethod::radiusTable). Sample k uses
 * u_k = (k + xi) / M and direction k rotated by phi, (xi, phi) hashed from
 * (pixel, seed): a rotated, shifted spiral lattice per pixel, deterministic
 * for a seed. */
kernel void tsis_lss_gather(const __global int* pixels, const int count, const __global float4* pos,
                            const __global float4* ea, const int width, const int height,
                            const __global float2* dirs, const int m, const __global float* radii,
                            const int entries, const __global float4* rd, const TsisTableInfo info,
                            const TsisCamera cam, const uint seed, __global float4* out) {
    const int j = get_global_id(0);
    if (j >= count) return;
    const int pix = pixels[j];
    const float px = (float)(pix % width) + 0.5f;
    const float py = (float)(pix / width) + 0.5f;
    const float3 xo = pos[pix].xyz;
    const float medium = pos[pix].w;
    const float depth =
        dot(xo - (float3)(cam.ex, cam.ey, cam.ez), (float3)(cam.fx, cam.fy, cam.fz));
    const float per_mm = 1.0f / (depth * cam.pixel_angle); /* pixels per mm at xo */
    const uint h1 = tsis_hash((uint)pix ^ tsis_hash(seed));
    const uint h2 = tsis_hash(h1 + 0x9e3779b9U);
    const float xi = tsis_hash_unit(h1);
    float cs;
    const float sn = sincos(tsis_hash_unit(h2) * 6.2831853f, &cs);
    const float du = (float)entries / (float)m;
#if TSIS_LSS_LANES == 1
    float3 b = (float3)(0.0f);
    for (int k = 0; k < m; ++k) {
        const float t = ((float)k + xi) * du;
        const int i = min((int)t, entries - 1);
        const float r0 = radii[i];
        const float r1 = radii[i + 1];
        const float r = r0 + (t - (float)i) * (r1 - r0);
        const float2 d = dirs[k];
        const float sx = floor(px + (cs * d.x - sn * d.y) * r * per_mm);
        const float sy = floor(py + (sn * d.x + cs * d.y) * r * per_mm);
        const bool inside = sx >= 0.0f && sx < (float)width && sy >= 0.0f && sy < (float)height;
        const int q = inside ? (int)sy * width + (int)sx : pix;
        /* 1 / p(r) up to the constant entries * 2 pi, applied once below. */
        const float w = inside ? (r1 - r0) * r : 0.0f;
        const float3 dx = pos[q].xyz - xo;
        const float4 f = tsis_profile(rd, info, tsis_medium_distance(dx, medium, pos[q].w));
        b += (w * f.xyz) * ea[q].xyz;
    }
#elif TSIS_LSS_LANES == 8
    float8 br = (float8)(0.0f);
    float8 bg = (float8)(0.0f);
    float8 bb = (float8)(0.0f);
    const float8 lane = (float8)(0.0f, 1.0f, 2.0f, 3.0f, 4.0f, 5.0f, 6.0f, 7.0f);
    const int last = (int)info.size - 1;
    for (int k = 0; k < m; k += 8) {
        const float8 kk = lane + (float)k;
        const float8 t = (kk + xi) * du;
        const int8 i = min(convert_int8(t), entries - 1);
        LSS_LANES(LSS_LOAD_RADII)
        const float8 r0 = LSS_VEC(ra, x);
        const float8 r1 = LSS_VEC(ra, y);
        const float8 r = r0 + (t - convert_float8(i)) * (r1 - r0);
        const float16 d = vload16(0, (const __global float*)(dirs + k));
        const float8 sx = floor(px + (cs * d.even - sn * d.odd) * r * per_mm);
        const float8 sy = floor(py + (sn * d.even + cs * d.odd) * r * per_mm);
        const int8 inside = isgreaterequal(sx, 0.0f) & isless(sx, (float)width) &
                            isgreaterequal(sy, 0.0f) & isless(sy, (float)height) &
                            isless(kk, (float)m);
        const int8 q = select((int8)pix, convert_int8(sy) * width + convert_int8(sx), inside);
        const float8 w = select((float8)(0.0f), (r1 - r0) * r, inside);
        LSS_LANES(LSS_LOAD_PIXEL)
        const float8 dx = LSS_VEC(p, x) - xo.x;
        const float8 dy = LSS_VEC(p, y) - xo.y;
        const float8 dz = LSS_VEC(p, z) - xo.z;
        float8 frac;
        const int8 row = tsis_profile_index8(sqrt(dx * dx + dy * dy + dz * dz), info, &frac);
        /* Out of range gives the last row with frac 0; it reads row `last` twice. */
        const int8 next = min(row + 1, last);
        const float8 wf =
            select((float8)(0.0f), w, (row < last) & isequal(LSS_VEC(p, w), (float8)(medium)));
        LSS_LANES(LSS_LOAD_ROWS)
        br += wf * LSS_VEC(e, x) * (LSS_VEC(ta, x) + frac * (LSS_VEC(tb, x) - LSS_VEC(ta, x)));
        bg += wf * LSS_VEC(e, y) * (LSS_VEC(ta, y) + frac * (LSS_VEC(tb, y) - LSS_VEC(ta, y)));
        bb += wf * LSS_VEC(e, z) * (LSS_VEC(ta, z) + frac * (LSS_VEC(tb, z) - LSS_VEC(ta, z)));
    }
    const float3 b = (float3)(lss_sum8(br), lss_sum8(bg), lss_sum8(bb));
#else
#error "TSIS_LSS_LANES must be 1 or 8"
#endif
    const float norm = (float)entries * 6.2831853f / ((float)m * depth * depth);
    out[j] = (float4)(b * norm, 0.0f);
}
