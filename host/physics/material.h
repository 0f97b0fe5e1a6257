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

// The physical range of the coefficients (docs/guide/scenes-and-materials.md "Scenes and
// materials"): σs′ and σa each in [0, kMaxSigma] mm⁻¹ and σt′ = σs′ + σa at least kMinSigmaT (a
// mean free path of at most 10 m): values past them are input mistakes, and in the kernels' floats
// they become infinities and NaNs.
inline constexpr double kMaxSigma = 1e4;
inline constexpr double kMinSigmaT = 1e-4;

// What is wrong with m ("" when nothing): NaN/inf/negative coefficients or
// ones outside the range above in a channel, or η outside (1, 4).
std::string materialProblem(const Material& m);
// User input, checked once where it enters (the CLI, the viewer's script,
// Renderer::render): throws Error with materialProblem.
void validateMaterial(const Material& m);
// The physics takes validated materials: a bad one here is a bug (a CHECK
// that prints the problem and aborts).
void checkMaterialImpl(const char* file, int line, const Material& m);
#define TSIS_CHECK_MATERIAL(m) ::tsis::checkMaterialImpl(__FILE__, __LINE__, m)

}  // namespace tsis
