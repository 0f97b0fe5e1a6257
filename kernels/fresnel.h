/* Exact unpolarized Fresnel transmittance from air into a medium of relative
 * index eta, as host/physics/fresnel.h and gl/shaders/common.glsl have it
 * (docs/design.md §2: not Schlick). Kernels only. */
#ifndef TSIS_FRESNEL_H
#define TSIS_FRESNEL_H

#ifdef __OPENCL_VERSION__
static inline float tsis_fresnel_t(const float eta, float cos_i) {
    cos_i = clamp(cos_i, 0.0f, 1.0f);
    const float sin2_t = (1.0f - cos_i * cos_i) / (eta * eta);
    const float cos_t = sqrt(max(0.0f, 1.0f - sin2_t));
    const float rs = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    const float rp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    return 1.0f - 0.5f * (rs * rs + rp * rp);
}
#endif /* __OPENCL_VERSION__ */

#endif /* TSIS_FRESNEL_H */
