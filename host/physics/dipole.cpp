#include "physics/dipole.h"

#include <cmath>
#include <numbers>

#include "util/error.h"

namespace tsis {

double diffuseFresnelReflectance(double eta) {
    return -1.440 / (eta * eta) + 0.710 / eta + 0.668 + 0.0636 * eta;
}

DipoleChannel::DipoleChannel(double sigmaSPrime, double sigmaA, double eta)
    : sigmaSPrime(sigmaSPrime), sigmaA(sigmaA), eta(eta) {
    // Callers validate user input (validateMaterial); here a bad value is a bug.
    TSIS_CHECK_GE(sigmaSPrime, 0.0);
    TSIS_CHECK_GE(sigmaA, 0.0);
    TSIS_CHECK_GT(sigmaSPrime + sigmaA, 0.0);
    TSIS_CHECK_GT(eta, 0.0);
    sigmaTPrime = sigmaSPrime + sigmaA;
    alphaPrime = sigmaSPrime / sigmaTPrime;
    sigmaTr = std::sqrt(3.0 * sigmaA * sigmaTPrime);
    Fdr = diffuseFresnelReflectance(eta);
    A = (1.0 + Fdr) / (1.0 - Fdr);
    zr = 1.0 / sigmaTPrime;
    zv = zr * (1.0 + 4.0 * A / 3.0);
}

double DipoleChannel::Rd(double r) const {
    // One source at depth z: z (1 + σtr s) e^(−σtr s) / s³ with s its distance to xo.
    auto source = [&](double z) {
        const double s = std::sqrt(r * r + z * z);
        return z * (1.0 + sigmaTr * s) * std::exp(-sigmaTr * s) / (s * s * s);
    };
    return alphaPrime / (4.0 * std::numbers::pi) * (source(zr) + source(zv));
}

double DipoleChannel::totalReflectance() const {
    const double root = std::sqrt(3.0 * (1.0 - alphaPrime));
    return 0.5 * alphaPrime * (1.0 + std::exp(-4.0 / 3.0 * A * root)) * std::exp(-root);
}

// The material was validated where it entered; the CHECK names what is wrong.
static std::array<DipoleChannel, 3> channels(const Material& m) {
    TSIS_CHECK_MATERIAL(m);
    return {DipoleChannel(m.sigmaSPrime.x, m.sigmaA.x, m.eta),
            DipoleChannel(m.sigmaSPrime.y, m.sigmaA.y, m.eta),
            DipoleChannel(m.sigmaSPrime.z, m.sigmaA.z, m.eta)};
}

Dipole::Dipole(const Material& m) : ch(channels(m)) {}

glm::dvec3 Dipole::Rd(double r) const {
    return {ch[0].Rd(r), ch[1].Rd(r), ch[2].Rd(r)};
}

glm::dvec3 Dipole::totalReflectance() const {
    return {ch[0].totalReflectance(), ch[1].totalReflectance(), ch[2].totalReflectance()};
}

glm::dvec3 Dipole::sigmaTr() const {
    return {ch[0].sigmaTr, ch[1].sigmaTr, ch[2].sigmaTr};
}

glm::dvec3 Dipole::meanFreePath() const {
    return {ch[0].meanFreePath(), ch[1].meanFreePath(), ch[2].meanFreePath()};
}

}  // namespace tsis
