// Scattering coefficients of a translucent material (docs/design.md §2): reduced
// scattering σs' and absorption σa in mm⁻¹ per RGB channel, relative index η.
#pragma once

#include <glm/vec3.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace tsis {

struct Material {
    std::string name;
    glm::dvec3 sigmaSPrime{0.0};  // σs' (mm⁻¹)
    glm::dvec3 sigmaA{0.0};       // σa (mm⁻¹)
    double eta = 1.3;
};

// The Jensen et al. 2001 measured table; η = 1.3 except marble (1.5).
const std::vector<Material>& presetMaterials();

// The preset with this name; throws Error listing the valid names.
const Material& presetMaterial(std::string_view name);

// Throws Error naming the problem for NaN/inf/negative coefficients, σt' = 0 in
// a channel, or η outside (1, 4).
void validateMaterial(const Material& m);

}  // namespace tsis
