#include "physics/report.h"

#include <gtest/gtest.h>

#include <sstream>

#include "physics/dipole.h"
#include "physics/split.h"

namespace tsis {
namespace {

Json rgb(const glm::dvec3& v) {
    return Json::array({v.x, v.y, v.z});
}

// The report against values built independently.
TEST(Report, DipoleReportKeysAndValues) {
    const Material& m = presetMaterial("marble");
    const std::vector<double> radii = {0.0, 0.01, 0.5, 3.0, 25.0};
    const Json got = dipoleReport(m, radii);
    const Dipole d(m);
    Json rd = Json::array();
    for (double r : radii) rd.push_back(Json::array({r, rgb(d.Rd(r))}));
    Json want = Json::object();
    want["material"] = "marble";
    want["eta"] = 1.5;
    want["sigma_s_prime"] = rgb(m.sigmaSPrime);
    want["sigma_a"] = rgb(m.sigmaA);
    want["sigma_tr"] = rgb(d.sigmaTr());
    want["mean_free_path"] = rgb(1.0 / (m.sigmaSPrime + m.sigmaA));
    want["total_reflectance"] = rgb(d.totalReflectance());
    want["rp"] = rgb(importanceRadius(d, 0.1));
    want["rd"] = rd;
    EXPECT_EQ(got, want);
    EXPECT_EQ(dipoleReport(m, radii, 0.05)["rp"], rgb(importanceRadius(d, 0.05)));
}

TEST(Report, MaterialsTableIsAligned) {
    std::istringstream in(materialsTable());
    std::vector<std::string> lines;
    for (std::string l; std::getline(in, l);) lines.push_back(l);
    ASSERT_EQ(lines.size(), 1 + presetMaterials().size());
    for (size_t k = 1; k < lines.size(); ++k) {
        EXPECT_EQ(lines[k].size(), lines[0].size()) << lines[k];
        EXPECT_EQ(lines[k].rfind(presetMaterials()[k - 1].name + " ", 0), 0u) << lines[k];
    }
    EXPECT_NE(lines[6].find("0.830  0.791  0.753"), std::string::npos) << lines[6];  // marble
}

}  // namespace
}  // namespace tsis
