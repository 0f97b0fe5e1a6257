// Which covered pixels a frame evaluates and which it interpolates. B varies
// over the mean free path ℓ, often many pixels wide: evaluating it on a grid of
// every `stride`-th pixel and interpolating bilinearly in between is exact for
// a field linear across the cell and costs 1/stride² of the evaluations. A
// pixel is interpolated only when all four corners of its grid cell are
// covered and lie within `maxCornerMm` of it in 3D (the same surface, no
// silhouette or depth jump between) and their positions interpolated land
// within a tenth of that of its own (a nearly flat cell); otherwise it tries
// the cell of half the side, whose corners are evaluated for it (down to 2
// pixels), and failing every level it is evaluated itself.
#pragma once

#include <vector>

#include "cl/cl_runtime.h"
#include "render/frame_resources.h"
#include "scene/scene.h"
#include "tsis_shared.h"

namespace tsis {

// The default grid: spacing ≤ kSparseGridSpacing·ℓ, at most kSparseMaxAutoStride.
constexpr int kSparseMaxAutoStride = 4;
constexpr double kSparseGridSpacing = 0.25;
// Corners within this·ℓ in 3D and within 2 frontal cell diagonals.
constexpr double kSparseMaxCornerEll = 0.5;

// The grid over cells (pixels or texels) of side cellMm: its stride
// (`stride`, or by the mean free path ℓ when ≤ 0) and how far a cell's
// corners may be (planSparsePixels' maxCornerMm).
struct SparseGrid {
    int stride;
    float maxCornerMm;
};
SparseGrid sparseGridFor(double cellMm, double ell, int stride);

// A pixel's side at the camera target's distance (mm).
double pixelMm(const Camera& camera, int height);

struct SparsePixels {
    // Indices into the packed covered points to evaluate, grouped so runs of
    // 8 are neighbours on screen: the grid's points first, then the rest.
    std::vector<int> evaluate;
    // Packed indices of the point and of its cell's corners, and the weights,
    // by level (cell side stride, stride/2, … 2): level i is
    // interpolate[levelEnds[i-1], levelEnds[i]), its corners evaluated or in
    // a level before it.
    std::vector<TsisInterpolatedPixel> interpolate;
    std::vector<int> levelEnds;
};

// pixels: the GL pixel index (y·width + x) of each packed point, ascending;
// positions: xyz(w) per packed point (4 floats each). stride 1: every point
// is evaluated.
SparsePixels planSparsePixels(const std::vector<int>& pixels, const std::vector<float>& positions,
                              int width, int height, int stride, float maxCornerMm);

// rgba: 4 floats per packed point, the evaluated ones filled; fills the rest
// (in the list's order: level by level). The reference for SparseInterpolation.
void interpolateSparsePixels(const SparsePixels& plan, std::vector<float>& rgba);

// The same on the device (kernels/sparse_pixels.cl), in place in the CL
// buffer the method wrote B to: B does not cross to the host and back.
class SparseInterpolation {
  public:
    explicit SparseInterpolation(ClRuntime& cl);
    // The plan's pixels to the device (blocking: the plan may be gone before
    // the queue runs), kept for the runs after it: those to interpolate, and
    // those to evaluate as order() for the caller's kernel.
    void upload(const SparsePixels& plan);
    // The last upload's points to evaluate (SparsePixels::evaluate), int each.
    const cl::Buffer& order() const { return order_.buffer; }
    // rgba: float4 per packed point, from the last upload. Enqueues without
    // waiting; lastMs() waits.
    void run(cl::Buffer& rgba);
    // Both, for a plan used once.
    void run(const SparsePixels& plan, cl::Buffer& rgba) {
        upload(plan);
        run(rgba);
    }
    // CL profiling: the kernel, and the upload when this run's plan was new.
    double lastMs() const;

  private:
    ClRuntime& cl_;
    cl::Kernel kernel_;
    GrowingBuffer pixels_, order_;
    std::vector<int> levelEnds_;  // the plan's (SparsePixels::levelEnds)
    std::vector<cl::Event> events_;
    bool uploaded_ = false;  // an upload since the last run
};

}  // namespace tsis
