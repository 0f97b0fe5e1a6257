#include "physics/better_dipole.h"

#include <cmath>
#include <numbers>

#include "physics/fresnel.h"
#include "util/error.h"

namespace tsis {

// Moments of the reflectance met from inside (relative index 1/η).
BetterDipoleChannel::BetterDipoleChannel(double sigmaSPrime, double sigmaA, double eta)
    : BetterDipoleChannel(sigmaSPrime, sigmaA, fresnelMoment(1.0 / eta, 1),
                          fresnelMoment(1.0 / eta, 2)) {}

BetterDipoleChannel::BetterDipoleChannel(double sigmaSPrime, double sigmaA, double c1, double c2) {
    TSIS_CHECK_GE(sigmaSPrime, 0.0);
    TSIS_CHECK_GE(sigmaA, 0.0);
    TSIS_CHECK_GT(sigmaSPrime + sigmaA, 0.0);
    sigmaTPrime = sigmaSPrime + sigmaA;
    alphaPrime = sigmaSPrime / sigmaTPrime;
    D = (2.0 * sigmaA + sigmaSPrime) / (3.0 * sigmaTPrime * sigmaTPrime);
    sigmaTr = std::sqrt(sigmaA / D);
    cPhi = 0.25 * (1.0 - 2.0 * c1);
    cE = 0.5 * (1.0 - 3.0 * c2);
    zb = 2.0 * D * (1.0 + 3.0 * c2) / (1.0 - 2.0 * c1);
    zr = 1.0 / sigmaTPrime;
}

double BetterDipoleChannel::pointSource(double z, double r) const {
    const double zv = z + 2.0 * zb;
    const double dr = std::sqrt(r * r + z * z), dv = std::sqrt(r * r + zv * zv);
    const double er = std::exp(-sigmaTr * dr), ev = std::exp(-sigmaTr * dv);
    const double phi = (er / dr - ev / dv) / D;
    const double e = z * (1.0 + sigmaTr * dr) * er / (dr * dr * dr) +
                     zv * (1.0 + sigmaTr * dv) * ev / (dv * dv * dv);
    return (cPhi * phi + cE * e) / (4.0 * std::numbers::pi);
}

double BetterDipoleChannel::totalReflectance() const {
    // ∫ e^(−σ s)/s 2πr dr = 2π e^(−σz)/σ and ∫ z(1 + σs)e^(−σs)/s³ 2πr dr = 2π e^(−σz).
    // σa = 0: (er − ev)/σtr → 2zb, and the total is 1 (all light leaves).
    const double er = std::exp(-sigmaTr * zr), ev = std::exp(-sigmaTr * (zr + 2.0 * zb));
    const double fluence = sigmaTr > 0.0 ? (er - ev) / sigmaTr : 2.0 * zb;
    return alphaPrime * (cPhi * fluence / (2.0 * D) + cE * 0.5 * (er + ev));
}

}  // namespace tsis
