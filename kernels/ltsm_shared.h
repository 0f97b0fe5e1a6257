/* The ltsm filter pattern (thesis 3.3.2), shared by host and kernel: L rings of
 * C samples plus the centre, as offsets on the plane through xo perpendicular
 * to the light's axis, each with the per-channel area that makes the filter
 * exact for a flat, uniformly lit plane (host/render/ring_pattern.h). */
#ifndef TSIS_LTSM_SHARED_H
#define TSIS_LTSM_SHARED_H

#include "tsis_shared.h" /* TSIS_CHECK_SIZE, TSIS_CHECK_OFFSET */

typedef struct {
    float dx, dy; /* offset on the plane (mm) */
    float r;      /* its length (mm) */
    float pad0;
    /* A'_c = (integral of f_c over the sample's ring sector) / f_c(r) (mm^2):
     * B_c += flux density * A'_c * f_c(|xo - x_i|). */
    float ar, ag, ab;
    float pad1;
} TsisRingSample;

TSIS_CHECK_SIZE(TsisRingSample, 32);
TSIS_CHECK_OFFSET(TsisRingSample, dx, 0);
TSIS_CHECK_OFFSET(TsisRingSample, dy, 4);
TSIS_CHECK_OFFSET(TsisRingSample, r, 8);
TSIS_CHECK_OFFSET(TsisRingSample, pad0, 12);
TSIS_CHECK_OFFSET(TsisRingSample, ar, 16);
TSIS_CHECK_OFFSET(TsisRingSample, ag, 20);
TSIS_CHECK_OFFSET(TsisRingSample, ab, 24);
TSIS_CHECK_OFFSET(TsisRingSample, pad1, 28);

#endif /* TSIS_LTSM_SHARED_H */
