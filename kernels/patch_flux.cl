/* What enters each patch of the object transport's fit
 * (host/render/object_transport.h), from the flux atlas' texels the patch
 * holds, texels[start[p] .. start[p + 1]) (atlas indices): the flux (rgb) and
 * the luminance-weighted tangential part of the refracted direction of travel,
 * s = -(l - (n.l) n) / eta per light (xyz), and of its square |s|^2 less the
 * walks' mean (w, TSIS_ENTRY_MEAN_SIN2). A texel's flux is shared among the
 * lights by their unshadowed irradiance I Ft cos / d^2 (the atlas holds only
 * the sum); flux no light explains (the environment's) has no direction.
 * lights: 2 float4 a light, (vec, type: 0 point, 1 directional) and (rgb, 0).
 * One work-group a patch (a few hundred patches of a few hundred to a few
 * thousand texels): its work-items stride over the patch's texels, then sum
 * in local memory (TSIS_PATCH_GROUP items, a power of two). */
#include "fresnel.h"
#include "tsis_shared.h"

__kernel void tsis_patch_flux(__global const float4* flux, __global const int* sample_texel,
                              __global const float4* sample_geometry,
                              __global const float* eta_of_medium, __global const float4* lights,
                              const int light_count, __global const int* start,
                              __global const int* texels, const int patches,
                              __global float4* out_flux, __global float4* out_direction) {
    const int p = get_group_id(0);
    const int lid = get_local_id(0);
    __local float4 sum_of[TSIS_PATCH_GROUP], dir_of[TSIS_PATCH_GROUP];
    __local float square_of[TSIS_PATCH_GROUP];
    float4 sum = (float4)(0.0f);
    float3 dir = (float3)(0.0f);
    float square = 0.0f;
    float y_sub = 0.0f; /* the luminance of the texels that gave a direction */
    for (int k = start[p] + lid; k < start[p + 1]; k += TSIS_PATCH_GROUP) sum += flux[texels[k]];
    /* The direction from TSIS_PATCH_DIRECTION_SAMPLES of the patch's texels
     * (sample_texel, -1 past a small patch's own; sample_geometry: their
     * position, w the medium, and normal), scaled to the patch's flux below:
     * a mean over a patch does not need every texel, and its light math is
     * most of the kernel. */
    const int t = lid < TSIS_PATCH_DIRECTION_SAMPLES
                      ? sample_texel[p * TSIS_PATCH_DIRECTION_SAMPLES + lid]
                      : -1;
    if (t >= 0) {
        const int j = p * TSIS_PATCH_DIRECTION_SAMPLES + lid;
        const float4 f = flux[t];
        const float4 xm = sample_geometry[2 * j];
        const float3 x = xm.xyz;
        const float3 n = sample_geometry[2 * j + 1].xyz;
        const float eta = eta_of_medium[(int)xm.w];
        float3 s = (float3)(0.0f);
        float q = 0.0f, w = 0.0f;
        /* Branch-free (selects), so that the group's items run as vectors. */
        for (int i = 0; i < light_count; ++i) {
            const float4 v = lights[2 * i];
            const float4 rgb = lights[2 * i + 1];
            const bool point = v.w == 0.0f;
            const float3 d = point ? v.xyz - x : -v.xyz;
            const float inv = rsqrt(max(dot(d, d), 1e-12f));
            const float3 l = d * inv;
            const float c = max(dot(n, l), 0.0f);
            const float e = TSIS_LUMINANCE(rgb.x, rgb.y, rgb.z) * tsis_fresnel_t(eta, c) * c *
                            (point ? inv * inv : 1.0f);
            s += e * (-(l - c * n) / eta);
            q += e * (1.0f - c * c) / (eta * eta);
            w += e;
        }
        const float y = TSIS_LUMINANCE(f.x, f.y, f.z);
        y_sub += y;
        dir += w > 0.0f ? y * s / w : (float3)(0.0f);
        square += w > 0.0f ? y * (q / w - TSIS_ENTRY_MEAN_SIN2(eta)) : 0.0f;
    }
    sum_of[lid] = sum;
    dir_of[lid] = (float4)(dir, y_sub);
    square_of[lid] = square;
    barrier(CLK_LOCAL_MEM_FENCE);
    for (int width = TSIS_PATCH_GROUP / 2; width > 0; width /= 2) {
        if (lid < width) {
            sum_of[lid] += sum_of[lid + width];
            dir_of[lid] += dir_of[lid + width];
            square_of[lid] += square_of[lid + width];
        }
        barrier(CLK_LOCAL_MEM_FENCE);
    }
    if (lid == 0 && p < patches) {
        out_flux[p] = sum_of[0];
        const float4 total = sum_of[0];
        const float y = TSIS_LUMINANCE(total.x, total.y, total.z);
        out_direction[p] = dir_of[0].w > 0.0f
                               ? (float4)(dir_of[0].xyz, square_of[0]) * (y / dir_of[0].w)
                               : (float4)(0.0f);
    }
}
