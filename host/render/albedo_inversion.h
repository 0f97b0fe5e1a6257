// A material from what an artist sets (issue 20, pbrt-v4's SubsurfaceMaterial
// with `reflectance` + `mfp`): the surface albedo, i.e. the total diffuse
// reflectance ∫ Rd 2πr dr of the --profile model, and the mean free path
// ℓ = 1/σt′, per channel. The albedo fixes the reduced scattering albedo
// α′ = σs′/σt′ (the total reflectance depends on α′ and η alone), ℓ the scale:
// σs′ = α′/ℓ, σa = (1 − α′)/ℓ (docs/design.md §2 "Materials").
#pragma once

#include <glm/vec3.hpp>
#include <string>

#include "physics/material.h"
#include "render/render_options.h"

namespace tsis {

// The mean free paths taken (mm): 0.1 µm to 10 m, the range of σt′ (physics/material.h).
inline constexpr double kMinMeanFreePath = 1e-4;
inline constexpr double kMaxMeanFreePath = 1e4;

// What is wrong with an albedo or mean free path ("" when nothing): each
// channel of the albedo in (0, kMaxAlbedo], of the mean free path in
// [kMinMeanFreePath, kMaxMeanFreePath] mm.
std::string albedoProblem(const glm::dvec3& albedo);
std::string meanFreePathProblem(const glm::dvec3& mfp);
// The largest albedo taken: the total reflectance tends to 1 as σa → 0.
constexpr double kMaxAlbedo = 0.99;

// The material whose `model` profile (mc: the better dipole, whose inversion
// needs no simulation) reflects `albedo` in total, with mean free
// path `mfp` (mm) and index eta. Throws Error (albedoProblem, meanFreePathProblem).
Material materialFromAlbedo(const std::string& name, const glm::dvec3& albedo,
                            const glm::dvec3& mfp, double eta, ProfileModel model);

// The inverse: the albedo (total reflectance) and mean free path of `m`.
glm::dvec3 albedoOf(const Material& m, ProfileModel model);
glm::dvec3 meanFreePathOf(const Material& m);

}  // namespace tsis
