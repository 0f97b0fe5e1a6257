/* What enters each patch of the object transport's fit
 * (host/render/object_transport.h), from the flux atlas' texels the patch
 * holds, texels[start[p] .. start[p + 1]) (atlas indices): the flux (rgb) and
 * the luminance-weighted tangential part of the refracted direction of travel,
 * s = -(l - (n.l) n) / eta per light (xyz). A texel's flux is shared among the
 * lights by their unshadowed irradiance I Ft cos / d^2 (the atlas holds only
 * the sum); flux no light explains (the environment's) has no direction.
 * lights: 2 float4 a light, (vec, type: 0 point, 1 directional) and (rgb, 0).
 * One work-item a patch; a few hundred patches of a few hundred texels each. */
#include "fresnel.h"
#include "tsis_shared.h"

__kernel void tsis_patch_flux(__global const float4* flux, __global const float4* position,
                              __global const float4* normal, __global const float* eta_of_medium,
                              __global const float4* lights, const int light_count,
                              __global const int* start, __global const int* texels,
                              const int patches, __global float4* out_flux,
                              __global float4* out_direction) {
    const int p = get_global_id(0);
    if (p >= patches) return;
    float4 sum = (float4)(0.0f);
    float3 dir = (float3)(0.0f);
    for (int k = start[p]; k < start[p + 1]; ++k) {
        const int t = texels[k];
        const float4 f = flux[t];
        sum += f;
        const float3 x = position[t].xyz;
        const float3 n = normalize(normal[t].xyz);
        const float eta = eta_of_medium[max((int)(position[t].w + 0.5f) - 1, 0)];
        float3 s = (float3)(0.0f);
        float w = 0.0f;
        for (int i = 0; i < light_count; ++i) {
            const float4 v = lights[2 * i];
            const float4 rgb = lights[2 * i + 1];
            float3 l;
            float falloff = 1.0f;
            if (v.w == 0.0f) {
                const float3 d = v.xyz - x;
                const float d2 = max(dot(d, d), 1e-12f);
                falloff = 1.0f / d2;
                l = d * rsqrt(d2);
            } else {
                l = -normalize(v.xyz);
            }
            const float c = dot(n, l);
            if (c <= 0.0f) continue;
            const float e =
                TSIS_LUMINANCE(rgb.x, rgb.y, rgb.z) * tsis_fresnel_t(eta, c) * c * falloff;
            s += e * (-(l - c * n) / eta);
            w += e;
        }
        if (w > 0.0f) dir += TSIS_LUMINANCE(f.x, f.y, f.z) * s / w;
    }
    out_flux[p] = sum;
    out_direction[p] = (float4)(dir, 0.0f);
}
