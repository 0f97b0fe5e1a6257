/* The ltsm filter pattern (thesis 3.3.2), shared by host and kernel: L rings of
 * C samples plus the centre, as offsets on the plane through xo perpendicular
 * to the light's axis, each with the per-channel area that makes the filter
 * exact for a flat, uniformly lit plane (host/render/ring_pattern.h). */
#ifndef TSIS_LTSM_SHARED_H
#define TSIS_LTSM_SHARED_H

typedef struct {
    float dx, dy; /* offset on the plane (mm) */
    float r;      /* its length (mm) */
    float pad0;
    /* A'_c = (integral of f_c over the sample's ring sector) / f_c(r) (mm^2):
     * B_c += flux density * A'_c * f_c(|xo - x_i|). */
    float ar, ag, ab;
    float pad1;
} TsisRingSample;

#endif /* TSIS_LTSM_SHARED_H */
