/* --method mis: parameters shared by host and kernels (kernels/mis.cl). */
#ifndef TSIS_MIS_SHARED_H
#define TSIS_MIS_SHARED_H

#ifndef __OPENCL_VERSION__
#include <cstdint>
#endif

#include "tsis_shared.h" /* TSIS_MAX_LIGHTS: the gather keeps every light's projection */

typedef struct {
    int lights;       /* light maps, back to back in the combined buffers */
    int res;          /* each map is res x res */
    int n_tex;        /* N, texture-space samples shared by all pixels */
    int n_dist;       /* distance-driven samples per pixel and light */
    int segments;     /* K: the radius sampler's equal-probability segments */
    int q_size;       /* bins of the radial density table used in the weights */
    float q_inv_step; /* q_size / r_max */
    float tex_scale;  /* N / (sum of Y over the flux atlas): N p_tex(x) = tex_scale Y(E(x)) */
    unsigned int seed;
    float pad0, pad1, pad2;
} TsisMisInfo;

TSIS_CHECK_SIZE(TsisMisInfo, 48);
TSIS_CHECK_OFFSET(TsisMisInfo, lights, 0);
TSIS_CHECK_OFFSET(TsisMisInfo, res, 4);
TSIS_CHECK_OFFSET(TsisMisInfo, n_tex, 8);
TSIS_CHECK_OFFSET(TsisMisInfo, n_dist, 12);
TSIS_CHECK_OFFSET(TsisMisInfo, segments, 16);
TSIS_CHECK_OFFSET(TsisMisInfo, q_size, 20);
TSIS_CHECK_OFFSET(TsisMisInfo, q_inv_step, 24);
TSIS_CHECK_OFFSET(TsisMisInfo, tex_scale, 28);
TSIS_CHECK_OFFSET(TsisMisInfo, seed, 32);
TSIS_CHECK_OFFSET(TsisMisInfo, pad0, 36);
TSIS_CHECK_OFFSET(TsisMisInfo, pad1, 40);
TSIS_CHECK_OFFSET(TsisMisInfo, pad2, 44);

#endif /* TSIS_MIS_SHARED_H */
