// Chart packing into [0,1]² for a given texture resolution.
//
// Every chart is rotated to its smallest-area bounding rectangle, then
// rasterised conservatively (every texel its triangles touch) at a common
// density and dilated by ⌈gutter/2⌉ texels. Charts, largest first (by long
// side × short side² of their rectangle; failing that, by rectangle area), go
// to the free position of a bitmap of the square whose middle row is lowest
// (then lowest, then leftmost), in the best of four 90° orientations, so small
// charts fill the holes that large ones leave. The density is the largest one
// at which every chart fits (in either order) inside the square with a
// 1-texel margin, found to 0.3% by a search with two trial densities per round.
//
// Guarantees at `resolution`: two charts' conservative texels are at least
// 2·⌈gutter/2⌉ + 1 texels apart (so their geometry at least `gutter` texels),
// and every chart is at least 1 texel from the [0,1] border.
#pragma once

#include <glm/common.hpp>
#include <glm/vec2.hpp>
#include <vector>

#include "atlas/chart.h"

namespace tsis::atlas {

struct PackChart {
    const std::vector<glm::dvec2>* uv;  // any scale (same for all charts), any placement
    const std::vector<Tri>* triangles;
};

struct PackResult {
    std::vector<std::vector<glm::dvec2>> uv;  // per chart, placed in [0,1]²
    double texelsPerUnit = 0;                 // texel edge lengths per input UV unit
    double footprint = 0;                     // fraction of the square under dilated rasters
};

// Rotation (cos, sin) that turns the smallest-area bounding rectangle of the
// points axis-aligned, wider than tall: p ↦ (c·x + s·y, −s·x + c·y).
glm::dvec2 minAreaRectRotation(const std::vector<glm::dvec2>& uv);

// threads: 2 or more runs two trial densities side by side.
PackResult packCharts(const std::vector<PackChart>& charts, int resolution, int gutterTexels,
                      int threads = 1);

}  // namespace tsis::atlas
