// The frame's model error as a number (tsis render --truth-check, the
// viewer's `truth` command): the model's radiance without the surface
// reflection against --method volumetric's at the same view, both at the
// pixels' centres (--aa 1). The volumetric time is split between two seeds,
// so the reference's own noise follows from their difference and is taken
// out of the error in quadrature.
#pragma once

#include "render/renderer.h"

namespace tsis {

struct TruthCheck {
    double relRmse = 0;     // pooled sqrt(Σ(model − truth)² / Σ truth²), covered pixels
    double noise = 0;       // the reference's (the two seeds' mean), same units
    double subtracted = 0;  // sqrt(max(0, relRmse² − noise²))
    double seconds = 0;     // of volumetric paths
    int pixels = 0;
};

// `seconds` of volumetric paths in all (at least one pass per seed).
TruthCheck truthCheck(Renderer& renderer, const Scene& scene, RenderOptions options,
                      double seconds);

// Pooled rel. RMSE of `model` against the mean of `a` and `b` over `coverage`
// (> 0.5), with the mean's noise |a − b|/2 per pixel (rgb images).
TruthCheck pooledError(const ImageF& model, const ImageF& a, const ImageF& b,
                       const ImageF& coverage);

}  // namespace tsis
