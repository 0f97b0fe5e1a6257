/* The pyramid's interpolated pixels (render/sparse_pixels.h): B at each from
 * its cell's four corners, bilinearly, in place. One launch a level of the
 * list, [first, end): its corners are evaluated or of a level before, so no
 * item reads what another of its launch writes. The sum in the host's order
 * without contraction, so the device gives the host reference's bits
 * (interpolateSparsePixels). */
#include "tsis_shared.h"

#pragma OPENCL FP_CONTRACT OFF

kernel void tsis_interpolate_sparse(const __global TsisInterpolatedPixel* pixels, const int first,
                                    const int end, __global float4* rgba) {
    const int i = first + get_global_id(0);
    if (i >= end) return;
    const TsisInterpolatedPixel p = pixels[i];
    float4 v = (float4)(0.0f);
    for (int j = 0; j < 4; ++j) v += p.weights[j] * rgba[p.corners[j]];
    rgba[p.point] = v;
}
