/* The pyramid's interpolated pixels (render/sparse_pixels.h): B at each from
 * its grid cell's four evaluated corners, bilinearly, in place. Corners are
 * grid points, never interpolated themselves, so no item reads what another
 * writes. The sum in the host's order without contraction, so the device
 * gives the host reference's bits (interpolateSparsePixels). */
#include "tsis_shared.h"

#pragma OPENCL FP_CONTRACT OFF

kernel void tsis_interpolate_sparse(const __global TsisInterpolatedPixel* pixels, const int count,
                                    __global float4* rgba) {
    const int i = get_global_id(0);
    if (i >= count) return;
    const TsisInterpolatedPixel p = pixels[i];
    float4 v = (float4)(0.0f);
    for (int j = 0; j < 4; ++j) v += p.weights[j] * rgba[p.corners[j]];
    rgba[p.point] = v;
}
