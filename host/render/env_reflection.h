// The environment's reflection through the GGX lobe (docs/design.md §10),
// split-sum (Karis 2013): the residual (scene/environment.h, the map without
// its sun, which is a light the lobe already sees) prefiltered by the lobe
// about the mirror direction, in the map's own frame (turning the map turns
// the lookup direction in the shader, no re-filtering), times the lobe's
// directional albedo at each medium's η and the view cosine. For a uniform
// environment the product is exact: L · ggxDirectionalAlbedo(η, R, cos θo).
#pragma once

#include <vector>

#include "scene/environment.h"

namespace tsis {

// Width of the prefiltered lat-long map (height: half). 5.6° texels: the
// default lobe (R 0.3) spans about 10° about the mirror direction.
constexpr int kReflectionMapWidth = 64;
// Entries of the albedo table per medium, at √cos θo = 0, 1/(n−1), …, 1
// (denser where the albedo turns fastest, at grazing view).
constexpr int kReflectionAlbedoEntries = 64;

// With a roughness map (render/surface_atlas.h) R varies per texel: the
// composite blends the two nearest of a ladder of prefiltered layers, step
// k at ladderRoughness(k), denser at low R where the lobe narrows fastest
// (the shader, radiance.frag, inverts the same formula).
constexpr int kRoughnessLadderSteps = 9;
double ladderRoughness(int k);

// The residual prefiltered by the lobe at `roughness`: for each direction r
// of a width × width/2 lat-long grid (map frame, row 0 = up), the mean of
// the residual weighted by D(r·h)·max(0, r·l) dω with h = (l + r)/|l + r|
// (n = v = r). RGBA floats, row 0 = up.
std::vector<float> prefilterReflection(const EnvironmentMap& map, double roughness, int width);

// ggxDirectionalAlbedo(η_m, R_m, cos θo) for each medium m (one row each,
// the value in all of RGBA), kReflectionAlbedoEntries per row at √cos θo
// uniformly spaced.
std::vector<float> reflectionAlbedoTable(const std::vector<float>& etaOfMedium,
                                         const std::vector<float>& roughnessOfMedium);

}  // namespace tsis
