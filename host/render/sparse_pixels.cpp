#include "render/sparse_pixels.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec3.hpp>

#include "cl/flux_tree.h"
#include "cl/launch.h"
#include "util/error.h"

namespace tsis {

SparseGrid sparseGridFor(double cellMm, double ell, int stride) {
    if (stride <= 0) {
        stride = 1;
        while (stride < kSparseMaxAutoStride && 2 * stride * cellMm <= kSparseGridSpacing * ell)
            stride *= 2;
    }
    // Corners farther than twice a frontal cell's diagonal: a grazing or broken
    // surface, where B changes faster across the cell than the grid assumes.
    const double cellDiagonal = std::sqrt(2.0) * stride * cellMm;
    return {stride, static_cast<float>(std::min(kSparseMaxCornerEll * ell, 2 * cellDiagonal))};
}

double pixelMm(const Camera& camera, int height) {
    return 2.0 * std::tan(glm::radians(double(camera.fovYDegrees)) / 2) *
           glm::length(camera.eye - camera.target) / height;
}

namespace {

constexpr float kFlatness = 0.1f;  // of maxCornerMm

// Barycentric weights of (fx, fy) in the unit cell's triangle without corner
// `missing` (0 (0,0), 1 (1,0), 2 (0,1), 3 (1,1)); one is negative outside it.
std::array<float, 4> triangleWeights(int missing, float fx, float fy) {
    switch (missing) {
        case 0:
            return {0.0f, 1 - fy, 1 - fx, fx + fy - 1};
        case 1:
            return {1 - fy, 0.0f, fy - fx, fx};
        case 2:
            return {1 - fx, fx - fy, 0.0f, fy};
        default:
            return {1 - fx - fy, fx, fy, 0.0f};
    }
}

}  // namespace

SparsePixels planSparsePixels(const std::vector<int>& pixels, const std::vector<float>& positions,
                              int width, int height, int stride, float maxCornerMm) {
    TSIS_CHECK_GE(stride, 1);
    TSIS_CHECK_GE(positions.size(), pixels.size() * 4);
    // Packed index of each pixel, −1 where uncovered.
    std::vector<int> packed(static_cast<size_t>(width) * height, -1);
    for (size_t k = 0; k < pixels.size(); ++k) packed[static_cast<size_t>(pixels[k])] = int(k);
    auto at = [&](int k) {
        const float* p = &positions[static_cast<size_t>(k) * 4];
        return glm::vec3(p[0], p[1], p[2]);
    };
    auto pointAt = [&](int x, int y) {
        return x < width && y < height ? packed[static_cast<size_t>(y) * width + x] : -1;
    };
    // Whether point k is on the grid of every s-th pixel.
    auto onGrid = [&](size_t k, int s) {
        return pixels[k] % width % s == 0 && pixels[k] / width % s == 0;
    };
    enum : char { kPending, kEvaluated, kInterpolated };
    std::vector<char> state(pixels.size(), kPending);

    SparsePixels plan;
    std::vector<int> grid, gridCells, rest, restPixels;
    for (size_t k = 0; k < pixels.size(); ++k) {
        if (onGrid(k, stride)) {
            const int x = pixels[k] % width, y = pixels[k] / width;
            state[k] = kEvaluated;
            grid.push_back(int(k));
            // The grid in its own coordinates, so its tiles are 4×2 grid points.
            gridCells.push_back((y / stride) * ((width + stride - 1) / stride) + x / stride);
        }
    }
    // A pixel whose cell fails at one level tries the cell of half the side,
    // down to 2: its corners evaluated, or interpolated at a level above.
    // Near silhouettes and on curved parts a smaller cell often passes, where
    // evaluating every such pixel cost a third of the frame's evaluations.
    for (int s = stride; s >= 2; s /= 2) {
        if (s < stride)
            for (size_t k = 0; k < pixels.size(); ++k)
                if (state[k] == kPending && onGrid(k, s)) state[k] = kEvaluated;
        for (size_t k = 0; k < pixels.size(); ++k) {
            if (state[k] != kPending) continue;
            const int x = pixels[k] % width, y = pixels[k] / width;
            const int x0 = x - x % s, y0 = y - y % s;
            std::array<int, 4> c = {pointAt(x0, y0), pointAt(x0 + s, y0), pointAt(x0, y0 + s),
                                    pointAt(x0 + s, y0 + s)};
            // A corner interpolated at a coarser level counts: its range of
            // the list is interpolated before this one. One corner off the
            // surface (a silhouette through the cell): the triangle of the
            // other three, where the pixel lies in it.
            int missing = -1, usable = 0;
            for (int j = 0; j < 4; ++j) {
                const int corner = c[size_t(j)];
                if (corner < 0)
                    missing = j;
                else if (state[size_t(corner)] != kPending &&
                         glm::distance(at(corner), at(int(k))) <= maxCornerMm)
                    ++usable;
            }
            const float fx = float(x - x0) / float(s), fy = float(y - y0) / float(s);
            std::array<float, 4> w = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
            if (usable == 3 && missing >= 0) {
                w = triangleWeights(missing, fx, fy);
                if (w[0] < 0 || w[1] < 0 || w[2] < 0 || w[3] < 0) continue;
                c[size_t(missing)] = c[size_t(missing ^ 3)];  // read with weight 0
            } else if (usable < 4) {
                continue;
            }
            // The corners' positions interpolated must land near the pixel's
            // own: the cell is close to flat, so B's interpolation follows the
            // surface.
            glm::vec3 p(0.0f);
            for (int j = 0; j < 4; ++j) p += w[size_t(j)] * at(c[size_t(j)]);
            if (glm::distance(p, at(int(k))) > kFlatness * maxCornerMm) continue;
            plan.interpolate.push_back(
                {int(k), {c[0], c[1], c[2], c[3]}, {w[0], w[1], w[2], w[3]}});
            state[k] = kInterpolated;
        }
        plan.levelEnds.push_back(static_cast<int>(plan.interpolate.size()));
    }
    // The rest, evaluated below the grid's level or in no cell at all, in
    // pixel order (tileOrder's input).
    for (size_t k = 0; k < pixels.size(); ++k) {
        if (state[k] == kInterpolated || onGrid(k, stride)) continue;
        rest.push_back(int(k));
        restPixels.push_back(pixels[k]);
    }
    for (int i : FluxTree::tileOrder(gridCells, (width + stride - 1) / stride))
        plan.evaluate.push_back(grid[static_cast<size_t>(i)]);
    for (int i : FluxTree::tileOrder(restPixels, width))
        plan.evaluate.push_back(rest[static_cast<size_t>(i)]);
    return plan;
}

void interpolateSparsePixels(const SparsePixels& plan, std::vector<float>& rgba) {
    for (const TsisInterpolatedPixel& p : plan.interpolate)
        for (int c = 0; c < 4; ++c) {
            float v = 0;
            for (int j = 0; j < 4; ++j)
                v += p.weights[j] * rgba[static_cast<size_t>(p.corners[j]) * 4 + c];
            rgba[static_cast<size_t>(p.point) * 4 + c] = v;
        }
}

SparseInterpolation::SparseInterpolation(ClRuntime& cl)
    : cl_(cl), kernel_(cl.kernel("sparse_pixels.cl", "tsis_interpolate_sparse")) {}

void SparseInterpolation::upload(const SparsePixels& plan) {
    events_.clear();
    uploaded_ = true;
    const size_t evaluate = plan.evaluate.size() * sizeof(int);
    cl::Buffer& order = order_.reserve(cl_.context(), evaluate);
    if (evaluate > 0)
        cl_.queue().enqueueWriteBuffer(order, CL_TRUE, 0, evaluate, plan.evaluate.data());
    const std::vector<TsisInterpolatedPixel>& p = plan.interpolate;
    levelEnds_ = plan.levelEnds;
    if (p.empty()) return;
    const size_t bytes = p.size() * sizeof(TsisInterpolatedPixel);
    events_.emplace_back();
    cl_.queue().enqueueWriteBuffer(pixels_.reserve(cl_.context(), bytes), CL_TRUE, 0, bytes,
                                   p.data(), nullptr, &events_.back());
}

void SparseInterpolation::run(cl::Buffer& rgba) {
    if (!uploaded_) events_.clear();
    uploaded_ = false;
    // A level's pixels read the ones above: a launch each, in order.
    int begin = 0;
    for (int end : levelEnds_) {
        if (end == begin) continue;
        setKernelArgs(kernel_, pixels_.buffer, begin, end, rgba);
        events_.emplace_back();
        enqueue1D(cl_.queue(), kernel_, size_t(end - begin), kLocalSize, &events_.back());
        begin = end;
    }
}

double SparseInterpolation::lastMs() const {
    return eventMilliseconds(events_);
}

}  // namespace tsis
