/* --method mis: one unbiased estimator for the global and the local regime
 * (host/render/method_mis.h has the derivation). Two kinds of samples, all
 * densities in the surface-area measure:
 *   T: N texture-space samples (pick atlas texel i with p_i = Y(Phi_i)/sum Y),
 *      p_T(x) = Y(E(x)) / sum Y, contribution w_i * Rd(|xo - x_i|);
 *   D: n samples per pixel and light l on the plane through xo perpendicular
 *      to the light's axis, landing on texel t of the light's map; the radius
 *      r is drawn so that s = sqrt(r^2 + z^2) follows the importance of Rd,
 *      z the distance from xo to the lit surface at its own projection (0
 *      where xo is lit; the thickness where light reaches xo through the
 *      object): density q per mm^2 of plane, p_l(x) = q * tau^2 / A_l(t), A_l
 *      the texel's area on the surface; contribution Phi_l(t) * Rd /
 *      (n q tau^2) estimates light l's share of B.
 * Both are weighted by one partition of unity c(x) + (1 - c(x)) = 1, the
 * balance heuristic c = N p_T / (N p_T + sum_l n p_l) with p_T and p_l
 * estimated from the light maps (E_l = Phi_l / A_l): any c keeps the sum
 * unbiased, a good one keeps its variance low. */
#include "hash.h"
#include "light_map.h"
#include "mis_shared.h"
#include "profile.h"

/* Per texel of every light map: (E rgb, 1 / A) with A the texel's area on
 * the surface from its neighbours' positions (on each axis the nearer lit
 * neighbour, so an edge of the light view does not stretch it); 0 where no
 * light landed. Global size >= lights * res^2. */
kernel void tsis_mis_texels(const __global float4* flux, const __global float4* position,
                            const TsisMisInfo mi, __global float4* irradiance) {
    const int g = get_global_id(0);
    const int per = mi.res * mi.res;
    if (g >= mi.lights * per) return;
    const int base = (g / per) * per;
    const int i = g - base;
    const int x = i % mi.res;
    const int y = i / mi.res;
    const float4 phi = flux[g];
    if (!(phi.w > 0.0f)) {
        irradiance[g] = (float4)(0.0f);
        return;
    }
    /* Neighbours of another medium (flux a: the tag) are another surface. */
    const float3 p = position[g].xyz;
    float3 axis[2];
    for (int a = 0; a < 2; ++a) {
        float best = INFINITY;
        axis[a] = (float3)(0.0f);
        for (int s = -1; s <= 1; s += 2) {
            const int nx = x + (a == 0 ? s : 0);
            const int ny = y + (a == 1 ? s : 0);
            if (nx < 0 || ny < 0 || nx >= mi.res || ny >= mi.res) continue;
            const int n = base + ny * mi.res + nx;
            if (flux[n].w != phi.w) continue;
            const float3 d = position[n].xyz - p;
            const float len = dot(d, d);
            if (len < best) {
                best = len;
                axis[a] = d;
            }
        }
    }
    const float area = length(cross(axis[0], axis[1]));
    irradiance[g] = area > 0.0f ? (float4)(phi.xyz / area, 1.0f / area) : (float4)(0.0f);
}

/* Light m's texel that sees x, or -1 if x is not lit by it: x must lie within
 * two texel sizes of the surface point the map holds there. */
static inline int mis_visible(const __global TsisLightMapInfo* lights, const int m,
                              const __global float4* position, const __global float4* irradiance,
                              const float3 x, float2* tc) {
    TsisLightMapInfo l = lights[m];
    const float3 c = tsis_light_project(&l, x);
    *tc = c.xy;
    const int t = tsis_light_texel(&l, c.x, c.y);
    if (t < 0) return -1;
    const int g = m * l.res * l.res + t;
    const float inv_area = irradiance[g].w;
    if (!(inv_area > 0.0f)) return -1;
    const float3 d = position[g].xyz - x;
    return dot(d, d) * inv_area < 4.0f ? g : -1;
}

/* The radius sampler: radii at equal steps 1/K of the importance's cdf,
 * linear between. Its cdf at s (the same piecewise-linear function). */
static inline float mis_cdf(const __global float* radii, const int segments, const float s) {
    if (!(s > radii[0])) return 0.0f;
    if (!(s < radii[segments])) return 1.0f;
    int lo = 0, hi = segments;
    while (hi - lo > 1) {
        const int mid = (lo + hi) / 2;
        if (radii[mid] <= s)
            lo = mid;
        else
            hi = mid;
    }
    return ((float)lo + (s - radii[lo]) / (radii[lo + 1] - radii[lo])) / (float)segments;
}

/* The distance samples' density at plane distance r for depth offset z, given
 * tail = 1 - cdf(z): q0(s) / tail with s = sqrt(r^2 + z^2), q0 the z = 0
 * density per mm^2 (binned; used only in the weights). */
static inline float mis_q(const __global float* q, const TsisMisInfo mi, const float r,
                          const float z, const float tail) {
    const float b = sqrt(r * r + z * z) * mi.q_inv_step;
    return b < (float)mi.q_size && tail > 0.0f ? q[(int)b] / tail : 0.0f;
}

/* Per texture-space sample i: where it lands in every light map, as
 * (x, y, 1/A, 0) at [m * N + i] (1/A = 0: not lit by m), and N p_T at [i]. */
kernel void tsis_mis_prepare(const __global TsisSample* samples, const TsisMisInfo mi,
                             const __global TsisLightMapInfo* lights,
                             const __global float4* position, const __global float4* irradiance,
                             __global float4* seen, __global float* tex_density) {
    const int i = get_global_id(0);
    if (i >= mi.n_tex) return;
    const float3 x = (float3)(samples[i].px, samples[i].py, samples[i].pz);
    float3 e = (float3)(0.0f);
    for (int m = 0; m < mi.lights; ++m) {
        float2 tc;
        const int g = mis_visible(lights, m, position, irradiance, x, &tc);
        const float4 irr = g >= 0 ? irradiance[g] : (float4)(0.0f);
        e += irr.xyz;
        seen[m * mi.n_tex + i] = (float4)(tc, irr.w, 0.0f);
    }
    tex_density[i] = mi.tex_scale * TSIS_LUMINANCE(e.x, e.y, e.z);
}

/* One output point per work-item. */
kernel void tsis_mis_gather(const __global float4* points, const int count, const TsisMisInfo mi,
                            const __global TsisSample* samples, const __global float4* seen,
                            const __global float* tex_density,
                            const __global TsisLightMapInfo* lights, const __global float4* flux,
                            const __global float4* position, const __global float4* irradiance,
                            const __global float* radii, const __global float* q,
                            const __global float4* table, const TsisTableInfo info,
                            __global float4* out) {
    const int j = get_global_id(0);
    if (j >= count) return;
    const float3 xo = points[j].xyz;
    const float medium = points[j].w; /* light counts only within it (profile.h) */
    /* xo in each light's map: texel coordinates and tau, the texel size at
     * xo's depth; z, the depth offset to the lit surface there, and the
     * sampler's mass beyond it. */
    float3 o[TSIS_MAX_LIGHTS];
    float2 zt[TSIS_MAX_LIGHTS];
    const int per = mi.res * mi.res;
    for (int m = 0; m < mi.lights; ++m) {
        TsisLightMapInfo l = lights[m];
        const float3 c = tsis_light_project(&l, xo);
        o[m] = (float3)(c.xy, l.tau_per_w * c.z);
        float4 lit;
        tsis_light_bilinear(&l, flux + m * per, position + m * per, c.x, c.y, medium, &lit);
        const float z = lit.w > 0.0f ? length(lit.xyz / lit.w - xo) : 0.0f;
        zt[m] = (float2)(z, 1.0f - mis_cdf(radii, mi.segments, z));
    }
    float3 b = (float3)(0.0f);

    /* T: c(x_i) w_i Rd. */
    for (int i = 0; i < mi.n_tex; ++i) {
        const TsisSample s = samples[i];
        const float pt = tex_density[i];
        float pd = 0.0f;
        for (int m = 0; m < mi.lights; ++m) {
            const float4 v = seen[m * mi.n_tex + i];
            if (v.z > 0.0f)
                pd += mis_q(q, mi, length(v.xy - o[m].xy) * o[m].z, zt[m].x, zt[m].y) * o[m].z *
                      o[m].z * v.z;
        }
        pd *= (float)mi.n_dist;
        const float c = pt + pd > 0.0f ? pt / (pt + pd) : 1.0f;
        const float3 d = xo - (float3)(s.px, s.py, s.pz);
        const float4 f = tsis_profile(table, info, tsis_medium_distance(d, medium, s.medium));
        b += c * (float3)(s.wr, s.wg, s.wb) * f.xyz;
    }

    /* D: per light, n points of an R2 sequence shifted by a per-pixel hash. */
    for (int l = 0; l < mi.lights; ++l) {
        const uint h = tsis_hash((uint)j ^ tsis_hash(mi.seed * 8u + (uint)l));
        const float s1 = tsis_hash_unit(h);
        const float s2 = tsis_hash_unit(tsis_hash(h + 0x9e3779b9U));
        const float tau = o[l].z;
        const TsisLightMapInfo ll = lights[l];
        for (int k = 0; k < mi.n_dist; ++k) {
            const float a1 = s1 + 0.7548776662f * (float)k;
            const float a2 = s2 + 0.5698402910f * (float)k;
            const float u1 = a1 - floor(a1);
            const float u2 = a2 - floor(a2);
            /* s from the cdf's part beyond z, then r on the plane. */
            const float sk = (1.0f - zt[l].y * (1.0f - u1)) * (float)mi.segments;
            const int seg = clamp((int)sk, 0, mi.segments - 1);
            const float s0 = radii[seg];
            const float ds = radii[seg + 1] - s0;
            const float sd = s0 + (sk - (float)seg) * ds;
            const float r = sqrt(max(sd * sd - zt[l].x * zt[l].x, 0.0f));
            if (!(r > 0.0f) || !(ds > 0.0f) || !(zt[l].y > 0.0f)) continue;
            /* Exact density of this draw per mm^2 of the plane: ds = r dr / s. */
            const float qd = 1.0f / ((float)mi.segments * ds * zt[l].y * 6.2831853f * sd);
            float cs;
            const float sn = sincos(6.2831853f * u2, &cs);
            const int t = tsis_light_texel(&ll, o[l].x + r / tau * cs, o[l].y + r / tau * sn);
            if (t < 0) continue;
            const int g = l * mi.res * mi.res + t;
            const float4 phi = flux[g];
            if (phi.w != medium) continue; /* no surface, or another medium's */
            const float3 x = position[g].xyz;
            /* c(x), the same function as for T samples. */
            float3 e = (float3)(0.0f);
            float pd = 0.0f;
            for (int m = 0; m < mi.lights; ++m) {
                float2 tc;
                const int gm = mis_visible(lights, m, position, irradiance, x, &tc);
                if (gm < 0) continue;
                const float4 irr = irradiance[gm];
                e += irr.xyz;
                pd += mis_q(q, mi, length(tc - o[m].xy) * o[m].z, zt[m].x, zt[m].y) * o[m].z *
                      o[m].z * irr.w;
            }
            const float pt = mi.tex_scale * TSIS_LUMINANCE(e.x, e.y, e.z);
            pd *= (float)mi.n_dist;
            const float c = pt + pd > 0.0f ? pt / (pt + pd) : 1.0f;
            const float3 d = xo - x;
            const float4 f = tsis_profile(table, info, sqrt(dot(d, d)));
            b += (1.0f - c) * phi.xyz * f.xyz / ((float)mi.n_dist * qd * tau * tau);
        }
    }
    out[j] = (float4)(b, 0.0f);
}
