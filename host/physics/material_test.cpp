#include "physics/material.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "physics/dipole.h"
#include "util/error.h"

namespace tsis {
namespace {

// The message validateMaterial throws for m ("" when it accepts m).
std::string rejection(const Material& m) {
    try {
        validateMaterial(m);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

void expectRejected(const Material& m, std::initializer_list<const char*> words) {
    const std::string msg = rejection(m);
    ASSERT_FALSE(msg.empty()) << "accepted a bad material";
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    for (const char* w : words) EXPECT_NE(msg.find(w), std::string::npos) << w << " ∉ " << msg;
}

TEST(Material, PresetsAreJensensTableAndValid) {
    ASSERT_EQ(presetMaterials().size(), 12u);
    for (const Material& m : presetMaterials()) {
        EXPECT_EQ(rejection(m), "") << m.name;
        EXPECT_EQ(m.eta, m.name == "marble" ? 1.5 : 1.3) << m.name;
    }
    // Spot checks against docs/design.md §2, including the rows Mitsuba 0.x misprints.
    EXPECT_EQ(presetMaterial("chicken1").sigmaA, glm::dvec3(0.015, 0.077, 0.19));
    EXPECT_EQ(presetMaterial("chicken2").sigmaA, glm::dvec3(0.018, 0.088, 0.20));
    EXPECT_EQ(presetMaterial("cream").sigmaSPrime, glm::dvec3(7.38, 5.47, 3.15));
    EXPECT_EQ(presetMaterial("spectralon").sigmaA, glm::dvec3(0.0));
    EXPECT_EQ(presetMaterial("wholemilk").sigmaA, glm::dvec3(0.0011, 0.0024, 0.014));
}

TEST(Material, UnknownPresetListsValidNames) {
    try {
        presetMaterial("nope");
        FAIL() << "no error";
    } catch (const Error& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("'nope'"), std::string::npos) << msg;
        EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
        for (const Material& m : presetMaterials())
            EXPECT_NE(msg.find(m.name), std::string::npos) << m.name << " ∉ " << msg;
    }
}

TEST(Material, RejectsBadCoefficientsNamingFieldAndChannel) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    Material m = presetMaterial("skin1");
    m.name = "bad";

    Material a = m;
    a.sigmaSPrime.y = nan;
    expectRejected(a, {"'bad'", "sigma_s'", "green", "finite"});
    a = m;
    a.sigmaA.z = inf;
    expectRejected(a, {"sigma_a", "blue", "finite"});
    a = m;
    a.sigmaA.x = -0.01;
    expectRejected(a, {"sigma_a", "red", "negative"});
    a = m;
    a.sigmaSPrime.x = -1.0;
    expectRejected(a, {"sigma_s'", "red", "negative"});
    a = m;
    a.sigmaSPrime.y = a.sigmaA.y = 0.0;
    expectRejected(a, {"sigma_t'", "green", "0"});
    for (double eta : {1.0, 4.0, 0.5, nan, inf}) {
        a = m;
        a.eta = eta;
        expectRejected(a, {"eta", "(1, 4)"});
    }
    a = m;
    a.eta = 3.9;
    EXPECT_EQ(rejection(a), "");
}

// The physical range: each coefficient in [0, 1e4] mm⁻¹ and σt′ at least
// 1e-4 mm⁻¹, over every channel and both coefficients; the ends are taken.
TEST(Material, CoefficientsOutsideThePhysicalRangeAreRejected) {
    const Material m = presetMaterial("marble");
    for (int c = 0; c < 3; ++c) {
        for (double big : {1e300, 1.0001e4, 1e5}) {
            Material a = m;
            a.sigmaSPrime[c] = big;
            expectRejected(a, {"sigma_s'", "[0, 10000] mm^-1"});
            a = m;
            a.sigmaA[c] = big;
            expectRejected(a, {"sigma_a", "[0, 10000] mm^-1"});
        }
        for (double tiny : {1e-300, 4e-5}) {
            Material a = m;
            a.sigmaSPrime[c] = a.sigmaA[c] = tiny;
            expectRejected(a, {"sigma_t'", "at least 0.0001 mm^-1"});
        }
        Material ends = m;
        ends.sigmaSPrime[c] = kMaxSigma;
        ends.sigmaA[c] = kMaxSigma;
        EXPECT_EQ(rejection(ends), "");
        ends.sigmaSPrime[c] = kMinSigmaT;
        ends.sigmaA[c] = 0;
        EXPECT_EQ(rejection(ends), "");
    }
    for (const Material& p : presetMaterials()) EXPECT_EQ(rejection(p), "") << p.name;
}

// User input is validated where it enters; the physics' constructors CHECK.
TEST(Material, DipoleOfBadMaterialIsACheck) {
    Material m = presetMaterial("apple");
    m.sigmaA.x = -1.0;
    EXPECT_DEATH(Dipole{m}, "sigma_a red is negative");
}

}  // namespace
}  // namespace tsis
