// Error metrics of an image against a reference, as `tsis compare` prints them
// (rmse, rel_rmse, mean_rel_err, max_abs, psnr over the masked pixels).
#pragma once

#include "tsis/renderer.h"

namespace tsis::api {

struct Metrics {
    double rmse = 0, relRmse = 0, meanRelErr = 0, maxAbs = 0;
    double psnr = 0;  // dB; infinity when the images are equal
    long long pixels = 0;
};

// mask: null for every pixel, else the pixels whose first channel > 0.5 (e.g.
// Frame::coverage). Throws tsis::Error for mismatched sizes or channel counts.
Metrics compare(const Image& image, const Image& reference, const Image* mask = nullptr);

}  // namespace tsis::api
