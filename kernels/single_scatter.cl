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
 * out, the volumetric truth has them. Phase p = 1/(4 pi).
 *
 * Each work item evaluates TSIS_SCATTER_LANES points side by side, one to a
 * lane of float vectors, every branch a select: PoCL runs a work group's
 * items one after another and does not vectorise this control flow itself,
 * so scalar code left the vector units idle (the views' reads are gathered
 * lane by lane). */
#include "fresnel.h"
#include "light_map.h"
#include "single_scatter_shared.h"

#define TSIS_LANE_WIDTH TSIS_SCATTER_LANES
#include "lanes.h"

typedef float8 lf; /* one value a lane */
typedef int8 li;   /* a lane mask: -1 true, 0 false */
typedef struct {
    lf x, y, z;
} l3;

static inline l3 l3_make(const lf x, const lf y, const lf z) {
    l3 r;
    r.x = x;
    r.y = y;
    r.z = z;
    return r;
}
static inline l3 l3_splat(const float3 v) {
    return l3_make((lf)(v.x), (lf)(v.y), (lf)(v.z));
}
static inline l3 l3_sub(const l3 a, const l3 b) {
    return l3_make(a.x - b.x, a.y - b.y, a.z - b.z);
}
/* a s + b */
static inline l3 l3_mad(const l3 a, const lf s, const l3 b) {
    return l3_make(mad(a.x, s, b.x), mad(a.y, s, b.y), mad(a.z, s, b.z));
}
static inline l3 l3_scale(const l3 a, const lf s) {
    return l3_make(a.x * s, a.y * s, a.z * s);
}
static inline lf l3_dot(const l3 a, const l3 b) {
    return mad(a.x, b.x, mad(a.y, b.y, a.z * b.z));
}
static inline l3 l3_cross(const l3 a, const l3 b) {
    return l3_make(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline l3 l3_normalize(const l3 a) {
    return l3_scale(a, rsqrt(l3_dot(a, a)));
}
/* m ? b : a, lane by lane */
static inline l3 l3_select(const l3 a, const l3 b, const li m) {
    return l3_make(select(a.x, b.x, m), select(a.y, b.y, m), select(a.z, b.z, m));
}

/* p[index] in each lane where ok, else `none` (named per-lane values, as
 * lanes.h builds its vectors). */
#define TSIS_SCATTER_GATHER(k) const float g##k = ok.s##k ? p[index.s##k] : none;
static inline lf tsis_gather(const __global float* p, const li index, const li ok,
                             const float none) {
    TSIS_LANES(TSIS_SCATTER_GATHER)
    return TSIS_VEC_OF(g);
}

#ifdef TSIS_SCATTER_FROM_DEPTH
/* View texel (x, y) at depth z (window, [0, 1]) back in the world. */
static inline l3 tsis_unproject(const float16 to_world, const float res, const lf x, const lf y,
                                const lf z) {
    const lf cx = (x + 0.5f) / res * 2.0f - 1.0f, cy = (y + 0.5f) / res * 2.0f - 1.0f;
    const lf cz = z * 2.0f - 1.0f;
    const lf w = to_world.s3 * cx + to_world.s7 * cy + to_world.sb * cz + to_world.sf;
    return l3_make((to_world.s0 * cx + to_world.s4 * cy + to_world.s8 * cz + to_world.sc) / w,
                   (to_world.s1 * cx + to_world.s5 * cy + to_world.s9 * cz + to_world.sd) / w,
                   (to_world.s2 * cx + to_world.s6 * cy + to_world.sa * cz + to_world.se) / w);
}

/* The step from texel (x, y) at p to its neighbour (x + dx, y + dy) or the
 * opposite one: towards the side whose depth is nearer z and holds a
 * surface. */
static inline l3 tsis_depth_tangent(const float16 to_world, const float res, const lf x, const lf y,
                                    const float dx, const float dy, const lf z, const lf zp,
                                    const lf zm, const l3 p) {
    const li plus = isless(zp, (lf)(1.0f)) &
                    (~isless(zm, (lf)(1.0f)) | islessequal(fabs(zp - z), fabs(z - zm)));
    const lf side = select((lf)(-1.0f), (lf)(1.0f), plus);
    return l3_scale(
        l3_sub(tsis_unproject(to_world, res, x + side * dx, y + side * dy, select(zm, zp, plus)),
               p),
        side);
}
#endif

/* The surface point the light sees at p's texel and its normal, in the
 * lanes it returns true (none elsewhere: no surface of medium `tag`); *clip_w:
 * p's clip w. A drawn view holds res^2 positions then res^2 normals (w the
 * medium tag, as the flux map's); one made from the shadow map
 * (TSIS_SCATTER_FROM_DEPTH, one medium) its depth only: the point
 * unprojected, the facet's normal from the neighbours' depths, one-sided
 * towards the neighbour that continues the surface (render/single_scatter.h
 * depthViewTexel, in double). */
static inline li tsis_scatter_surface(const TsisLightMapInfo* map, const __global float* view,
                                      const float16 to_world, const lf tag, const l3 p, l3* y,
                                      l3* n, lf* clip_w) {
    const float* m = map->view_proj;
    const lf cx = m[0] * p.x + m[4] * p.y + m[8] * p.z + m[12];
    const lf cy = m[1] * p.x + m[5] * p.y + m[9] * p.z + m[13];
    const lf cw = m[3] * p.x + m[7] * p.y + m[11] * p.z + m[15];
    const float res = (float)map->res;
    const lf s = 0.5f * res / cw;
    const lf fx = floor(cx * s + 0.5f * res), fy = floor(cy * s + 0.5f * res);
    const li inside = isgreaterequal(fx, (lf)(0.0f)) & isgreaterequal(fy, (lf)(0.0f)) &
                      isless(fx, (lf)(res)) & isless(fy, (lf)(res));
    const li tx = convert_int8(select((lf)(0.0f), fx, inside));
    const li ty = convert_int8(select((lf)(0.0f), fy, inside));
    const li t = ty * map->res + tx;
    *clip_w = cw;
#ifdef TSIS_SCATTER_FROM_DEPTH
    const lf z = tsis_gather(view, t, inside, 1.0f);
    const lf zxp = tsis_gather(view, t + 1, inside & (tx + 1 < map->res), 1.0f);
    const lf zxm = tsis_gather(view, t - 1, inside & (tx > 0), 1.0f);
    const lf zyp = tsis_gather(view, t + map->res, inside & (ty + 1 < map->res), 1.0f);
    const lf zym = tsis_gather(view, t - map->res, inside & (ty > 0), 1.0f);
    *y = tsis_unproject(to_world, res, fx, fy, z);
    *n = l3_normalize(
        l3_cross(tsis_depth_tangent(to_world, res, fx, fy, 1.0f, 0.0f, z, zxp, zxm, *y),
                 tsis_depth_tangent(to_world, res, fx, fy, 0.0f, 1.0f, z, zyp, zym, *y)));
    return inside & isless(z, (lf)(1.0f)) & (isless(zxp, (lf)(1.0f)) | isless(zxm, (lf)(1.0f))) &
           (isless(zyp, (lf)(1.0f)) | isless(zym, (lf)(1.0f)));
#else
    const li normals = (li)(4 * map->res * map->res);
    *y = l3_make(tsis_gather(view, 4 * t, inside, 0.0f), tsis_gather(view, 4 * t + 1, inside, 0.0f),
                 tsis_gather(view, 4 * t + 2, inside, 0.0f));
    *n = l3_normalize(l3_make(tsis_gather(view, normals + 4 * t, inside, 0.0f),
                              tsis_gather(view, normals + 4 * t + 1, inside, 0.0f),
                              tsis_gather(view, normals + 4 * t + 2, inside, 0.0f)));
    return inside & isequal(tsis_gather(view, normals + 4 * t + 3, inside, 0.0f), tag);
#endif
}

/* (1 - e^-x)/x, 1 at 0. */
static inline lf tsis_scatter_phi(const lf x) {
    return select(-expm1(-x) / x, 1.0f - 0.5f * x, isless(fabs(x), (lf)(1e-4f)));
}

/* The stratum's integral over the camera ray's depth s in [a, b] of
 * e^(-sigma_t (s + h(s)/cos_t)), one channel, h(s) = h_m - (s - s_m) c the
 * depth below the entry's tangent plane, linear in s (c = wt . n_i). Where
 * h < 0 the point is above the plane: with c > 0 the ray has crossed the
 * entry face (out of the body: nothing), with c <= 0 it is within a texel of
 * the surface it entered below (h taken as 0, as the first step does). */
static inline lf tsis_scatter_stratum(const lf sigma_t, const lf a, const lf b, const lf sm,
                                      const lf hm, const lf c, const lf cos_t) {
    /* Where h = 0 (none when the ray runs along the plane). */
    const lf sz = select((lf)(-INFINITY), sm + hm / c, isnotequal(c, (lf)(0.0f)));
    const li touch = islessequal(c, (lf)(0.0f)) & isgreater(sz, a);
    const lf z = fmin(sz, b);
    lf sum = select((lf)(0.0f), exp(-sigma_t * a) * (z - a) * tsis_scatter_phi(sigma_t * (z - a)),
                    touch);
    const lf p = select(a, z, touch);
    const lf q = select(b, fmin(b, sz), isgreater(c, (lf)(0.0f)));
    const lf hp = fmax(hm - (p - sm) * c, 0.0f);
    const lf alpha = sigma_t * (1.0f - c / cos_t);
    sum += select((lf)(0.0f),
                  exp(-sigma_t * (p + hp / cos_t)) * (q - p) * tsis_scatter_phi(alpha * (q - p)),
                  isgreater(q, p));
    return sum;
}

#define TSIS_SCATTER_LOAD(k)                               \
    const int j##k = order[min(first + 0x##k, count - 1)]; \
    const float4 q##k = points[j##k];                      \
    const float4 m##k = normals[j##k];                     \
    const TsisScatterMedium md##k = media[clamp((int)(q##k.w + 0.5f) - 1, 0, media_count - 1)];
#define TSIS_SCATTER_STORE(k)                                   \
    if (first + 0x##k < count)                                  \
        out[j##k] = (accumulate ? out[j##k] : (float4)(0.0f)) + \
                    (valid.s##k ? (float4)(r0.s##k, r1.s##k, r2.s##k, 0.0f) : (float4)(0.0f));

/* At the `count` points order[] names (the rest interpolated after:
 * render/sparse_pixels.h), TSIS_SCATTER_LANES of them a work item. */
kernel void tsis_single_scatter(const __global float4* points, const __global float4* normals,
                                const __global int* order, const int count, const float4 eye,
                                const __global TsisScatterMedium* media, const int media_count,
                                const TsisLightMapInfo map, const TsisScatterLight light,
                                const __global float* view, const float16 to_world,
                                const int strata, const int accumulate, __global float4* out) {
    const int first = (int)get_global_id(0) * TSIS_SCATTER_LANES;
    if (first >= count) return;
    /* The lanes' points, normals and media (a lane past the end repeats the
     * last point, unwritten). */
    TSIS_LANES(TSIS_SCATTER_LOAD)
    const lf tag = TSIS_VEC(q, w);
    const li medium = convert_int8(tag + 0.5f) - 1;
    const li valid = (medium >= 0) & (medium < media_count);
    const l3 xo = l3_make(TSIS_VEC(q, x), TSIS_VEC(q, y), TSIS_VEC(q, z));
    l3 n = l3_normalize(l3_make(TSIS_VEC(m, x), TSIS_VEC(m, y), TSIS_VEC(m, z)));
    const l3 v = l3_normalize(l3_sub(l3_splat(eye.xyz), xo));
    lf cos_o = l3_dot(n, v);
    /* As the composite: the side that faces the eye. */
    n = l3_select(n, l3_scale(n, (lf)(-1.0f)), isless(cos_o, (lf)(0.0f)));
    cos_o = fabs(cos_o);
    const lf eta = TSIS_VEC(md, eta);
    const lf inv_eta = 1.0f / eta;
    const lf cos_to = sqrt(fmax(1.0f - inv_eta * inv_eta * (1.0f - cos_o * cos_o), 0.0f));
    /* The camera ray refracted into the medium. */
    const l3 wt = l3_normalize(l3_mad(n, inv_eta * cos_o - cos_to, l3_scale(v, -inv_eta)));
    const lf sigma_t[3] = {TSIS_VEC(md, st_r), TSIS_VEC(md, st_g), TSIS_VEC(md, st_b)};
    const lf sigma = fmin(sigma_t[0], fmin(sigma_t[1], sigma_t[2]));
    const float3 light_vec = (float3)(light.x, light.y, light.z);
    const float3 e_light = (float3)(light.r, light.g, light.b);
    const l3 light_at = l3_splat(light_vec);
    const l3 light_dir = l3_splat(-normalize(light_vec)); /* directional: towards it */
    /* The depth's range within TSIS_SCATTER_DEPTH mean free paths. */
    const float kept = 1.0f - exp(-(float)TSIS_SCATTER_DEPTH);
    lf sum[3] = {(lf)(0.0f), (lf)(0.0f), (lf)(0.0f)};
    lf a = (lf)(0.0f);
    for (int k = 0; k < strata; ++k) {
        /* The stratum [a, b] (equal mass of sigma e^(-sigma s)) and its
         * middle, where its entry plane is found. */
        const lf b = -log(1.0f - (float)(k + 1) / (float)strata * kept) / sigma;
        const lf sm = -log(1.0f - ((float)k + 0.5f) / (float)strata * kept) / sigma;
        const lf a_k = a;
        a = b;
        const l3 x = l3_mad(wt, sm, xo);
        l3 y, ny;
        lf clip_w;
        li live = valid & tsis_scatter_surface(&map, view, to_world, tag, x, &y, &ny, &clip_w);
        /* x in front of the light's first surface: outside the object. */
        const l3 toward = light.type == 0 ? l3_normalize(l3_sub(light_at, x)) : light_dir;
        live &= ~isless(l3_dot(l3_sub(y, x), toward), -map.tau_per_w * clip_w);
        if (!any(live)) continue;
        /* The entry whose refracted ray reaches x: on y's tangent plane in
         * closed form, then the surface the light sees there, again. The
         * lanes still stepping are `stepping`; each keeps the values of the
         * step it stopped at. */
        li stepping = live;
        lf cos_i = (lf)(0.0f), cos_t = (lf)(1.0f), h2 = (lf)(0.0f), e_scale = (lf)(1.0f);
        l3 n_i = ny;
        for (int it = 0;; ++it) {
            lf e_it = (lf)(1.0f);
            l3 l = light_dir;
            if (light.type == 0) {
                const l3 d = l3_sub(light_at, y);
                const lf d2 = l3_dot(d, d);
                e_it = 1.0f / d2;
                l = l3_scale(d, rsqrt(d2));
            }
            const lf ci = l3_dot(ny, l);
            const lf ct = sqrt(fmax(1.0f - inv_eta * inv_eta * (1.0f - ci * ci), 0.0f));
            const lf hh = l3_dot(l3_sub(y, x), ny);
            cos_i = select(cos_i, ci, stepping);
            cos_t = select(cos_t, ct, stepping);
            h2 = select(h2, hh, stepping);
            e_scale = select(e_scale, e_it, stepping);
            n_i = l3_select(n_i, ny, stepping);
            /* x above a later step's tangent plane: no connection (at the
             * first, x within a texel of the surface: none to cross). */
            const li above = stepping & ~isgreater(hh, (lf)(0.0f));
            if (it > 0) cos_i = select(cos_i, (lf)(0.0f), above);
            h2 = select(h2, (lf)(0.0f), above);
            stepping &= ~above & isgreater(ci, (lf)(0.0f));
            if (it == TSIS_SCATTER_ENTRY_STEPS || !any(stepping)) break;
            const l3 refracted = l3_mad(ny, inv_eta * ci - ct, l3_scale(l, -inv_eta));
            l3 y2, n2;
            lf w2;
            /* Past what the light sees: the entry would be at grazing
             * incidence, where Ft cos theta_i -> 0. */
            const li seen = tsis_scatter_surface(&map, view, to_world, tag,
                                                 l3_mad(refracted, -hh / ct, x), &y2, &n2, &w2);
            cos_i = select(cos_i, (lf)(0.0f), stepping & ~seen);
            stepping &= seen;
            y = l3_select(y, y2, stepping);
            ny = l3_select(ny, n2, stepping);
        }
        live &= isgreater(cos_i, (lf)(0.0f));
        const lf c = l3_dot(wt, n_i);
        const lf gain = tsis_fresnel_t8(eta, cos_i) * cos_i / cos_t * e_scale;
        const float e_rgb[3] = {e_light.x, e_light.y, e_light.z};
        for (int ch = 0; ch < 3; ++ch)
            sum[ch] += select(
                (lf)(0.0f),
                tsis_scatter_stratum(sigma_t[ch], a_k, b, sm, h2, c, cos_t) * gain * e_rgb[ch],
                live);
    }
    const lf scale = inv_eta * inv_eta / (4.0f * M_PI_F) * TSIS_VEC(md, to_radiosity);
    const lf r0 = sum[0] * TSIS_VEC(md, ss_r) * scale;
    const lf r1 = sum[1] * TSIS_VEC(md, ss_g) * scale;
    const lf r2 = sum[2] * TSIS_VEC(md, ss_b) * scale;
    TSIS_LANES(TSIS_SCATTER_STORE)
}
