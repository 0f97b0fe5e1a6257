#include "tsis/compare.h"

#include "compare/image_compare.h"
#include "util/error.h"

namespace tsis::api {

namespace {

ImageF toInternal(const Image& i, const char* what) {
    const long long w = i.width, h = i.height, c = i.channels;
    if (w < 1 || h < 1 || c < 1 || c > kMaxCompareChannels || w > kMaxCompareSide ||
        h > kMaxCompareSide || w * h > kMaxComparePixels)
        fail(what, ": ", w, "×", h, "×", c, " is past compare's limits (at most ", kMaxCompareSide,
             " on a side, ", kMaxComparePixels, " pixels, 1 to ", kMaxCompareChannels,
             " channels)");
    if (i.pixels.size() != static_cast<size_t>(w * h * c))
        fail(what, ": ", i.pixels.size(), " values for ", w, "×", h, "×", c);
    return {i.width, i.height, i.channels, i.pixels};
}

}  // namespace

Metrics compare(const Image& image, const Image& reference, const Image* mask) {
    const ImageF m = mask ? toInternal(*mask, "mask") : ImageF();
    const CompareMetrics c =
        compareImages(toInternal(image, "image"), toInternal(reference, "reference"),
                      mask ? &m : nullptr, "image", "reference", "mask")
            .metrics;
    return {c.rmse, c.relRmse, c.meanRelErr, c.maxAbs,
            c.psnr, c.pixels,  c.nonfiniteA, c.nonfiniteB};
}

}  // namespace tsis::api
