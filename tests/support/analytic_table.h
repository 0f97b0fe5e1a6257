// A profile table filled directly (no physics), and its interpolation in
// double, for kernel tests that check a device sum against the host.
#pragma once

#include <cmath>

#include "physics/profile_table.h"

namespace tsis::test {

// f_c(r) = (1 − r/rMax)²·e^(−s_c r), s = (0.5, 1, 2): smooth and 0 at rMax, so
// float and double agree near the cut-off too.
inline ProfileTable analyticTable(double rMax) {
    const double s[3] = {0.5, 1.0, 2.0};
    ProfileTable t;
    t.info.r_max = float(rMax);
    t.info.inv_step = float((TSIS_TABLE_SIZE - 1) / rMax);
    t.info.size = TSIS_TABLE_SIZE;
    t.rgba.resize(4 * TSIS_TABLE_SIZE);
    for (int k = 0; k < TSIS_TABLE_SIZE; ++k) {
        const double r = k * rMax / (TSIS_TABLE_SIZE - 1);
        for (int c = 0; c < 3; ++c)
            t.rgba[4 * k + c] = float((1 - r / rMax) * (1 - r / rMax) * std::exp(-s[c] * r));
    }
    return t;
}

// The table's interpolation in double (kernels/profile.h semantics).
inline double lookup(const ProfileTable& t, double r, int c) {
    const double x = r * t.info.inv_step;
    if (!(x < t.info.size - 1)) return 0.0;
    const int i = int(x);
    const double a = t.rgba[4 * i + c];
    const double b = t.rgba[4 * i + 4 + c];
    return a + (x - i) * (b - a);
}

}  // namespace tsis::test
