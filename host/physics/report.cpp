#include "physics/report.h"

#include <cstdio>

#include "physics/dipole.h"
#include "physics/split.h"

namespace tsis {

static Json rgb(const glm::dvec3& v) {
    return Json::array({v.x, v.y, v.z});
}

Json dipoleReport(const Material& m, const std::vector<double>& radii, double rpBound) {
    const Dipole d(m);
    Json rd = Json::array();
    for (double r : radii) rd.push_back(Json::array({r, rgb(d.Rd(r))}));
    Json j = Json::object();
    j["material"] = m.name;
    j["eta"] = m.eta;
    j["sigma_s_prime"] = rgb(m.sigmaSPrime);
    j["sigma_a"] = rgb(m.sigmaA);
    j["sigma_tr"] = rgb(d.sigmaTr());
    j["mean_free_path"] = rgb(d.meanFreePath());
    j["total_reflectance"] = rgb(d.totalReflectance());
    j["rp"] = rgb(importanceRadius(d, rpBound));
    j["rd"] = std::move(rd);
    return j;
}

std::string materialsTable() {
    std::string out;
    char line[256];
    auto add = [&](const char* fmt, auto... args) {
        std::snprintf(line, sizeof line, fmt, args...);
        out += line;
    };
    add("%-10s %4s  %-20s  %-23s  %-20s  %-23s\n", "material", "eta", "sigma_s' (1/mm) RGB",
        "sigma_a (1/mm) RGB", "total Rd RGB", "mean free path (mm) RGB");
    for (const Material& m : presetMaterials()) {
        const Dipole d(m);
        const glm::dvec3 R = d.totalReflectance(), l = d.meanFreePath();
        add("%-10s %4.2f  %6.2f %6.2f %6.2f  %7.4f %7.4f %7.4f  %6.3f %6.3f %6.3f  "
            "%7.4f %7.4f %7.4f\n",
            m.name.c_str(), m.eta, m.sigmaSPrime.x, m.sigmaSPrime.y, m.sigmaSPrime.z, m.sigmaA.x,
            m.sigmaA.y, m.sigmaA.z, R.x, R.y, R.z, l.x, l.y, l.z);
    }
    return out;
}

}  // namespace tsis
