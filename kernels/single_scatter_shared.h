/* Jensen et al. 2001's single-scattering term L(1) (kernels/single_scatter.cl,
 * render/single_scatter.h): what the kernel reads of each medium and light.
 * Shared by host and kernel. */
#ifndef TSIS_SINGLE_SCATTER_SHARED_H
#define TSIS_SINGLE_SCATTER_SHARED_H

#include "tsis_shared.h" /* TSIS_CHECK_SIZE, TSIS_CHECK_OFFSET */

/* Steps towards the entry point whose refracted ray reaches the sample, from
 * Jensen's (the straight line to the light), which is exact on a plane; on a
 * curved surface near the shadow line it puts the entry too close, and the
 * term overshoots the volumetric walk's single scattering 1.4x at
 * cos theta_i = 0.1 and 4-7x at 0 (30 mm skin1 sphere). Two steps: 0.89-0.98
 * at 0.1, below the walk at 0 (single_scatter_test.cpp); three: the same;
 * each costs two more map reads per stratum. */
#define TSIS_SCATTER_ENTRY_STEPS 2

/* Points a work item of tsis_single_scatter evaluates side by side, one to a
 * lane of float8s. */
#define TSIS_SCATTER_LANES 8

/* The camera ray's depth ends this many mean free paths 1/min sigma_t' in:
 * past it the camera's own attenuation leaves < e^-8 = 0.03% of what any
 * depth can add (the back of a back-lit 30 mm sphere, 23 mean free paths in,
 * is left out). */
#define TSIS_SCATTER_DEPTH 8

/* A medium: reduced scattering and extinction (mm^-1, rgb), its relative
 * index, and the factor from L(1)/Ft(eta, cos theta_o) to the radiosity the
 * composite turns back into it: pi / (the exit term's scale over Ft/pi). */
typedef struct {
    float ss_r, ss_g, ss_b; /* sigma_s' */
    float eta;
    float st_r, st_g, st_b; /* sigma_t' = sigma_s' + sigma_a */
    float to_radiosity;
} TsisScatterMedium;
TSIS_CHECK_SIZE(TsisScatterMedium, 32);
TSIS_CHECK_OFFSET(TsisScatterMedium, ss_r, 0);
TSIS_CHECK_OFFSET(TsisScatterMedium, eta, 12);
TSIS_CHECK_OFFSET(TsisScatterMedium, st_r, 16);
TSIS_CHECK_OFFSET(TsisScatterMedium, to_radiosity, 28);

/* A light: type 0 = point (x, y, z its position, rgb its intensity W/sr),
 * 1 = directional (x, y, z its direction of travel, rgb the irradiance
 * normal to it, W/mm^2). */
typedef struct {
    float x, y, z;
    int type;
    float r, g, b;
    float pad;
} TsisScatterLight;
TSIS_CHECK_SIZE(TsisScatterLight, 32);
TSIS_CHECK_OFFSET(TsisScatterLight, x, 0);
TSIS_CHECK_OFFSET(TsisScatterLight, type, 12);
TSIS_CHECK_OFFSET(TsisScatterLight, r, 16);
TSIS_CHECK_OFFSET(TsisScatterLight, pad, 28);

#endif /* TSIS_SINGLE_SCATTER_SHARED_H */
