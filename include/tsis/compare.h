// Error metrics of an image against a reference, as `tsis compare` prints them
// (rmse, rel_rmse, mean_rel_err, max_abs, psnr over the masked pixels whose
// values are finite in both, and how many selected pixels hold NaN or ∞).
#pragma once

#include "tsis/renderer.h"

namespace tsis::api {

struct Metrics {
    double rmse = 0, relRmse = 0, meanRelErr = 0, maxAbs = 0;
    double psnr = 0;  // dB; infinity when the images are equal
    long long pixels = 0;
    // Selected pixels left out for NaN or ∞ in the image / the reference
    // (`tsis compare` fails on any unless --allow-nonfinite).
    long long nonfiniteImage = 0, nonfiniteReference = 0;
};

// The largest images compare takes (checked before anything is copied from
// Python): 2^26 pixels, the largest frame tsis renders (8192²), at most
// 65536 on a side, 1 to 4 channels.
constexpr long long kMaxComparePixels = 1LL << 26;
constexpr long long kMaxCompareSide = 65536;
constexpr int kMaxCompareChannels = 4;

// mask: null for every pixel, else the pixels whose first channel > 0.5 (e.g.
// Frame::coverage). Throws tsis::Error for mismatched sizes or channel counts,
// images past the limits above or whose pixels do not fill width × height ×
// channels, and when no selected pixel is finite in both.
Metrics compare(const Image& image, const Image& reference, const Image* mask = nullptr);

}  // namespace tsis::api
