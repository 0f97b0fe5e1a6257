// Which covered pixels a frame evaluates and which it interpolates. B varies
// over the mean free path ℓ, often many pixels wide: evaluating it on a grid of
// every `stride`-th pixel and interpolating bilinearly in between is exact for
// a field linear across the cell and costs 1/stride² of the evaluations. A
// pixel is interpolated only when all four corners of its grid cell are
// covered and lie within `maxCornerMm` of it in 3D (the same surface, no
// silhouette or depth jump between) and their positions interpolated land
// within a tenth of that of its own (a nearly flat cell); otherwise it is
// evaluated itself.
#pragma once

#include <array>
#include <vector>

namespace tsis {

struct SparsePixels {
    // Indices into the packed covered points to evaluate, grouped so runs of
    // 8 are neighbours on screen: the grid's points first, then the rest.
    std::vector<int> evaluate;
    struct Interpolated {
        int point;                   // packed index
        std::array<int, 4> corners;  // packed indices of the cell's corners
        std::array<float, 4> weights;
    };
    std::vector<Interpolated> interpolate;
};

// pixels: the GL pixel index (y·width + x) of each packed point, ascending;
// positions: xyz(w) per packed point (4 floats each). stride 1: every point
// is evaluated.
SparsePixels planSparsePixels(const std::vector<int>& pixels, const std::vector<float>& positions,
                              int width, int height, int stride, float maxCornerMm);

// rgba: 4 floats per packed point, the evaluated ones filled; fills the rest.
void interpolateSparsePixels(const SparsePixels& plan, std::vector<float>& rgba);

}  // namespace tsis
