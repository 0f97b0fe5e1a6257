#include "physics/beam_diffusion.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "physics/better_dipole.h"
#include "physics/fresnel.h"
#include "support/plane_integral.h"

namespace tsis {
namespace {

constexpr double kEta = 1.3;

double direct(double rho, double r) {
    return beamDiffusionSS(rho, kEta, r) +
           beamDiffusionMS(BetterDipoleChannel(rho, 1.0 - rho, kEta), r);
}

// The table's Catmull-Rom against the formulas at random (albedo, radius).
TEST(BeamDiffusion, TableMatchesDirectEvaluation) {
    const auto table = beamDiffusionTable(kEta);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    double worst = 0;
    for (int k = 0; k < 300; ++k) {
        const double rho = 0.05 + 0.94 * u(rng);
        const double r = 0.01 * std::pow(2000.0, u(rng));  // 0.01 to 20 free paths
        const double want = direct(rho, r), got = table->Rd(rho, r);
        // Relative where the profile matters; absolute against its peak far out.
        const double err = std::abs(got - want) / (want + 1e-4 * direct(rho, 0.01));
        worst = std::max(worst, err);
        EXPECT_LT(err, 0.005) << "rho " << rho << " r " << r << ": " << got << " vs " << want;
    }
    std::printf("worst table error %.4f\n", worst);
}

// Single scattering over the plane has a closed form in one integral:
// (ρ/2) ∫₀¹ Ft(1/η, μ) μ/(1 + μ) dμ (each depth t contributes
// σt e^(−σt t(1 + 1/μ)) along each exit direction μ).
TEST(BeamDiffusion, SingleScatteringPlaneIntegral) {
    const double rho = 0.8;
    const int n = 20000;
    double closed = 0;
    for (int k = 0; k < n; ++k) {
        const double mu = (k + 0.5) / n;
        closed += fresnelTransmittance(1.0 / kEta, mu) * mu / (1.0 + mu) / n;
    }
    closed *= rho / 2.0;
    const double numeric = test::planeIntegral(
        [&](double r) { return beamDiffusionSS(rho, kEta, r, 2000); }, 1e-7, 60.0, 2000);
    EXPECT_NEAR(numeric / closed, 1.0, 2e-3);
}

// The profile tsis tabulates (table, σt′ scaling) over the plane against the
// formulas' own plane integral, per preset channel.
TEST(BeamDiffusion, ProfilePlaneIntegralMatchesFormulas) {
    for (const char* name : {"marble", "skin1", "ketchup"}) {
        const Material m = presetMaterial(name);
        const BeamDiffusion pbd(m);
        for (int c = 0; c < 3; ++c) {
            const double st = m.sigmaSPrime[c] + m.sigmaA[c], rho = m.sigmaSPrime[c] / st;
            const BetterDipoleChannel ms(rho, 1.0 - rho, m.eta);
            auto formula = [&](double r) {
                return beamDiffusionSS(rho, m.eta, r) + beamDiffusionMS(ms, r);
            };
            // In free paths (σt′ = 1) for the formulas; in mm for the profile.
            const double want = test::planeIntegral(formula, 1e-4, 150.0, 2000);
            const double got = test::planeIntegral([&](double r) { return pbd.Rd(r)[c]; },
                                                   1e-4 / st, 150.0 / st, 2000);
            EXPECT_NEAR(got / want, 1.0, 0.01) << name << " " << c;
        }
    }
}

// Multiple scattering scales with σt′: Rd(r) = σt′² Rd₁(σt′ r).
TEST(BeamDiffusion, MultipleScatteringScalesWithSigmaT) {
    const BetterDipoleChannel unit(0.9, 0.1, kEta), scaled(9.0, 1.0, kEta);
    for (double r : {0.01, 0.3, 2.0})
        EXPECT_NEAR(beamDiffusionMS(scaled, r / 10.0) / (100.0 * beamDiffusionMS(unit, r)), 1.0,
                    1e-9)
            << r;
}

}  // namespace
}  // namespace tsis
