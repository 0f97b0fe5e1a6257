#include "physics/split.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "util/error.h"

namespace tsis {

double importanceRadius(const DipoleChannel& d, double lowerBound) {
    TSIS_CHECK_GT(lowerBound, 0.0);
    auto importance = [&](double r) { return d.Rd(r) * 2.0 * std::numbers::pi * r; };

    // Scan outward from 0 on a geometric grid (0.1% steps from 1e-6·zr): fine at
    // the peak near r ~ zr, and it reaches a slow 1/r² tail (σa = 0) in a few
    // thousand steps. Remember the last downward crossing; stop once past the
    // maximum and far (1e-6) below both the bound and the maximum.
    const double tail = d.sigmaTr > 0.0 ? 1.0 / d.sigmaTr : 0.0;
    const double rLimit = 1e6 * std::max(d.zv, tail);
    double prevR = 0.0, prevI = 0.0;  // importance(0) = 0
    double peakR = 0.0, peakI = 0.0;
    double lo = -1.0, hi = -1.0;  // importance(lo) ≥ bound > importance(hi)
    for (double r = 1e-6 * d.zr; r < rLimit; r *= 1.001) {
        const double I = importance(r);
        if (I > peakI) {
            peakI = I;
            peakR = r;
        }
        if (prevI >= lowerBound && I < lowerBound) {
            lo = prevR;
            hi = r;
        }
        if (r > peakR && I < 1e-6 * std::min(lowerBound, peakI)) break;
        prevR = r;
        prevI = I;
    }
    if (lo < 0.0) return peakR;  // never reached the bound (to the grid's 0.1%)

    for (int k = 0; k < 200 && hi - lo > 1e-14 * hi; ++k) {
        const double mid = 0.5 * (lo + hi);
        if (importance(mid) >= lowerBound)
            lo = mid;
        else
            hi = mid;
    }
    return 0.5 * (lo + hi);
}

glm::dvec3 importanceRadius(const Dipole& d, double lowerBound) {
    return {importanceRadius(d.ch[0], lowerBound), importanceRadius(d.ch[1], lowerBound),
            importanceRadius(d.ch[2], lowerBound)};
}

double localWeight(double r, double Rp, double K) {
    // The thesis prints 1 − ½e^(−(r−Rp)K) for r ≤ Rp: a misprint (docs/design.md §3).
    // There the exponent is positive, so Wl < 0 once r < Rp − ln2/K. The sign-
    // flipped form below is the intended one: continuous (½ at Rp), monotone,
    // in [0, 1], Wl → 1 at r = 0 for K·Rp ≫ 1 as in the thesis' Fig. 3.4.
    const double e = 0.5 * std::exp(-std::abs(r - Rp) * K);
    return r <= Rp ? 1.0 - e : e;
}

glm::dvec3 localWeight(double r, const glm::dvec3& Rp, double K) {
    return {localWeight(r, Rp.x, K), localWeight(r, Rp.y, K), localWeight(r, Rp.z, K)};
}

}  // namespace tsis
