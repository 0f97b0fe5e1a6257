#include "physics/beam_diffusion.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <numbers>

#include "physics/better_dipole.h"
#include "physics/fresnel.h"
#include "util/error.h"

namespace tsis {

namespace {

// pbrt-v3's grids: albedos denser near 1, radii geometric (×1.2) from 2.5e-3
// to ~200 mean free paths.
constexpr int kAlbedos = 100, kRadii = 64;

// Non-uniform Catmull-Rom: weights of xs[first..first+3] at x (zero where the
// index falls outside); false when x is outside [xs.front(), xs.back()].
bool catmullRom(const std::vector<double>& xs, double x, int& first, double w[4]) {
    if (!(x >= xs.front() && x <= xs.back())) return false;
    const int n = static_cast<int>(xs.size());
    const int i = std::min(
        static_cast<int>(std::upper_bound(xs.begin(), xs.end(), x) - xs.begin()) - 1, n - 2);
    const double x1 = xs[i], x2 = xs[i + 1], t = (x - x1) / (x2 - x1);
    const double t2 = t * t, t3 = t2 * t;
    const double h00 = 2 * t3 - 3 * t2 + 1, h01 = -2 * t3 + 3 * t2, h10 = t3 - 2 * t2 + t,
                 h11 = t3 - t2;
    first = i - 1;
    w[0] = w[3] = 0.0;
    w[1] = h00;
    w[2] = h01;
    // Tangents: central differences scaled to [x1, x2], one-sided at the ends.
    if (i > 0) {
        const double s = (x2 - x1) / (x2 - xs[i - 1]);
        w[0] -= h10 * s;
        w[2] += h10 * s;
    } else {
        w[1] -= h10;
        w[2] += h10;
    }
    if (i + 2 < n) {
        const double s = (x2 - x1) / (xs[i + 2] - x1);
        w[1] -= h11 * s;
        w[3] += h11 * s;
    } else {
        w[1] -= h11;
        w[2] += h11;
    }
    return true;
}

}  // namespace

double beamDiffusionMS(const BetterDipoleChannel& dipole, double r, int samples) {
    const double st = dipole.sigmaTPrime, rho = dipole.alphaPrime;
    double sum = 0;
    for (int i = 0; i < samples; ++i) {
        const double z = -std::log(1.0 - (i + 0.5) / samples) / st;
        const double kappa = 1.0 - std::exp(-2.0 * st * (std::sqrt(r * r + z * z) + z));
        sum += kappa * rho * rho * dipole.pointSource(z, r);
    }
    return sum / samples;
}

double beamDiffusionSS(double rho, double eta, double r, int samples) {
    // Depths above tCrit see xo past the critical angle: no light leaves.
    const double tCrit = r * std::sqrt(std::max(0.0, eta * eta - 1.0));
    double sum = 0;
    for (int i = 0; i < samples; ++i) {
        const double t = tCrit - std::log(1.0 - (i + 0.5) / samples);
        const double d = std::sqrt(r * r + t * t), mu = t / d;
        sum += rho * std::exp(-(d + tCrit)) / (d * d) * fresnelTransmittance(1.0 / eta, mu) * mu;
    }
    return sum / (4.0 * std::numbers::pi * samples);
}

BeamDiffusionTable::BeamDiffusionTable(double eta) : eta_(eta) {
    for (int i = 0; i < kAlbedos; ++i)
        rho_.push_back((1.0 - std::exp(-8.0 * i / (kAlbedos - 1))) / (1.0 - std::exp(-8.0)));
    radius_ = {0.0, 2.5e-3};
    while (static_cast<int>(radius_.size()) < kRadii) radius_.push_back(radius_.back() * 1.2);
    profile_.resize(static_cast<size_t>(kAlbedos) * kRadii);
    const double c1 = fresnelMoment(1.0 / eta, 1), c2 = fresnelMoment(1.0 / eta, 2);
    for (int i = 0; i < kAlbedos; ++i) {
        const BetterDipoleChannel ms(rho_[i], 1.0 - rho_[i], c1, c2);
        for (int j = 1; j < kRadii; ++j) {
            const double r = radius_[j];
            // Per unit albedo: smooth down to ρ = 0 (single scattering ∝ ρ,
            // multiple ∝ ρ²), where the limit is single scattering's.
            const double perRho =
                i == 0 ? beamDiffusionSS(1.0, eta, r)
                       : (beamDiffusionSS(rho_[i], eta, r) + beamDiffusionMS(ms, r)) / rho_[i];
            profile_[static_cast<size_t>(i) * kRadii + j] = 2.0 * std::numbers::pi * r * perRho;
        }
    }
}

double BeamDiffusionTable::Rd(double rho, double r) const {
    r = std::max(r, radius_[1]);
    rho = std::clamp(rho, 0.0, 1.0);
    int fi, fj;
    double wi[4], wj[4];
    if (!catmullRom(rho_, rho, fi, wi) || !catmullRom(radius_, r, fj, wj)) return 0.0;
    double v = 0;
    for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) {
            const int i = fi + a, j = fj + b;
            if (wi[a] == 0.0 || wj[b] == 0.0 || i < 0 || j < 0 || i >= kAlbedos || j >= kRadii)
                continue;
            v += wi[a] * wj[b] * profile_[static_cast<size_t>(i) * kRadii + j];
        }
    return std::max(0.0, rho * v / (2.0 * std::numbers::pi * r));
}

std::shared_ptr<const BeamDiffusionTable> beamDiffusionTable(double eta) {
    static std::mutex mutex;
    static std::map<double, std::shared_ptr<const BeamDiffusionTable>> tables;
    const std::lock_guard<std::mutex> lock(mutex);
    auto& t = tables[eta];
    if (!t) t = std::make_shared<const BeamDiffusionTable>(eta);
    return t;
}

BeamDiffusion::BeamDiffusion(const Material& m)
    : table((TSIS_CHECK_MATERIAL(m), beamDiffusionTable(m.eta))),
      rho(m.sigmaSPrime / (m.sigmaSPrime + m.sigmaA)),
      sigmaT(m.sigmaSPrime + m.sigmaA) {}

glm::dvec3 BeamDiffusion::Rd(double r) const {
    glm::dvec3 v;
    for (int c = 0; c < 3; ++c) v[c] = sigmaT[c] * sigmaT[c] * table->Rd(rho[c], sigmaT[c] * r);
    return v;
}

}  // namespace tsis
