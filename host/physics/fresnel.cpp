#include "physics/fresnel.h"

#include <algorithm>
#include <cmath>

namespace tsis {

double fresnelReflectance(double eta, double cosTheta) {
    const double ci = std::clamp(cosTheta, 0.0, 1.0);
    // Snell: sinθt = sinθi / η. Air into a denser medium never totally reflects,
    // but answer 1 for η < 1 anyway rather than take sqrt of a negative.
    const double sin2t = (1.0 - ci * ci) / (eta * eta);
    if (sin2t >= 1.0) return 1.0;
    const double ct = std::sqrt(1.0 - sin2t);
    const double rs = (ci - eta * ct) / (ci + eta * ct);  // s-polarised amplitude
    const double rp = (eta * ci - ct) / (eta * ci + ct);  // p-polarised amplitude
    return 0.5 * (rs * rs + rp * rp);
}

}  // namespace tsis
