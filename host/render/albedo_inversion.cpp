#include "render/albedo_inversion.h"

#include <cmath>
#include <glm/common.hpp>

#include "render/energy_target.h"
#include "util/error.h"

namespace tsis {

namespace {

std::string channelProblem(const char* what, const glm::dvec3& v, double lo, double hi,
                           bool loOpen) {
    for (int c = 0; c < 3; ++c)
        if (!std::isfinite(v[c]) || (loOpen ? v[c] <= lo : v[c] < lo) || v[c] > hi)
            return concat(what, " ", v.x, ",", v.y, ",", v.z, ": each channel must be in ",
                          loOpen ? "(" : "[", lo, ", ", hi, "]");
    return "";
}

// σs′ = α′/ℓ, σa = (1 − α′)/ℓ.
Material fromAlphaPrime(const std::string& name, const glm::dvec3& alpha, const glm::dvec3& mfp,
                        double eta) {
    Material m;
    m.name = name;
    m.sigmaSPrime = alpha / mfp;
    m.sigmaA = (glm::dvec3(1.0) - alpha) / mfp;
    m.eta = eta;
    return m;
}

}  // namespace

std::string albedoProblem(const glm::dvec3& albedo) {
    return channelProblem("albedo", albedo, 0.0, kMaxAlbedo, true);
}

std::string meanFreePathProblem(const glm::dvec3& mfp) {
    const std::string p =
        channelProblem("mean free path", mfp, kMinMeanFreePath, kMaxMeanFreePath, false);
    return p.empty() ? p : p + " mm";
}

Material materialFromAlbedo(const std::string& name, const glm::dvec3& albedo,
                            const glm::dvec3& mfp, double eta, ProfileModel model) {
    if (const std::string p = albedoProblem(albedo); !p.empty()) fail(p);
    if (const std::string p = meanFreePathProblem(mfp); !p.empty()) fail(p);
    // Bisection on α′ per channel (all three at once): the total reflectance
    // rises monotonically from 0 at α′ = 0 towards 1 at α′ = 1. The total does
    // not depend on the scale, so it is found at ℓ = 1 mm. The Monte Carlo
    // profile would simulate every step: mc inverts through the better dipole
    // (its R is within 0.91–1.01 of transport's, physical_models.md).
    const ProfileModel inverted = model == ProfileModel::Mc ? ProfileModel::BetterDipole : model;
    glm::dvec3 lo(0.0), hi(1.0 - 1e-9);
    for (int it = 0; it < 48; ++it) {
        const glm::dvec3 mid = 0.5 * (lo + hi);
        const glm::dvec3 total =
            profileTotalReflectance(fromAlphaPrime(name, mid, glm::dvec3(1.0), eta), inverted);
        for (int c = 0; c < 3; ++c) (total[c] < albedo[c] ? lo[c] : hi[c]) = mid[c];
    }
    Material m = fromAlphaPrime(name, 0.5 * (lo + hi), mfp, eta);
    validateMaterial(m);
    return m;
}

glm::dvec3 albedoOf(const Material& m, ProfileModel model) {
    // No absorption in a channel: all the light comes back out.
    if (m.sigmaA.x == 0 || m.sigmaA.y == 0 || m.sigmaA.z == 0) {
        Material absorbing = m;
        absorbing.sigmaA = glm::max(m.sigmaA, 1e-9 * (m.sigmaSPrime + m.sigmaA));
        return glm::min(profileTotalReflectance(absorbing, model), glm::dvec3(1.0));
    }
    return profileTotalReflectance(m, model);
}

glm::dvec3 meanFreePathOf(const Material& m) {
    return glm::dvec3(1.0) / (m.sigmaSPrime + m.sigmaA);
}

}  // namespace tsis
