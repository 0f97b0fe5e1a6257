/* Translucent Shadow Maps (Dachsbacher & Stamminger 2003), --method tsm:
 * B(xo) = sum over lights and taps k of Phi_k * Rd_ring(k)(dz_k), a fixed
 * pattern of taps around xo's projection into each light's flux map. The
 * pattern, and why the weights are ring tables, is documented with the host
 * code (host/render/method_tsm.cpp).
 *
 * Pyramids (one per light, levels back to back, level l at cell levels[l].x,
 * levels[l].y x levels[l].z cells):
 *   F = flux summed over the cell's texels (rgb),
 *   P = luminance-weighted positions summed over the cell (Y x, Y y, Y z, Y),
 * so a bilinear mix of cells gives a footprint's flux and the centroid of the
 * light it received. F's w is the cell's medium tag (1 + medium, mesh/media.h;
 * 0: no surface, -1: several): a tap reads only cells of the exit point's
 * medium, so light does not cross between media (a coarse cell straddling
 * two media is skipped: tsm's approximation near where media meet). */
#include "light_map.h"
#include "profile.h"

/* Level 0 from one light's maps; global size >= count. */
kernel void tsis_tsm_level0(const __global float4* flux, const __global float4* position,
                            const int count, __global float4* F, __global float4* P) {
    const int i = get_global_id(0);
    if (i >= count) return;
    const float4 f = flux[i];
    const float y = TSIS_LUMINANCE(f.x, f.y, f.z);
    F[i] = (float4)(f.xyz, f.w);
    P[i] = (float4)(y * position[i].xyz, y);
}

/* Level l+1 (dst, dw x dh) from level l (src, sw x sh): 2x2 sums; odd edges
 * sum what exists. Global size >= (dw, dh). */
kernel void tsis_tsm_reduce(__global float4* F, __global float4* P, const int src, const int sw,
                            const int sh, const int dst, const int dw, const int dh) {
    const int x = get_global_id(0);
    const int y = get_global_id(1);
    if (x >= dw || y >= dh) return;
    float4 f = (float4)(0.0f);
    float4 p = (float4)(0.0f);
    float medium = 0.0f;
    for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx) {
            const int sx = 2 * x + dx;
            const int sy = 2 * y + dy;
            if (sx < sw && sy < sh) {
                const float4 c = F[src + sy * sw + sx];
                f += c;
                p += P[src + sy * sw + sx];
                if (c.w != 0.0f) medium = medium == 0.0f || medium == c.w ? c.w : -1.0f;
            }
        }
    f.w = medium;
    F[dst + y * dw + x] = f;
    P[dst + y * dw + x] = p;
}

/* A bilinear weight, kept for a cell of `medium` (or of none: it holds 0). */
static inline float tsm_keep(const float w, const float4 cell, const float medium) {
    return cell.w == medium || cell.w == 0.0f ? w : 0.0f;
}

/* Bilinear mix of the four cells around c (in cells, cell j's centre at j),
 * clamped at the map's edge (the maps' borders are empty), over the cells of
 * `medium`. */
static void tsm_bilinear(const __global float4* F, const __global float4* P, const int4 level,
                         const float2 c, const float medium, float4* f, float4* p) {
    const float2 c0 = floor(c);
    const float2 t = c - c0;
    const int x0 = clamp((int)c0.x, 0, level.y - 1);
    const int y0 = clamp((int)c0.y, 0, level.z - 1);
    const int x1 = min(x0 + 1, level.y - 1);
    const int y1 = min(y0 + 1, level.z - 1);
    const int r0 = level.x + y0 * level.y;
    const int r1 = level.x + y1 * level.y;
    const float4 f00 = F[r0 + x0], f10 = F[r0 + x1], f01 = F[r1 + x0], f11 = F[r1 + x1];
    const float w00 = tsm_keep((1.0f - t.x) * (1.0f - t.y), f00, medium);
    const float w10 = tsm_keep(t.x * (1.0f - t.y), f10, medium);
    const float w01 = tsm_keep((1.0f - t.x) * t.y, f01, medium);
    const float w11 = tsm_keep(t.x * t.y, f11, medium);
    *f = w00 * f00 + w10 * f10 + w01 * f01 + w11 * f11;
    *p = w00 * P[r0 + x0] + w10 * P[r0 + x1] + w01 * P[r1 + x0] + w11 * P[r1 + x1];
}

/* One light, one output point per work-item. Measured on PoCL (512x512
 * default scene): the bilinear reads dominate (nearest-cell reads halve the
 * pass), and choosing the mip level once per ring instead of per tap saved a
 * third. source: the light's position (w = 1) or
 * its direction of travel (w = 0). rings: one profile table per ring, back to
 * back (info.size entries each), f_ring(dz) = Rd averaged over the ring's
 * annulus of the plane at depth offset dz. accumulate: add to out (the lights
 * after the first). */
kernel void tsis_tsm_filter(const __global float4* points, const int count,
                            const TsisLightMapInfo light, const float4 source,
                            const __global float4* F, const __global float4* P,
                            const __global int4* levels, const int level_count,
                            const __global TsisTsmTap* taps, const int tap_count,
                            const __global float4* rings, const TsisTableInfo info,
                            const float radius_mm, const int accumulate, __global float4* out) {
    const int j = get_global_id(0);
    if (j >= count) return;
    const float3 xo = points[j].xyz;
    const float medium = points[j].w;
    const float3 o = tsis_light_project(&light, xo);
    /* Depth offsets are taken along the light's direction of travel at xo. */
    const float3 travel = source.w > 0.0f ? normalize(xo - source.xyz) : source.xyz;
    const float rt = radius_mm / (light.tau_per_w * o.z); /* R in level-0 texels */
    float3 b = (float3)(0.0f);
    /* Taps come ring by ring and share their ring's footprint, so the mip
     * level is chosen once per ring. */
    int ring = -1;
    int4 level = (int4)(0);
    float footprint = 0.0f, scale = 1.0f, weight = 0.0f;
    for (int k = 0; k < tap_count; ++k) {
        const TsisTsmTap tap = taps[k];
        if ((int)tap.ring != ring) {
            ring = (int)tap.ring;
            footprint = tap.area * rt * rt; /* level-0 texels the tap stands for */
            /* Cells half the footprint's side: the bilinear tent spans about the footprint. */
            const int lod =
                clamp((int)rint(0.5f * log2(max(footprint, 1.0f))) - 1, 0, level_count - 1);
            level = levels[lod];
            scale = 1.0f / (float)(1 << lod);
            /* Mean flux per level-0 texel (a level-l cell sums 4^l) times the footprint. */
            weight = footprint * scale * scale;
        }
        float4 f, p;
        tsm_bilinear(F, P, level, (o.xy + rt * (float2)(tap.x, tap.y)) * scale - 0.5f, medium, &f,
                     &p);
        if (!(p.w > 0.0f)) continue; /* no light there */
        const float dz = fabs(dot(p.xyz / p.w - xo, travel));
        const float4 rd = tsis_profile(rings + ring * (int)info.size, info, dz);
        b += f.xyz * weight * rd.xyz;
    }
    const float4 base = accumulate ? out[j] : (float4)(0.0f);
    out[j] = base + (float4)(b, 0.0f);
}
