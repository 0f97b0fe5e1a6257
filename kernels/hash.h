/* Integer hashing for per-pixel sample offsets and rotations. OpenCL C only. */
#ifndef TSIS_HASH_H
#define TSIS_HASH_H

/* Wellons' lowbias32: decorrelates neighbouring pixels. */
static inline uint tsis_hash(uint x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

/* A float uniform on the unit interval (closed at 0, open at 1) from a hash: its top 24 bits. */
static inline float tsis_hash_unit(const uint h) { return (float)(h >> 8) * (1.0f / 16777216.0f); }

#endif /* TSIS_HASH_H */
