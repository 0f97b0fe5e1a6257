/* Importance sampling of the flux atlas by descending the luminance sum
 * pyramid (thesis Algorithm 3.1 as corrected in docs/design.md §3). */
#include "tsis_shared.h"

/* Sample i takes u_i = frac((i + xi) / n): a shifted regular grid, so the N
 * samples stratify the CDF (low discrepancy) while xi (0 <= xi < 1) randomises it.
 * Texel i is drawn with p_i = Y_i / sum Y; the sample's weight is
 * w_c = Phi_i(c) / (n p_i) = Phi_i(c) sum Y / (n Y_i). */
kernel void tsis_draw(const __global float* pyramid, const __global float4* flux,
                      const __global float4* position, const int levels, const int n,
                      const float xi, __global TsisSample* samples) {
    const int i = get_global_id(0);
    if (i >= n) return;

    /* The 1-texel top level starts at sum_{k<levels} (res >> k)^2. */
    int offset = 0;
    for (int k = 0; k < levels; ++k) offset += 1 << (2 * (levels - k));
    const float total = pyramid[offset];

    /* (i + xi) / n < 1 exactly, but may round up to 1 in float. */
    const float u = fmin(((float)i + xi) / (float)n, 0x1.fffffep-1f);
    float mass = u * total;

    int x = 0;
    int y = 0;
    for (int k = levels - 1; k >= 0; --k) {
        const int w = 1 << (levels - k); /* width of level k */
        offset -= w * w;
        const __global float* lev = pyramid + offset;
        const int cx = 2 * x;
        const int cy = 2 * y;
        const float s[4] = {lev[cy * w + cx], lev[cy * w + cx + 1], lev[(cy + 1) * w + cx],
                            lev[(cy + 1) * w + cx + 1]};
        /* Walk the children in a fixed order, subtracting their mass until the
         * remainder falls inside one. mass >= 0 throughout, so "mass < s" never
         * picks a zero-mass child. */
        int pick = -1;
        for (int c = 0; c < 4; ++c) {
            if (mass < s[c]) {
                pick = c;
                break;
            }
            mass -= s[c];
        }
        if (pick < 0) {
            /* Round-off: the parent's float sum exceeded its children's. Take
             * the last child with mass (none when the whole atlas is dark). */
            pick = 0;
            for (int c = 3; c >= 0; --c) {
                if (s[c] > 0.0f) {
                    pick = c;
                    break;
                }
            }
        }
        x = cx + (pick & 1);
        y = cy + (pick >> 1);
    }

    const int res = 1 << levels;
    const int texel = y * res + x;
    const float yi = pyramid[texel];
    const float4 phi = flux[texel];
    const float4 p = position[texel];
    const float scale = (total > 0.0f && yi > 0.0f) ? total / ((float)n * yi) : 0.0f;
    TsisSample out;
    out.px = p.x;
    out.py = p.y;
    out.pz = p.z;
    out.texel = (float)texel;
    out.wr = phi.x * scale;
    out.wg = phi.y * scale;
    out.wb = phi.z * scale;
    out.medium = p.w;
    samples[i] = out;
}
