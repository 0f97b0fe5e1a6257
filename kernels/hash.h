/* Integer hashing for per-pixel sample offsets and rotations. Shared by the
 * kernels and the host (the kernel tests' reference sums). */
#ifndef TSIS_HASH_H
#define TSIS_HASH_H

#include "tsis_shared.h" /* tsis_uint */

/* Wellons' lowbias32: decorrelates neighbouring pixels. */
static inline tsis_uint tsis_hash(tsis_uint x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

/* A float uniform on the unit interval (closed at 0, open at 1) from a hash:
 * its top 24 bits (exact in float). */
static inline float tsis_hash_unit(const tsis_uint h) {
    return (float)(h >> 8) * (1.0f / 16777216.0f);
}

#endif /* TSIS_HASH_H */
