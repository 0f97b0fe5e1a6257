/* The flux pyramid and its error-bounded descent (--method pyramid).
 *
 * The thesis' CDF pyramid sums the flux atlas in 2x2 blocks so samples can be
 * drawn by descending it. Here each block also keeps what Jensen & Buhler's
 * hierarchical integration needs of an octree node (TsisFluxNode): the flux
 * per channel, the surface area, the flux-weighted position and a radius that
 * bounds every texel of the block (texels adjacent in the atlas need not be
 * near each other in 3D: a block spanning two charts gets a large radius and
 * is opened). B(xo) = sum over a cut of the pyramid of flux_n * f(|xo - p_n|),
 * the cut chosen per group of output points so that every node used whole
 * satisfies
 *
 *     s_n^2 < epsilon * (d^2 + l^2),   s_n^2 = max(radius_n^2, area_n / pi),
 *
 * d the distance from p_n to the nearest of the group's points and l the
 * material's smallest mean
 * free path 1/max sigma_t'. The d^2 term is Jensen & Buhler's criterion
 * (area / distance^2 < epsilon, with the extent so that split blocks open);
 * the l^2 term stops the descent once a node is small against the scale on
 * which Rd itself varies near r = 0, so the pixel's own neighbourhood is not
 * opened down to single texels. A node whose extent reaches the points has
 * d < radius and is therefore opened unless it is smaller than sqrt(epsilon) l.
 * Finest-level nodes are used whole regardless. The relative error of using a
 * node whole (midpoint rule) is of order s^2 / (d^2 + l^2), so it falls with
 * epsilon; epsilon = 0 visits every texel (the exact sum over the atlas).
 *
 * Layout: level 0 = the atlas (res x res nodes, row-major), level k =
 * (res >> k)^2 nodes, all levels in one buffer in mipmap order (as pyramid.cl;
 * offsets from ImportanceSampler::levelOffset). Deterministic: fixed descent
 * order, no atomics. */
#include "tsis_shared.h"

#define TSIS_LANE_WIDTH 8
#include "lanes.h"

/* Level 0 from the atlases: flux (rgb), position (xyz, w = covered) and the
 * geometry atlas' normal (w = the texel's area, mm^2). Negative or NaN flux
 * counts as 0. A texel's radius: the half-diagonal of a square of its area. */
kernel void tsis_flux_leaves(const __global float4* flux, const __global float4* position,
                             const __global float4* normal, const int count,
                             __global TsisFluxNode* level0) {
    const int i = get_global_id(0);
    if (i >= count) return;
    const float4 p = position[i];
    TsisFluxNode n = {0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f};
    if (p.w > 0.0f) {
        const float4 f = flux[i];
        const float area = fmax(normal[i].w, 0.0f);
        n.fr = fmax(f.x, 0.0f); /* fmax(NaN, 0) = 0 */
        n.fg = fmax(f.y, 0.0f);
        n.fb = fmax(f.z, 0.0f);
        n.area = area;
        n.px = p.x;
        n.py = p.y;
        n.pz = p.z;
        n.radius = 0.70710678f * sqrt(area);
    }
    level0[i] = n;
}

static inline float tsis_node_weight(const TsisFluxNode n, const int by_area) {
    return by_area ? n.area : TSIS_LUMA_R * n.fr + TSIS_LUMA_G * n.fg + TSIS_LUMA_B * n.fb;
}

/* One level from the one below: sums, the position weighted by the children's
 * flux luminance (by area when the block is dark), and a radius that bounds
 * every child's sphere. */
kernel void tsis_flux_reduce(__global TsisFluxNode* nodes, const int src_offset,
                             const int dst_offset, const int dst_res) {
    const int i = get_global_id(0);
    if (i >= dst_res * dst_res) return;
    const int x = i % dst_res;
    const int y = i / dst_res;
    const int src_res = 2 * dst_res;
    const __global TsisFluxNode* c = nodes + src_offset + (2 * y) * src_res + 2 * x;
    const TsisFluxNode k0 = c[0], k1 = c[1], k2 = c[src_res], k3 = c[src_res + 1];
    TsisFluxNode n;
    n.fr = ((k0.fr + k1.fr) + k2.fr) + k3.fr;
    n.fg = ((k0.fg + k1.fg) + k2.fg) + k3.fg;
    n.fb = ((k0.fb + k1.fb) + k2.fb) + k3.fb;
    n.area = ((k0.area + k1.area) + k2.area) + k3.area;
    const int by_area = !(TSIS_LUMA_R * n.fr + TSIS_LUMA_G * n.fg + TSIS_LUMA_B * n.fb > 0.0f);
    const float w0 = tsis_node_weight(k0, by_area), w1 = tsis_node_weight(k1, by_area);
    const float w2 = tsis_node_weight(k2, by_area), w3 = tsis_node_weight(k3, by_area);
    const float wsum = ((w0 + w1) + w2) + w3;
    float3 p = (float3)(0.0f);
    if (wsum > 0.0f) {
        p = (w0 * (float3)(k0.px, k0.py, k0.pz) + w1 * (float3)(k1.px, k1.py, k1.pz) +
             w2 * (float3)(k2.px, k2.py, k2.pz) + w3 * (float3)(k3.px, k3.py, k3.pz)) / wsum;
    }
    float radius = 0.0f;
    if (k0.area > 0.0f) radius = fmax(radius, distance(p, (float3)(k0.px, k0.py, k0.pz)) + k0.radius);
    if (k1.area > 0.0f) radius = fmax(radius, distance(p, (float3)(k1.px, k1.py, k1.pz)) + k1.radius);
    if (k2.area > 0.0f) radius = fmax(radius, distance(p, (float3)(k2.px, k2.py, k2.pz)) + k2.radius);
    if (k3.area > 0.0f) radius = fmax(radius, distance(p, (float3)(k3.px, k3.py, k3.pz)) + k3.radius);
    /* Rounding: p is a weighted mean, so it may sit a few ulps off; keep the
     * bound conservative. */
    n.radius = radius * 1.000001f;
    n.px = p.x;
    n.py = p.y;
    n.pz = p.z;
    nodes[dst_offset + i] = n;
}

/* A node's code on the descent stack: level, y, x (x, y < 4096). */
#define TSIS_NODE_CODE(level, x, y) (((level) << 24) | ((y) << 12) | (x))

static inline float tsis_hmin8(const float8 v) {
    const float4 a = fmin(v.lo, v.hi);
    const float2 b = fmin(a.lo, a.hi);
    return fmin(b.x, b.y);
}

/* B for 8 consecutive points per work-item, all 8 sharing one cut (a node is
 * used whole only when the criterion holds for the nearest of them), so the
 * descent's control flow is scalar and the evaluations fill the vector lanes.
 * Item k takes points order[8k ... 8k+7]: the host orders the covered pixels
 * by 4x2-pixel tiles, so the 8 are neighbours on screen.
 * `levels` = log2(res); `split` the per-channel table of profile.h (built by
 * tsis_profile_split in gather.cl); evaluations[item] = nodes used whole.
 * Global size = ceil(count / 8). */
/* Lane k's point through the order (past count: the last one, never stored). */
#define TSIS_LOAD_ORDERED(k) const int i##k = order[min(base + 0x##k, count - 1)]; const float4 q##k = points[i##k];
#define TSIS_STORE_ORDERED(k) if (base + 0x##k < count) out[i##k] = (float4)(br.s##k, bg.s##k, bb.s##k, 0.0f);

kernel void tsis_flux_pyramid_gather(const __global float4* points, const __global int* order,
                                     const int count,
                                     const __global TsisFluxNode* nodes, const int res,
                                     const int levels, const float epsilon, const float ell2,
                                     const __global float2* split, const TsisTableInfo info,
                                     __global float4* out, __global int* evaluations) {
    const int item = get_global_id(0);
    const int base = item * TSIS_LANE_WIDTH;
    if (base >= count) return;
    TSIS_LANES(TSIS_LOAD_ORDERED)
    const floatW px = TSIS_VEC(q, x);
    const floatW py = TSIS_VEC(q, y);
    const floatW pz = TSIS_VEC(q, z);
    int offset[TSIS_PYRAMID_MAX_LEVELS + 1];
    int o = 0;
    for (int k = 0; k <= levels; ++k) {
        offset[k] = o;
        o += (res >> k) * (res >> k);
    }

    floatW br = (floatW)(0.0f);
    floatW bg = (floatW)(0.0f);
    floatW bb = (floatW)(0.0f);
    int used = 0;
    /* Depth-first: each opened node pushes its 4 children, so the stack never
     * holds more than 3 per level plus one. */
    int stack[3 * TSIS_PYRAMID_MAX_LEVELS + 2];
    int top = 0;
    stack[top++] = TSIS_NODE_CODE(levels, 0, 0);
    while (top > 0) {
        const int code = stack[--top];
        const int level = code >> 24;
        const int y = (code >> 12) & 0xfff;
        const int x = code & 0xfff;
        const TsisFluxNode n = nodes[offset[level] + y * (res >> level) + x];
        if (!(n.fr + n.fg + n.fb > 0.0f)) continue;
        const float3 at = (float3)(n.px, n.py, n.pz);
        const floatW dx = px - at.x, dy = py - at.y, dz = pz - at.z;
        const float d2 = tsis_hmin8(dx * dx + dy * dy + dz * dz);
        const float s2 = fmax(n.radius * n.radius, n.area * M_1_PI_F);
        if (level > 0 && !(s2 < epsilon * (d2 + ell2))) {
            const int cl = level - 1;
            stack[top++] = TSIS_NODE_CODE(cl, 2 * x + 1, 2 * y + 1);
            stack[top++] = TSIS_NODE_CODE(cl, 2 * x, 2 * y + 1);
            stack[top++] = TSIS_NODE_CODE(cl, 2 * x + 1, 2 * y);
            stack[top++] = TSIS_NODE_CODE(cl, 2 * x, 2 * y);
            continue;
        }
        tsis_lanes_add(px, py, pz, at, (float3)(n.fr, n.fg, n.fb), split, info, &br, &bg, &bb);
        ++used;
    }
    TSIS_LANES(TSIS_STORE_ORDERED)
    evaluations[item] = used;
}
