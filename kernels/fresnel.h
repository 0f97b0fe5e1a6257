/* Exact unpolarized Fresnel transmittance from air into a medium of relative
 * index eta, as host/physics/fresnel.h and gl/shaders/common.glsl have it
 * (docs/design.md §2: not Schlick). Kernels only. */
#ifndef TSIS_FRESNEL_H
#define TSIS_FRESNEL_H

#ifdef __OPENCL_VERSION__
/* One lane (float) or eight side by side (float8: kernels/single_scatter.cl). */
#define TSIS_DEFINE_FRESNEL_T(name, T)                              \
    static inline T name(const T eta, T cos_i) {                    \
        cos_i = clamp(cos_i, 0.0f, 1.0f);                           \
        const T sin2_t = (1.0f - cos_i * cos_i) / (eta * eta);      \
        const T cos_t = sqrt(fmax(1.0f - sin2_t, 0.0f));            \
        const T rs = (cos_i - eta * cos_t) / (cos_i + eta * cos_t); \
        const T rp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t); \
        return 1.0f - 0.5f * (rs * rs + rp * rp);                   \
    }
TSIS_DEFINE_FRESNEL_T(tsis_fresnel_t, float)
TSIS_DEFINE_FRESNEL_T(tsis_fresnel_t8, float8)
#endif /* __OPENCL_VERSION__ */

#endif /* TSIS_FRESNEL_H */
