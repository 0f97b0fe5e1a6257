#include "physics/material.h"

#include <cmath>

#include "util/error.h"

namespace tsis {

const std::vector<Material>& presetMaterials() {
    // Jensen et al. 2001, Fig. 5 (σs', σa in mm⁻¹). Marble uses η = 1.5: only then
    // does the closed-form ∫Rd match the paper's diffuse-reflectance column.
    static const std::vector<Material> presets = {
        {"apple", {2.29, 2.39, 1.97}, {0.0030, 0.0034, 0.046}, 1.3},
        {"chicken1", {0.15, 0.21, 0.38}, {0.015, 0.077, 0.19}, 1.3},
        {"chicken2", {0.19, 0.25, 0.32}, {0.018, 0.088, 0.20}, 1.3},
        {"cream", {7.38, 5.47, 3.15}, {0.0002, 0.0028, 0.0163}, 1.3},
        {"ketchup", {0.18, 0.07, 0.03}, {0.061, 0.97, 1.45}, 1.3},
        {"marble", {2.19, 2.62, 3.00}, {0.0021, 0.0041, 0.0071}, 1.5},
        {"potato", {0.68, 0.70, 0.55}, {0.0024, 0.0090, 0.12}, 1.3},
        {"skimmilk", {0.70, 1.22, 1.90}, {0.0014, 0.0025, 0.0142}, 1.3},
        {"skin1", {0.74, 0.88, 1.01}, {0.032, 0.17, 0.48}, 1.3},
        {"skin2", {1.09, 1.59, 1.79}, {0.013, 0.070, 0.145}, 1.3},
        {"spectralon", {11.6, 20.4, 14.9}, {0.0, 0.0, 0.0}, 1.3},
        {"wholemilk", {2.55, 3.21, 3.77}, {0.0011, 0.0024, 0.014}, 1.3},
    };
    return presets;
}

const Material& presetMaterial(std::string_view name) {
    std::string names;
    for (const Material& m : presetMaterials()) {
        if (m.name == name) return m;
        names += (names.empty() ? "" : ", ") + m.name;
    }
    fail("unknown material '", name, "'; valid names: ", names);
}

std::string materialProblem(const Material& m) {
    static const char* channel[3] = {"red", "green", "blue"};
    auto coefficientProblem = [&](const char* field, double v, int c) -> std::string {
        if (!std::isfinite(v))
            return concat("material '", m.name, "': ", field, " ", channel[c], " is ", v,
                          "; it must be a finite number (mm^-1)");
        if (v < 0.0)
            return concat("material '", m.name, "': ", field, " ", channel[c], " is negative (", v,
                          " mm^-1)");
        if (v > kMaxSigma)
            return concat("material '", m.name, "': ", field, " ", channel[c], " is ", v,
                          " mm^-1; it must lie in [0, ", kMaxSigma, "] mm^-1");
        return "";
    };
    for (int c = 0; c < 3; ++c) {
        for (const std::string& p : {coefficientProblem("sigma_s'", m.sigmaSPrime[c], c),
                                     coefficientProblem("sigma_a", m.sigmaA[c], c)})
            if (!p.empty()) return p;
        // The dipole divides by σt' (zr = 1/σt', α' = σs'/σt').
        if (m.sigmaSPrime[c] + m.sigmaA[c] <= 0.0)
            return concat("material '", m.name, "': sigma_t' = sigma_s' + sigma_a ", channel[c],
                          " is 0; the dipole needs a scattering or absorbing medium");
        if (m.sigmaSPrime[c] + m.sigmaA[c] < kMinSigmaT)
            return concat("material '", m.name, "': sigma_t' = sigma_s' + sigma_a ", channel[c],
                          " is ", m.sigmaSPrime[c] + m.sigmaA[c], " mm^-1; it must be at least ",
                          kMinSigmaT, " mm^-1 (a mean free path of at most ", 1 / kMinSigmaT,
                          " mm)");
    }
    // !(a < x && x < b) also rejects NaN.
    if (!(1.0 < m.eta && m.eta < 4.0))
        return concat("material '", m.name, "': eta is ", m.eta, "; it must lie in (1, 4)");
    return "";
}

void validateMaterial(const Material& m) {
    if (std::string p = materialProblem(m); !p.empty()) fail(p);
}

void checkMaterialImpl(const char* file, int line, const Material& m) {
    if (std::string p = materialProblem(m); !p.empty()) checkFailed(file, line, p);
}

}  // namespace tsis
