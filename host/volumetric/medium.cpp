#include "volumetric/medium.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tsis {

Medium::Medium(const Material& m)
    : sigmaS(m.sigmaSPrime), sigmaA(m.sigmaA), sigmaT(m.sigmaSPrime + m.sigmaA), eta(m.eta) {}

SpectralWeight::SpectralWeight(Rng& rng)
    : hero_(std::min(2, static_cast<int>(rng.uniform() * 3))) {}

void SpectralWeight::sampled(const glm::dvec3& f, const glm::dvec3& pdf) {
    const double ph = pdf[hero_];
    beta_ *= f / ph;
    ratio_ *= pdf / ph;
    // Keep both finite over long walks: only beta/mean(ratio) matters.
    const double s = std::max({ratio_.x, ratio_.y, ratio_.z});
    if (s > 1e100 || s < 1e-100) {
        beta_ /= s;
        ratio_ /= s;
    }
}

glm::dvec3 SpectralWeight::value() const {
    return beta_ * (3.0 / (ratio_.x + ratio_.y + ratio_.z));
}

glm::dvec3 transmittance(const Medium& m, double d) {
    return {std::exp(-m.sigmaT.x * d), std::exp(-m.sigmaT.y * d), std::exp(-m.sigmaT.z * d)};
}

FreeFlight sampleFreeFlight(const Medium& m, double tSurface, SpectralWeight& w, Rng& rng) {
    const double t = -std::log1p(-rng.uniform()) / m.sigmaT[w.hero()];
    if (t < tSurface) {
        const glm::dvec3 tr = transmittance(m, t);
        w.sampled(m.sigmaS * tr, m.sigmaT * tr);
        return {t, true};
    }
    const glm::dvec3 tr = transmittance(m, tSurface);
    w.sampled(tr, tr);
    return {tSurface, false};
}

}  // namespace tsis
