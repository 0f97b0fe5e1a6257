// A false-colour picture of per-pixel relative error (`tsis compare
// --heatmap`): viridis from 0 (dark blue) to the scale's maximum (yellow;
// larger errors saturate), pixels outside the mask grey, and below the image a
// legend: the colour bar, ticks at 0, ¼, ½, ¾ and 1 of the scale, and the
// values at 0, ½ and 1 written in percent (the last with a "+": saturated).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "image/image_io.h"

namespace tsis {

struct Heatmap {
    int width = 0, height = 0;
    std::vector<uint8_t> rgb;  // row 0 = top
    double scaleMax = 0;       // relative error shown at the top of the bar
};

// Viridis at t in [0, 1] (clamped), piecewise linear through 9 of its colours.
std::array<uint8_t, 3> heatColour(double t);

// The smallest of {1, 2, 2.5, 5}·10^k at or above the 99th percentile of the
// selected (≥ 0) values, at least 1e-4 (0.01%).
double heatmapScale(const ImageF& relError);

// relError: one channel, < 0 where not selected (image_compare.h's Comparison).
Heatmap renderHeatmap(const ImageF& relError, double scaleMax);

}  // namespace tsis
