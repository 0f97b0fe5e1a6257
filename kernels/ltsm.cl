/* Local translucent shadow map (thesis 3.3.2): per covered pixel xo, a ring
 * filter around xo's projection in one light's flux map,
 *   B(xo) += sum_s (Phi_s / tau^2) * A'_s * f(|xo - x_s|),
 * tau the texel size on the plane through xo perpendicular to the light's
 * axis, so Phi / tau^2 is the flux per mm^2 of that plane (the thesis'
 * A' = A d^2), A'_s the sample's area (ltsm_shared.h), Phi_s the flux per
 * texel and x_s the lit surface point at the sample, both bilinear in the
 * maps (light_map.h): nearest texels put the centre sample up to half a texel
 * from xo, which matters where a texel is wider than zr. Samples where no
 * light landed (off the object, off the map) add nothing.
 * Tried and dropped: reading the flux and centroid from a mip level matching
 * the sample's ring sector (as tsm does). At silhouettes of the light view the
 * centroid moves towards the lit part, f(|xo - x|) / f(r_s) grows, and the
 * result overshoots (+10% on the plane, twice the error on the torus). */
#include "light_map.h"
#include "ltsm_shared.h"
#include "profile.h"

kernel void tsis_ltsm(const __global float4* points, const int count, const TsisLightMapInfo light,
                      const __global float4* flux, const __global float4* position,
                      const __global TsisRingSample* pattern, const int pattern_size,
                      const __global float4* table, const TsisTableInfo info, const int accumulate,
                      __global float4* out) {
    const int j = get_global_id(0);
    if (j >= count) return;
    const float3 xo = points[j].xyz;
    const float medium = points[j].w;
    const float3 o = tsis_light_project(&light, xo);
    const float inv_tau = 1.0f / (light.tau_per_w * o.z);
    float3 b = (float3)(0.0f);
    for (int s = 0; s < pattern_size; ++s) {
        const TsisRingSample p = pattern[s];
        float4 x;
        const float3 phi = tsis_light_bilinear(&light, flux, position, o.x + p.dx * inv_tau,
                                               o.y + p.dy * inv_tau, medium, &x);
        if (!(x.w > 0.0f)) continue;
        const float3 d = xo - x.xyz / x.w;
        const float4 f = tsis_profile(table, info, sqrt(dot(d, d)));
        b += phi * (float3)(p.ar, p.ag, p.ab) * f.xyz;
    }
    b *= inv_tau * inv_tau;
    const float4 base = accumulate ? out[j] : (float4)(0.0f);
    out[j] = base + (float4)(b, 0.0f);
}
