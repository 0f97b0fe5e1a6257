#include "render/radial_importance.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "util/error.h"

namespace tsis {

RadialImportance::RadialImportance(const RadialProfile& f, double rMax, int cells) {
    TSIS_CHECK(std::isfinite(rMax) && rMax > 0.0);
    TSIS_CHECK_GE(cells, 1);
    // r = rMax·s²: cells shrink quadratically towards 0, where Rd varies on the
    // scale of zr, far below rMax at large sizes.
    r_.resize(static_cast<size_t>(cells) + 1);
    for (int k = 0; k <= cells; ++k) {
        const double s = static_cast<double>(k) / cells;
        r_[static_cast<size_t>(k)] = rMax * s * s;
    }
    r_.back() = rMax;
    auto g = [&f](double r) { return f(r) * (2.0 * std::numbers::pi * r); };
    cum_.assign(r_.size(), glm::dvec3(0.0));
    glm::dvec3 ga = g(0.0);
    for (size_t k = 1; k < r_.size(); ++k) {
        const double a = r_[k - 1], b = r_[k];
        const glm::dvec3 gb = g(b);
        cum_[k] = cum_[k - 1] + (b - a) / 6.0 * (ga + 4.0 * g(0.5 * (a + b)) + gb);
        ga = gb;
    }
    const glm::dvec3 total = cum_.back();
    int channels = 0;
    for (int c = 0; c < 3; ++c) channels += total[c] > 0.0;
    mix_.assign(r_.size(), 0.0);
    for (size_t k = 0; k < r_.size(); ++k) {
        double m = 0.0;
        for (int c = 0; c < 3; ++c)
            if (total[c] > 0.0) m += cum_[k][c] / total[c];
        mix_[k] = channels ? m / channels : static_cast<double>(k) / cells;
    }
    mix_.back() = 1.0;
}

glm::dvec3 RadialImportance::mass(double r) const {
    if (r <= 0.0) return glm::dvec3(0.0);
    if (r >= rMax()) return mass();
    const size_t k = static_cast<size_t>(std::upper_bound(r_.begin(), r_.end(), r) - r_.begin());
    const double t = (r - r_[k - 1]) / (r_[k] - r_[k - 1]);
    return cum_[k - 1] + t * (cum_[k] - cum_[k - 1]);
}

double RadialImportance::cdf(double r) const {
    if (r <= 0.0) return 0.0;
    if (r >= rMax()) return 1.0;
    const size_t k = static_cast<size_t>(std::upper_bound(r_.begin(), r_.end(), r) - r_.begin());
    const double t = (r - r_[k - 1]) / (r_[k] - r_[k - 1]);
    return mix_[k - 1] + t * (mix_[k] - mix_[k - 1]);
}

std::vector<float> RadialImportance::inverseTable(int entries) const {
    TSIS_CHECK_GE(entries, 1);
    std::vector<float> radii(static_cast<size_t>(entries) + 1);
    for (int k = 0; k <= entries; ++k)
        radii[static_cast<size_t>(k)] =
            static_cast<float>(inverse(static_cast<double>(k) / entries));
    return radii;
}

double RadialImportance::inverse(double u) const {
    if (u <= 0.0) return 0.0;
    if (u >= 1.0) return rMax();
    // First edge whose cdf reaches u; the cell before it holds u.
    const size_t k =
        static_cast<size_t>(std::lower_bound(mix_.begin(), mix_.end(), u) - mix_.begin());
    if (k == 0) return 0.0;
    const double span = mix_[k] - mix_[k - 1];
    const double t = span > 0.0 ? (u - mix_[k - 1]) / span : 0.0;
    return r_[k - 1] + t * (r_[k] - r_[k - 1]);
}

}  // namespace tsis
