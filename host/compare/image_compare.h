// Error metrics of an image A against a reference B (`tsis compare`), over the
// pixels a mask selects. Every metric runs over all channels of the selected
// pixels (n values):
//   rmse          √(Σ (a − b)² / n)
//   rel_rmse      rmse / mean of B            (B is the reference)
//   mean_rel_err  mean of |a − b| / max(|b|, floor), floor = 1e-3 · mean |B|
//                 (pixels where B is ~0 do not dominate)
//   max_abs       max |a − b|
//   psnr          20 log10(max of B / rmse) dB (∞ when A = B)
//   pixels        selected pixels compared (those finite in A and in B)
//   nonfinite_a   selected pixels with a NaN or ∞ in A (left out of the metrics)
//   nonfinite_b   the same in B
// A NaN would otherwise vanish from max_abs and make an all-NaN image a perfect match.
#pragma once

#include <string>

#include "image/image_io.h"
#include "util/json.h"

namespace tsis {

struct CompareMetrics {
    double rmse = 0, relRmse = 0, meanRelErr = 0, maxAbs = 0, psnr = 0;
    long long pixels = 0;
    long long nonfiniteA = 0, nonfiniteB = 0;
};

struct Comparison {
    CompareMetrics metrics;
    // Per pixel: mean over channels of |a − b| / max(|b|, floor); −1 where not selected.
    ImageF relError;
};

// The floor of the relative error's denominator, as a fraction of mean |B|.
constexpr double kRelErrorFloor = 1e-3;

// mask: null for all pixels, else pixels with mask channel 0 > 0.5. Names (file
// paths) appear in the one-line errors for mismatched sizes or channel counts,
// a mask that selects nothing, or no selected pixel finite in both.
Comparison compareImages(const ImageF& a, const ImageF& b, const ImageF* mask,
                         const std::string& nameA = "A", const std::string& nameB = "B",
                         const std::string& nameMask = "mask");

// Keys exactly: rmse, rel_rmse, mean_rel_err, max_abs, psnr (null when ∞), pixels,
// nonfinite_a, nonfinite_b.
Json compareJson(const CompareMetrics& m);

// A short human-readable table (non-finite pixels only when there are some).
std::string compareTable(const CompareMetrics& m);

// The pixels (y·width + x) whose 4-neighbourhood is covered (coverage > 0.5
// in channel 0): where an image of pixel means and one of pixel centres see
// the same surface.
std::vector<char> interiorPixels(const ImageF& coverage);

}  // namespace tsis
