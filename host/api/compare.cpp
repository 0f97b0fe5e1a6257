#include "tsis/compare.h"

#include "compare/image_compare.h"

namespace tsis::api {

namespace {

ImageF toInternal(const Image& i) {
    return {i.width, i.height, i.channels, i.pixels};
}

}  // namespace

Metrics compare(const Image& image, const Image& reference, const Image* mask) {
    const ImageF m = mask ? toInternal(*mask) : ImageF();
    const CompareMetrics c = compareImages(toInternal(image), toInternal(reference),
                                           mask ? &m : nullptr, "image", "reference", "mask")
                                 .metrics;
    return {c.rmse, c.relRmse, c.meanRelErr, c.maxAbs,
            c.psnr, c.pixels,  c.nonfiniteA, c.nonfiniteB};
}

}  // namespace tsis::api
