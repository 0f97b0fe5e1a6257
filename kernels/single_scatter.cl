/* Jensen et al. 2001's single-scattering term L(1) (docs/design.md "Single
 * scattering"), per covered camera point xo and one light, as the radiosity
 * the composite turns back into it: B1(xo) = to_radiosity * R,
 * L(1) = Ft(eta, cos theta_o) * R,
 *   R = sigma_s' p / eta^2 * integral ds_o Ft(eta, cos theta_i) E
 *         (cos theta_i / cos theta_ti) exp(-sigma_t' (s_i' + s_o)).
 * s_o along the refracted camera ray, integrated in closed form over K
 * strata of equal mass of sigma e^(-sigma s_o) up to TSIS_SCATTER_DEPTH /
 * sigma (sigma the smallest channel's sigma_t'), each with the entry plane
 * found at its middle: along it the depth below that plane is linear in s_o,
 * so the stratum's integral of e^(-sigma_t' (s_o + s_i')) is exact on a
 * plane and needs no draws (no noise; K = 1 is the plane's closed form).
 * The entry: first the light view's surface at the middle's texel (Jensen's xi), then
 * TSIS_SCATTER_ENTRY_STEPS times the point of that surface point's tangent
 * plane whose refracted ray reaches x, moved onto the surface the light sees
 * there; s_i' = (depth below the tangent plane) / cos theta_ti, the refracted
 * path. E (cos theta_i / cos theta_ti) is the beam's irradiance inside and
 * 1/eta^2 the radiance's change leaving the medium: Jensen 2001 leaves both
 * out, the volumetric truth has them. Phase p = 1/(4 pi). */
#include "fresnel.h"
#include "light_map.h"
#include "single_scatter_shared.h"

#ifdef TSIS_SCATTER_FROM_DEPTH
/* View texel (x, y) at depth z (window, [0, 1]) back in the world. */
static inline float3 tsis_unproject(const float16 to_world, const int res, const float x,
                                    const float y, const float z) {
    const float4 c = (float4)((x + 0.5f) / (float)res * 2.0f - 1.0f,
                              (y + 0.5f) / (float)res * 2.0f - 1.0f, z * 2.0f - 1.0f, 1.0f);
    const float4 w =
        to_world.s0123 * c.x + to_world.s4567 * c.y + to_world.s89ab * c.z + to_world.scdef;
    return w.xyz / w.w;
}

/* The step from texel (x, y) at p to its neighbour d (one of the axes) or
 * -d: towards the side whose depth is nearer z and holds a surface. */
static inline float3 tsis_depth_tangent(const float16 to_world, const int res, const float x,
                                        const float y, const float2 d, const float z,
                                        const float zp, const float zm, const float3 p) {
    const float side = zp < 1.0f && (!(zm < 1.0f) || fabs(zp - z) <= fabs(z - zm)) ? 1.0f : -1.0f;
    return side *
           (tsis_unproject(to_world, res, x + side * d.x, y + side * d.y, side > 0.0f ? zp : zm) -
            p);
}
#endif

/* The surface point the light sees at p's texel and its normal (false: no
 * surface of medium `tag` there); *clip_w: p's clip w. A drawn view holds
 * res^2 positions then res^2 normals (w the medium tag, as the flux map's);
 * one made from the shadow map (TSIS_SCATTER_FROM_DEPTH, one medium) its
 * depth only: the point unprojected, the facet's normal from the
 * neighbours' depths, one-sided towards the neighbour that continues the
 * surface (render/single_scatter.h depthViewTexel, in double). */
static inline bool tsis_scatter_surface(const TsisLightMapInfo* map, const __global float* view,
                                        const float16 to_world, const float tag, const float3 p,
                                        float3* y, float3* n, float* clip_w) {
    const float3 q = tsis_light_project(map, p);
    const int t = tsis_light_texel(map, q.x, q.y);
    if (t < 0) return false;
    *clip_w = q.z;
#ifdef TSIS_SCATTER_FROM_DEPTH
    const int res = map->res;
    const int tx = t % res, ty = t / res;
    const float z = view[t];
    const float zxp = tx + 1 < res ? view[t + 1] : 1.0f, zxm = tx > 0 ? view[t - 1] : 1.0f;
    const float zyp = ty + 1 < res ? view[t + res] : 1.0f, zym = ty > 0 ? view[t - res] : 1.0f;
    if (!(z < 1.0f && (zxp < 1.0f || zxm < 1.0f) && (zyp < 1.0f || zym < 1.0f))) return false;
    const float fx = (float)tx, fy = (float)ty;
    *y = tsis_unproject(to_world, res, fx, fy, z);
    *n = normalize(
        cross(tsis_depth_tangent(to_world, res, fx, fy, (float2)(1.0f, 0.0f), z, zxp, zxm, *y),
              tsis_depth_tangent(to_world, res, fx, fy, (float2)(0.0f, 1.0f), z, zyp, zym, *y)));
    return true;
#else
    const float4 nt = vload4(map->res * map->res + t, view);
    if (nt.w != tag) return false;
    *y = vload4(t, view).xyz;
    *n = normalize(nt.xyz);
    return true;
#endif
}

/* (1 - e^-x)/x, 1 at 0. */
static inline float3 tsis_scatter_phi(const float3 x) {
    return select(-expm1(-x) / x, 1.0f - 0.5f * x, isless(fabs(x), (float3)(1e-4f)));
}

/* The stratum's integral over the camera ray's depth s in [a, b] of
 * e^(-sigma_t (s + h(s)/cos_t)), h(s) = h_m - (s - s_m) c the depth below
 * the entry's tangent plane, linear in s (c = wt . n_i). Where h < 0 the
 * point is above the plane: with c > 0 the ray has crossed the entry face
 * (out of the body: nothing), with c <= 0 it is within a texel of the
 * surface it entered below (h taken as 0, as the first step does). */
static inline float3 tsis_scatter_stratum(const float3 sigma_t, const float a, const float b,
                                          const float sm, const float hm, const float c,
                                          const float cos_t) {
    /* Where h = 0 (none when the ray runs along the plane). */
    const float sz = c != 0.0f ? sm + hm / c : -INFINITY;
    float3 sum = (float3)(0.0f);
    float p = a, q = b;
    if (c <= 0.0f && sz > a) {
        const float z = fmin(sz, b);
        sum += exp(-sigma_t * a) * (z - a) * tsis_scatter_phi(sigma_t * (z - a));
        p = z;
    }
    if (c > 0.0f) q = fmin(b, sz);
    if (q > p) {
        const float hp = fmax(0.0f, hm - (p - sm) * c);
        const float3 alpha = sigma_t * (1.0f - c / cos_t);
        sum += exp(-sigma_t * (p + hp / cos_t)) * (q - p) * tsis_scatter_phi(alpha * (q - p));
    }
    return sum;
}

/* At the `count` points order[] names (the rest interpolated after:
 * render/sparse_pixels.h). */
kernel void tsis_single_scatter(const __global float4* points, const __global float4* normals,
                                const __global int* order, const int count, const float4 eye,
                                const __global TsisScatterMedium* media, const int media_count,
                                const TsisLightMapInfo map, const TsisScatterLight light,
                                const __global float* view, const float16 to_world,
                                const int strata, const int accumulate, __global float4* out) {
    const int i = get_global_id(0);
    if (i >= count) return;
    const int j = order[i];
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
    /* The depth's range within TSIS_SCATTER_DEPTH mean free paths. */
    const float kept = 1.0f - exp(-(float)TSIS_SCATTER_DEPTH);
    float3 sum = (float3)(0.0f);
    float a = 0.0f;
    for (int k = 0; k < strata; ++k) {
        /* The stratum [a, b] (equal mass of sigma e^(-sigma s)) and its
         * middle, where its entry plane is found. */
        const float b = -log(1.0f - (float)(k + 1) / (float)strata * kept) / sigma;
        const float sm = -log(1.0f - ((float)k + 0.5f) / (float)strata * kept) / sigma;
        const float a_k = a;
        a = b;
        const float3 x = xo + sm * wt;
        float3 y, ny;
        float clip_w;
        if (!tsis_scatter_surface(&map, view, to_world, tag, x, &y, &ny, &clip_w)) continue;
        /* x in front of the light's first surface: outside the object. */
        const float3 toward = light.type == 0 ? normalize(light_vec - x) : -normalize(light_vec);
        if (dot(y - x, toward) < -map.tau_per_w * clip_w) continue;
        /* The entry whose refracted ray reaches x: on y's tangent plane in
         * closed form, then the surface the light sees there, again. */
        float3 e, l;
        float cos_i = 0.0f, cos_t = 1.0f, h2 = 0.0f;
        for (int it = 0;; ++it) {
            e = e_light;
            if (light.type == 0) {
                const float3 d = light_vec - y;
                const float d2 = dot(d, d);
                e /= d2;
                l = d * rsqrt(d2);
            } else {
                l = -normalize(light_vec);
            }
            cos_i = dot(ny, l);
            cos_t = sqrt(max(0.0f, 1.0f - inv_eta * inv_eta * (1.0f - cos_i * cos_i)));
            h2 = dot(y - x, ny);
            /* x above a later step's tangent plane: no connection (at the
             * first, x within a texel of the surface: none to cross). */
            if (!(h2 > 0.0f)) {
                if (it > 0) cos_i = 0.0f;
                h2 = 0.0f;
                break;
            }
            if (!(cos_i > 0.0f) || it == TSIS_SCATTER_ENTRY_STEPS) break;
            const float3 refracted = -l * inv_eta + ny * (inv_eta * cos_i - cos_t);
            /* Past what the light sees: the entry would be at grazing
             * incidence, where Ft cos theta_i -> 0. */
            if (!tsis_scatter_surface(&map, view, to_world, tag, x - refracted * (h2 / cos_t), &y,
                                      &ny, &clip_w)) {
                cos_i = 0.0f;
                break;
            }
        }
        if (!(cos_i > 0.0f)) continue;
        const float3 w = tsis_scatter_stratum(sigma_t, a_k, b, sm, h2, dot(wt, ny), cos_t);
        sum += w * (tsis_fresnel_t(md.eta, cos_i) * cos_i / cos_t) * e;
    }
    const float3 r = sum * sigma_s * (inv_eta * inv_eta / (4.0f * M_PI_F));
    out[j] = base + (float4)(md.to_radiosity * r, 0.0f);
}
