#include "render/profile_table_cache.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "physics/dipole.h"

namespace tsis {
namespace {

// Largest relative error of the tabulated Rd (as the kernels interpolate it)
// against the double-precision dipole, over r in [0, rMax / 2] (two points of
// an object whose bounding sphere has diameter rMax are rarely further apart;
// beyond, Rd is < 1e-9 of its peak for these materials).
double worstRelativeError(const Material& m, double rMax) {
    ProfileTableCache t;
    EXPECT_TRUE(t.update(m, ProfileModel::Dipole, rMax));
    EXPECT_FALSE(t.update(m, ProfileModel::Dipole, rMax)) << "unchanged material: kept";
    const Dipole d(m);
    double worst = 0;
    for (int i = 0; i <= 200000; ++i) {
        const double r = 0.5 * rMax * i / 200000.0;
        const glm::dvec3 exact = d.Rd(r);
        const glm::vec3 got = t.table().lookup(static_cast<float>(r));
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(got[c] / exact[c] - 1.0));
    }
    return worst;
}

TEST(ProfileTableCache, RelativeErrorBelow1e5At10mmAnd1e4At30mm) {
    for (const char* name : {"marble", "skin1", "skimmilk", "ketchup"}) {
        const double e10 = worstRelativeError(presetMaterial(name), 10.0);
        const double e30 = worstRelativeError(presetMaterial(name), 30.0);
        std::printf("%-9s worst relative error of the table: %.2e at 10 mm, %.2e at 30 mm\n", name,
                    e10, e30);
        EXPECT_LT(e10, 1e-5) << name;
        EXPECT_LT(e30, 1e-4) << name;
    }
}

TEST(ProfileTableCache, KeysKeepEveryDigit) {
    // A size change in the 8th digit (which a 6-decimal key would round away)
    // is a new range, and a new table.
    ProfileTableCache t;
    const Material m = presetMaterial("marble");
    EXPECT_TRUE(t.update(m, ProfileModel::Dipole, 10.0));
    EXPECT_TRUE(t.update(m, ProfileModel::Dipole, 10.0000001));
    EXPECT_TRUE(t.update(m, ProfileModel::Dipole, std::nextafter(10.0000001, 11.0)));
    EXPECT_FALSE(t.update(m, ProfileModel::Dipole, std::nextafter(10.0000001, 11.0)));
    Material n = m;
    n.sigmaA.y = std::nextafter(n.sigmaA.y, 1.0);
    EXPECT_TRUE(t.update(n, ProfileModel::Dipole, std::nextafter(10.0000001, 11.0)));
}

TEST(ProfileTableCache, RetabulatesWhenMaterialOrRangeChanges) {
    ProfileTableCache t;
    Material m = presetMaterial("marble");
    EXPECT_TRUE(t.update(m, ProfileModel::Dipole, 10.0));
    EXPECT_TRUE(t.update(m, ProfileModel::Dipole, 20.0));
    m.sigmaA.x *= 2;
    EXPECT_TRUE(t.update(m, ProfileModel::Dipole, 20.0));
    EXPECT_FALSE(t.update(m, ProfileModel::Dipole, 20.0));
    // Another model (--profile) is another table, and back again.
    EXPECT_TRUE(t.update(m, ProfileModel::BetterDipole, 20.0));
    EXPECT_TRUE(t.update(m, ProfileModel::Pbd, 20.0));
    EXPECT_FALSE(t.update(m, ProfileModel::Pbd, 20.0));
    EXPECT_TRUE(t.update(m, ProfileModel::Dipole, 20.0));
}

}  // namespace
}  // namespace tsis
