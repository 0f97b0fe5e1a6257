#include "compare/image_compare.h"

#include <gtest/gtest.h>

#include <cmath>

#include "util/error.h"

namespace tsis {
namespace {

ImageF image(int w, int h, int ch, std::vector<float> v) {
    ImageF i;
    i.width = w;
    i.height = h;
    i.channels = ch;
    i.pixels = std::move(v);
    return i;
}

TEST(ImageCompare, ExactMetricsOnHandMadeImages) {
    const ImageF b = image(2, 2, 1, {2, 2, 4, 4});
    const ImageF a = image(2, 2, 1, {2, 3, 3, 4});  // differences 0, 1, -1, 0
    const Comparison c = compareImages(a, b, nullptr);
    const CompareMetrics& m = c.metrics;
    EXPECT_EQ(m.pixels, 4);
    EXPECT_DOUBLE_EQ(m.rmse, std::sqrt(0.5));
    EXPECT_DOUBLE_EQ(m.relRmse, std::sqrt(0.5) / 3.0);
    EXPECT_DOUBLE_EQ(m.meanRelErr, (0.5 + 0.25) / 4.0);
    EXPECT_DOUBLE_EQ(m.maxAbs, 1.0);
    EXPECT_NEAR(m.psnr, 20.0 * std::log10(4.0 / std::sqrt(0.5)), 1e-12);
    EXPECT_FLOAT_EQ(c.relError.pixels[1], 0.5f);
    EXPECT_FLOAT_EQ(c.relError.pixels[2], 0.25f);
}

TEST(ImageCompare, MaskSelectsPixelsAboveOneHalf) {
    const ImageF b = image(2, 2, 1, {2, 2, 4, 4});
    const ImageF a = image(2, 2, 1, {2, 3, 3, 4});
    const ImageF mask = image(2, 2, 2, {1, 0, 0.9f, 0, 0.5f, 1, 0.6f, 0});  // channel 0 counts
    const Comparison c = compareImages(a, b, &mask);
    EXPECT_EQ(c.metrics.pixels, 3);
    EXPECT_DOUBLE_EQ(c.metrics.rmse, std::sqrt(1.0 / 3.0));
    EXPECT_DOUBLE_EQ(c.metrics.relRmse, std::sqrt(1.0 / 3.0) / (8.0 / 3.0));
    EXPECT_DOUBLE_EQ(c.metrics.meanRelErr, 0.5 / 3.0);
    EXPECT_EQ(c.relError.pixels[2], -1.0f) << "not selected";
}

TEST(ImageCompare, ChannelsAllCountAndTheFloorGuardsZeros) {
    const ImageF b = image(1, 1, 3, {0, 10, 5});
    const ImageF a = image(1, 1, 3, {0.001f, 10, 4});
    const Comparison c = compareImages(a, b, nullptr);
    EXPECT_EQ(c.metrics.pixels, 1);
    const double floor = kRelErrorFloor * 5.0;  // mean |B| = 5
    EXPECT_NEAR(c.metrics.meanRelErr, (0.001 / floor + 0 + 0.2) / 3.0, 1e-6);
    EXPECT_NEAR(c.metrics.rmse, std::sqrt((1e-6 + 1.0) / 3.0), 1e-7);
    EXPECT_DOUBLE_EQ(c.metrics.maxAbs, 1.0);
}

TEST(ImageCompare, IdenticalImagesHaveInfinitePsnrWrittenAsNull) {
    const ImageF b = image(2, 1, 1, {1, 2});
    const Comparison c = compareImages(b, b, nullptr);
    EXPECT_EQ(c.metrics.rmse, 0.0);
    EXPECT_TRUE(std::isinf(c.metrics.psnr));
    const std::string json = dumpJson(compareJson(c.metrics));
    EXPECT_NE(json.find("\"psnr\": null"), std::string::npos) << json;
}

TEST(ImageCompare, JsonHasExactlyTheDocumentedKeys) {
    const std::string json = compareJson(CompareMetrics{}).dump(0);
    size_t keys = 0;
    for (size_t p = 0; (p = json.find("\":", p)) != std::string::npos; ++p) ++keys;
    EXPECT_EQ(keys, 8u) << json;
    for (const char* k : {"\"rmse\"", "\"rel_rmse\"", "\"mean_rel_err\"", "\"max_abs\"", "\"psnr\"",
                          "\"pixels\"", "\"nonfinite_a\"", "\"nonfinite_b\""})
        EXPECT_NE(json.find(k), std::string::npos) << k;
}

// A NaN or ∞ is counted and left out; it never reads as "no difference".
TEST(ImageCompare, NonFinitePixelsAreCountedAndLeftOut) {
    const float nan = std::nanf(""), inf = INFINITY;
    const ImageF b = image(2, 2, 1, {2, 2, 4, inf});
    const ImageF a = image(2, 2, 1, {2, nan, 3, 4});
    const Comparison c = compareImages(a, b, nullptr);
    EXPECT_EQ(c.metrics.pixels, 2);
    EXPECT_EQ(c.metrics.nonfiniteA, 1);
    EXPECT_EQ(c.metrics.nonfiniteB, 1);
    EXPECT_DOUBLE_EQ(c.metrics.maxAbs, 1.0);
    EXPECT_DOUBLE_EQ(c.metrics.rmse, std::sqrt(0.5));
    EXPECT_EQ(c.relError.pixels[1], -1.0f) << "left out";
    EXPECT_NE(compareTable(c.metrics).find("nonfinite     A 1, B 1"), std::string::npos);
    const ImageF clean = image(1, 1, 1, {1});
    EXPECT_EQ(compareTable(compareImages(clean, clean, nullptr).metrics).find("nonfinite"),
              std::string::npos);
}

TEST(ImageCompare, AllNonFiniteIsAnErrorNotAPerfectMatch) {
    const float nan = std::nanf("");
    const ImageF a = image(2, 1, 1, {nan, nan});
    try {
        compareImages(a, image(2, 1, 1, {1, 2}), nullptr, "a.exr", "b.exr");
        FAIL() << "an all-NaN image compared";
    } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("no pixel to compare"), std::string::npos) << m;
        EXPECT_NE(m.find("a.exr: 2"), std::string::npos) << m;
    }
}

TEST(ImageCompare, MismatchesAreOneLineErrorsNamingTheFiles) {
    const ImageF b = image(2, 2, 1, {1, 1, 1, 1});
    auto message = [](auto&& f) {
        try {
            f();
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    std::string e = message([&] {
        compareImages(image(2, 1, 1, {1, 1}), b, nullptr, "a.exr", "b.exr");
    });
    EXPECT_NE(e.find("a.exr (2×1 with 1 channel)"), std::string::npos) << e;
    EXPECT_NE(e.find("b.exr (2×2"), std::string::npos) << e;
    e = message([&] { compareImages(image(1, 1, 3, {1, 1, 1}), image(1, 1, 1, {1}), nullptr); });
    EXPECT_NE(e.find("3 channels"), std::string::npos) << e;
    const ImageF smallMask = image(1, 1, 1, {1});
    e = message([&] { compareImages(b, b, &smallMask, "a", "b", "m.exr"); });
    EXPECT_NE(e.find("m.exr is 1×1"), std::string::npos) << e;
    const ImageF emptyMask = image(2, 2, 1, {0, 0.5f, 0, 0});
    e = message([&] { compareImages(b, b, &emptyMask, "a", "b", "m.exr"); });
    EXPECT_NE(e.find("selects no pixel"), std::string::npos) << e;
    EXPECT_EQ(e.find('\n'), std::string::npos);
}

}  // namespace
}  // namespace tsis
