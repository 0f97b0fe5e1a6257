/* The flux tree and its error-bounded descent (--method pyramid).
 *
 * The thesis' CDF pyramid sums the flux atlas in 2x2 blocks so samples can be
 * drawn by descending it. Atlas neighbours need not be surface neighbours,
 * though: the packer puts unrelated charts side by side, and a block across
 * two of them can never be used whole. So the atlas' covered texels are the
 * leaves of an octree over their positions, built once per mesh and atlas
 * resolution on the host from their sorted 3D Morton codes
 * (FluxTree::setLeaves; single-child levels skipped, up to 8 children a
 * node), and only its sums are made again on the device whenever the flux
 * atlas changes. Each node (TsisFluxNode) keeps what Jensen & Buhler's
 * hierarchical integration needs: the flux per channel, the surface area,
 * the flux-weighted position and a radius that bounds all its texels. B(xo)
 * = sum over a cut of flux_n * f(|xo - p_n|), the cut chosen per group of
 * output points so that every node used whole satisfies
 *
 *     s_n^2 < epsilon * (d^2 + l^2),   s_n^2 = max(radius_n^2, area_n / pi),
 *
 * d the distance from p_n to the nearest of the group's points and l the
 * material's smallest mean free path 1/max sigma_t'. The d^2 term is Jensen &
 * Buhler's criterion (area / distance^2 < epsilon, with the extent); the l^2
 * term stops the descent once a node is small against the scale on which Rd
 * itself varies near r = 0, so the pixel's own neighbourhood is not opened
 * down to single texels. A node whose extent reaches the points has
 * d < radius and is therefore opened unless it is smaller than sqrt(epsilon) l.
 * Leaves (single texels) are used whole regardless. The relative error of
 * using a node whole (midpoint rule) is of order s^2 / (d^2 + l^2), so it
 * falls with epsilon; epsilon = 0 visits every texel (the exact sum over the
 * atlas).
 *
 * Media never mix in a node (docs/design.md §2): the leaves are sorted by
 * medium first, the levels near the root split them by medium, and a node's
 * medium tag (1 + medium, mesh/media.h) is its topology's w, 0 for a node of
 * several.
 *
 * Layout: nodes in breadth-first order, the root first, so each depth is a
 * contiguous range and each node's children are contiguous; topology[i] =
 * (first child, children, texel, medium tag), children = 0 for a leaf. Deterministic:
 * fixed summation and descent order, no atomics. */
#include "tsis_shared.h"

#define TSIS_LANE_WIDTH 8
#include "lanes.h"

static inline float tsis_node_weight(const TsisFluxNode n, const int by_area) {
    return by_area ? n.area : TSIS_LUMINANCE(n.fr, n.fg, n.fb);
}

/* The nodes [begin, end) of one depth, the deeper ones already made. A leaf
 * (topology .y = 0) from its atlas texel .z: flux (rgb), position (xyz, w =
 * covered) and the geometry atlas' normal (w = the texel's area, mm^2);
 * negative or NaN flux counts as 0; radius the half-diagonal of a square of
 * its area. An inner node from its children .x .. .x + .y - 1: sums, the
 * position weighted by the children's flux luminance (by area when the node
 * is dark) and a radius that bounds every child's sphere. With flux_only, a
 * leaf keeps the position, area and radius an earlier run over the same
 * atlas wrote and takes only the flux (a third of the texel reads, which are
 * scattered: the leaves are in space order). */
kernel void tsis_flux_tree_update(const __global float4* flux, const __global float4* position,
                                  const __global float4* normal, const __global int4* topology,
                                  const int begin, const int end, const int flux_only,
                                  __global TsisFluxNode* nodes) {
    const int i = begin + get_global_id(0);
    if (i >= end) return;
    const int4 t = topology[i];
    TsisFluxNode n = {0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f};
    if (t.y == 0 && flux_only && nodes[i].area > 0.0f) {
        const float4 f = flux[t.z];
        nodes[i].fr = fmax(f.x, 0.0f);
        nodes[i].fg = fmax(f.y, 0.0f);
        nodes[i].fb = fmax(f.z, 0.0f);
        return;
    }
    if (t.y == 0) {
        const float4 p = position[t.z];
        if (p.w > 0.0f) {
            const float4 f = flux[t.z];
            const float area = fmax(normal[t.z].w, 0.0f);
            n.fr = fmax(f.x, 0.0f); /* fmax(NaN, 0) = 0 */
            n.fg = fmax(f.y, 0.0f);
            n.fb = fmax(f.z, 0.0f);
            n.area = area;
            n.px = p.x;
            n.py = p.y;
            n.pz = p.z;
            n.radius = 0.70710678f * sqrt(area);
        }
        nodes[i] = n;
        return;
    }
    const __global TsisFluxNode* c = nodes + t.x;
    for (int k = 0; k < t.y; ++k) {
        n.fr += c[k].fr;
        n.fg += c[k].fg;
        n.fb += c[k].fb;
        n.area += c[k].area;
    }
    const int by_area = !(TSIS_LUMINANCE(n.fr, n.fg, n.fb) > 0.0f);
    float3 p = (float3)(0.0f);
    float wsum = 0.0f;
    for (int k = 0; k < t.y; ++k) {
        const float w = tsis_node_weight(c[k], by_area);
        p += w * (float3)(c[k].px, c[k].py, c[k].pz);
        wsum += w;
    }
    if (wsum > 0.0f) p /= wsum;
    float radius = 0.0f;
    for (int k = 0; k < t.y; ++k)
        if (c[k].area > 0.0f)
            radius = fmax(radius, distance(p, (float3)(c[k].px, c[k].py, c[k].pz)) + c[k].radius);
    /* Rounding: p is a weighted mean, so it may sit a few ulps off; keep the
     * bound conservative. */
    n.radius = radius * 1.000001f;
    n.px = p.x;
    n.py = p.y;
    n.pz = p.z;
    nodes[i] = n;
}

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
 * topology: per node (first child, children, texel), the root node 0;
 * `split` the per-channel table of profile.h (built by
 * tsis_profile_split in gather.cl); evaluations[item] = nodes used whole.
 * Global size = ceil(count / 8). */
/* Lane k's point through the order (past count: the last one, never stored). */
#define TSIS_LOAD_ORDERED(k)                              \
    const int i##k = order[min(base + 0x##k, count - 1)]; \
    const float4 q##k = points[i##k];
#define TSIS_STORE_ORDERED(k) \
    if (base + 0x##k < count) out[i##k] = (float4)(br.s##k, bg.s##k, bb.s##k, 0.0f);

kernel void tsis_flux_tree_gather(const __global float4* points, const __global int* order,
                                  const int count, const __global TsisFluxNode* nodes,
                                  const __global int4* topology, const float epsilon,
                                  const float ell2, const __global float2* split,
                                  const TsisTableInfo info, __global float4* out,
                                  __global int* evaluations) {
    const int item = get_global_id(0);
    const int base = item * TSIS_LANE_WIDTH;
    if (base >= count) return;
    TSIS_LANES(TSIS_LOAD_ORDERED)
    TSIS_LANES_XYZ
    TSIS_LANES_SUMS
    int used = 0;
    /* Depth-first: each opened node pushes its children (at most 8), so the
     * stack never holds more than 7 per depth plus one. */
    int stack[7 * TSIS_FLUX_TREE_MAX_DEPTH + 1];
    int sp = 0;
    stack[sp++] = 0;
    while (sp > 0) {
        const int index = stack[--sp];
        const TsisFluxNode n = nodes[index];
        if (!(n.fr + n.fg + n.fb > 0.0f)) continue;
        const int4 t = topology[index];
        /* A node of several media (t.w = 0, only near the root) is opened; a
         * node of one medium counts only the lanes of that medium. */
        const float4 at = (float4)(n.px, n.py, n.pz, (float)t.w);
        const floatW dx = px - at.x, dy = py - at.y, dz = pz - at.z;
        const float d2 = tsis_hmin8(
            select((floatW)(INFINITY), dx * dx + dy * dy + dz * dz, isequal(pm, (floatW)(at.w))));
        const float s2 = fmax(n.radius * n.radius, n.area * M_1_PI_F);
        if (t.w != 0 && !(d2 < INFINITY)) continue;
        if (t.y > 0 && (t.w == 0 || !(s2 < epsilon * (d2 + ell2)))) {
            for (int c = t.x + t.y - 1; c >= t.x; --c) stack[sp++] = c;
            continue;
        }
        tsis_lanes_add(px, py, pz, pm, at, (float3)(n.fr, n.fg, n.fb), split, info, &br, &bg, &bb);
        ++used;
    }
    TSIS_LANES(TSIS_STORE_ORDERED)
    evaluations[item] = used;
}
