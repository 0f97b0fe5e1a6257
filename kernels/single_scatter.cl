/* Jensen et al. 2001's single-scattering term L(1) (docs/design.md "Single
 * scattering"), per covered camera point xo and one light, as the radiosity
 * the composite turns back into it:
 *   B1(xo) = to_radiosity * R,  L(1) = Ft(eta, cos theta_o) * R,
 *   R = sigma_s' p (1/K) sum_k Ft(eta, cos theta_i) E (cos theta_i / cos theta_ti) / eta^2
 *         * exp(-sigma_t' (s_i' + s_o)) / pdf(s_o),
 * s_o along the refracted camera ray, drawn with pdf sigma e^(-sigma s_o)
 * (sigma the smallest channel's sigma_t', so every channel's weight stays
 * below 1/sigma), K stratified draws, each jittered in its stratum by a
 * hash of the point, the stratum and the seed; xi
 * the light's entry point (the light view's surface at the sample's texel),
 * s_i' = (depth below xi's tangent plane) / cos theta_ti, Jensen's refracted
 * path. E (cos theta_i / cos theta_ti) is the beam's irradiance inside, and
 * 1/eta^2 the radiance's change leaving the medium (Jensen 2001 leaves both
 * out; the volumetric truth has them). Phase p = 1/(4 pi). */
#include "fresnel.h"
#include "hash.h"
#include "light_map.h"
#include "single_scatter_shared.h"

kernel void tsis_single_scatter(const __global float4* points, const __global float4* normals,
                                const int count, const float4 eye,
                                const __global TsisScatterMedium* media, const int media_count,
                                const TsisLightMapInfo map, const TsisScatterLight light,
                                const __global float4* flux, const __global float4* position,
                                const __global float4* light_normal, const int samples,
                                const uint seed, const int accumulate, __global float4* out) {
    const int j = get_global_id(0);
    if (j >= count) return;
    const float4 base = accumulate ? out[j] : (float4)(0.0f);
    const float tag = points[j].w;
    const int m = (int)(tag + 0.5f) - 1;
    if (m < 0 || m >= media_count) {
        out[j] = base;
        return;
    }
    const TsisScatterMedium md = media[m];
    const float3 xo = points[j].xyz;
    float3 n = normalize(normals[j].xyz);
    const float3 v = normalize(eye.xyz - xo);
    float cos_o = dot(n, v);
    /* As the composite: the side that faces the eye. */
    if (cos_o < 0.0f) {
        n = -n;
        cos_o = -cos_o;
    }
    const float inv_eta = 1.0f / md.eta;
    const float cos_to = sqrt(max(0.0f, 1.0f - inv_eta * inv_eta * (1.0f - cos_o * cos_o)));
    /* The camera ray refracted into the medium. */
    const float3 wt = normalize(-v * inv_eta + n * (inv_eta * cos_o - cos_to));
    const float3 sigma_s = (float3)(md.ss_r, md.ss_g, md.ss_b);
    const float3 sigma_t = (float3)(md.st_r, md.st_g, md.st_b);
    const float sigma = fmin(sigma_t.x, fmin(sigma_t.y, sigma_t.z));
    const float3 e_light = (float3)(light.r, light.g, light.b);
    const float3 light_vec = (float3)(light.x, light.y, light.z);
    const uint h = tsis_hash(tsis_hash((uint)j) ^ seed);
    float3 sum = (float3)(0.0f);
    for (int k = 0; k < samples; ++k) {
        const float u = ((float)k + tsis_hash_unit(tsis_hash(h + (uint)k))) / (float)samples;
        const float so = -log(1.0f - u) / sigma;
        const float3 x = xo + so * wt;
        const float3 q = tsis_light_project(&map, x);
        const int t = tsis_light_texel(&map, q.x, q.y);
        if (t < 0 || flux[t].w != tag) continue;
        const float3 xi = position[t].xyz;
        const float3 ni = normalize(light_normal[t].xyz);
        float3 e = e_light;
        float3 l;
        if (light.type == 0) {
            const float3 d = light_vec - xi;
            const float d2 = dot(d, d);
            e /= d2;
            l = d * rsqrt(d2);
        } else {
            l = -normalize(light_vec);
        }
        /* x in front of the light's first surface: outside the object. */
        if (dot(xi - x, normalize(light.type == 0 ? light_vec - x : l)) < -map.tau_per_w * q.z)
            continue;
        const float cos_i = dot(ni, l);
        if (!(cos_i > 0.0f)) continue;
        const float cos_ti = sqrt(max(0.0f, 1.0f - inv_eta * inv_eta * (1.0f - cos_i * cos_i)));
        const float si = fmax(dot(xi - x, ni), 0.0f) / cos_ti;
        const float3 w = exp(-sigma_t * (si + so) + sigma * so) / sigma;
        sum += w * (tsis_fresnel_t(md.eta, cos_i) * cos_i / cos_ti) * e;
    }
    const float3 r = sum * sigma_s * (inv_eta * inv_eta / (4.0f * M_PI_F * (float)samples));
    out[j] = base + (float4)(md.to_radiosity * r, 0.0f);
}
