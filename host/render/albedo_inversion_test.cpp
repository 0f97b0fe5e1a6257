#include "render/albedo_inversion.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "util/error.h"

namespace tsis {
namespace {

// albedo → σ → albedo round-trips, and σ back, for every preset and profile.
TEST(AlbedoInversion, RoundTripsEveryPreset) {
    int tried = 0;
    for (ProfileModel model : {ProfileModel::Dipole, ProfileModel::BetterDipole, ProfileModel::Pbd})
        for (const Material& m : presetMaterials()) {
            // Without absorption the albedo is 1: no artist's material.
            if (m.sigmaA.x == 0 || m.sigmaA.y == 0 || m.sigmaA.z == 0) continue;
            const glm::dvec3 a = albedoOf(m, model), mfp = meanFreePathOf(m);
            ASSERT_TRUE(std::isfinite(a.x + a.y + a.z)) << m.name << " " << profileModelName(model);
            // pbd lets out more than enters for the least absorbing (its
            // single scattering is not normalised): past the artist's range.
            if (std::max({a.x, a.y, a.z}) > kMaxAlbedo) continue;
            ++tried;
            const Material back = materialFromAlbedo(m.name, a, mfp, m.eta, model);
            const glm::dvec3 again = albedoOf(back, model);
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(again[c] / a[c], 1.0, 0.005) << m.name << " " << c;
                EXPECT_NEAR(back.sigmaSPrime[c] / m.sigmaSPrime[c], 1.0, 0.005) << m.name;
                EXPECT_NEAR(back.sigmaA[c] / m.sigmaA[c], 1.0, 0.005)
                    << m.name << " " << profileModelName(model) << " " << c;
            }
            EXPECT_EQ(back.eta, m.eta);
        }
    EXPECT_GE(tried, 3 * static_cast<int>(presetMaterials().size()) - 6);
}

TEST(AlbedoInversion, RefusesWhatHasNoMaterial) {
    const glm::dvec3 mfp(1.0);
    for (const glm::dvec3& a : {glm::dvec3(1.0, 0.5, 0.5), glm::dvec3(0.0, 0.5, 0.5),
                                glm::dvec3(NAN, 0.5, 0.5), glm::dvec3(-0.1, 0.5, 0.5)})
        EXPECT_THROW(materialFromAlbedo("x", a, mfp, 1.3, ProfileModel::Dipole), Error);
    for (const glm::dvec3& l :
         {glm::dvec3(0.0, 1, 1), glm::dvec3(-1.0, 1, 1), glm::dvec3(INFINITY, 1, 1)})
        EXPECT_THROW(materialFromAlbedo("x", glm::dvec3(0.5), l, 1.3, ProfileModel::Dipole), Error);
}

}  // namespace
}  // namespace tsis
