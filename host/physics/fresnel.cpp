#include "physics/fresnel.h"

#include <algorithm>
#include <cmath>

namespace tsis {

double fresnelReflectance(double eta, double cosTheta) {
    const double ci = std::clamp(cosTheta, 0.0, 1.0);
    // Snell: sinθt = sinθi / η. Air into a denser medium never totally
    // reflects; η < 1 (from inside) does past the critical angle.
    const double sin2t = (1.0 - ci * ci) / (eta * eta);
    if (sin2t >= 1.0) return 1.0;
    const double ct = std::sqrt(1.0 - sin2t);
    const double rs = (ci - eta * ct) / (ci + eta * ct);  // s-polarised amplitude
    const double rp = (eta * ci - ct) / (eta * ci + ct);  // p-polarised amplitude
    return 0.5 * (rs * rs + rp * rp);
}

double fresnelMoment(double eta, int i) {
    // Simpson in μ; Fr has a kink at the critical angle (η < 1), so many nodes.
    const int n = 4000;
    double s = 0;
    for (int k = 0; k <= n; ++k) {
        const double mu = static_cast<double>(k) / n;
        const double w = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0);
        double mui = 1.0;
        for (int j = 0; j < i; ++j) mui *= mu;
        s += w * fresnelReflectance(eta, mu) * mui;
    }
    return s / (3.0 * n);
}

double normalizedExitScale(double eta) {
    return 1.0 / (1.0 - 2.0 * fresnelMoment(eta, 1));
}

}  // namespace tsis
