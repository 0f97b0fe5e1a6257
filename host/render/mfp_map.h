// Mean-free-path maps (issue 39, docs/design.md §2 "Materials"): a material's
// map (glTF extras.tsis.mfp_texture, linear) scales its mean free path per
// texel by the mean of the texel's r, g and b — σs′ and σa divided by it, so
// the albedo, which depends on α′ = σs′/σt′ alone, stays. A frame runs its
// method once per distinct material (render/scene_media.h), so the map is
// quantised to at most kMaxMfpSteps steps, geometric between its smallest
// and largest scale (adjacent steps at most kMfpStepRatio apart where the
// range allows); each texel scatters with its step's medium (its slot,
// render/albedo_atlas.h), as a solid of several materials does.
#pragma once

#include <glm/vec2.hpp>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace tsis {

constexpr int kMaxMfpSteps = 8;
constexpr double kMfpStepRatio = 1.2;

// The steps of `map` (named `mapName` in errors) for `medium`, ascending.
// Throws Error for a texel whose scale is not finite and > 0, or a step
// whose mean free path leaves [kMinMeanFreePath, kMaxMeanFreePath].
std::vector<MfpStep> mfpSteps(const ImageF& map, const std::string& mapName,
                              const Material& medium);

// The step of material `o` (with a map) at texture coordinate `tc`: the
// map's scale there (bilinear, wrapping, as the albedo texture) rounded to
// the nearest step in log scale.
size_t mfpStepAt(const ObjectMaterial& o, const glm::vec2& tc);

}  // namespace tsis
