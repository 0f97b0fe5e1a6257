#include "compare/image_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "util/error.h"

namespace tsis {

namespace {

std::string size(const ImageF& i) {
    return concat(i.width, "×", i.height, " with ", i.channels,
                  i.channels == 1 ? " channel" : " channels");
}

}  // namespace

Comparison compareImages(const ImageF& a, const ImageF& b, const ImageF* mask,
                         const std::string& nameA, const std::string& nameB,
                         const std::string& nameMask) {
    if (a.width != b.width || a.height != b.height || a.channels != b.channels)
        fail("cannot compare ", nameA, " (", size(a), ") with ", nameB, " (", size(b), ")");
    if (mask && (mask->width != b.width || mask->height != b.height))
        fail("mask ", nameMask, " is ", mask->width, "×", mask->height, " but ", nameB, " is ",
             b.width, "×", b.height);
    const size_t pixels = static_cast<size_t>(b.width) * b.height;
    const int ch = b.channels;
    auto finite = [&](const ImageF& i, size_t p) {
        for (int c = 0; c < i.channels; ++c)
            if (!std::isfinite(i.pixels[p * i.channels + c])) return false;
        return true;
    };
    // Selected and finite in both; the others selected are counted apart.
    std::vector<char> use(pixels, 0);
    long long selectedCount = 0, nonfiniteA = 0, nonfiniteB = 0;
    for (size_t p = 0; p < pixels; ++p) {
        if (mask && !(mask->pixels[p * mask->channels] > 0.5f)) continue;
        ++selectedCount;
        const bool fa = finite(a, p), fb = finite(b, p);
        nonfiniteA += !fa;
        nonfiniteB += !fb;
        use[p] = fa && fb;
    }
    if (selectedCount == 0) fail("mask ", nameMask, " selects no pixel (none > 0.5)");
    auto selected = [&](size_t p) { return use[p] != 0; };

    // First pass: the statistics of B the others need. Sums in double.
    long long n = 0;
    double sumB = 0, sumAbsB = 0, peak = -std::numeric_limits<double>::infinity();
    for (size_t p = 0; p < pixels; ++p) {
        if (!selected(p)) continue;
        ++n;
        for (int c = 0; c < ch; ++c) {
            const double v = b.pixels[p * ch + c];
            sumB += v;
            sumAbsB += std::abs(v);
            peak = std::max(peak, v);
        }
    }
    if (n == 0)
        fail("no pixel to compare: every selected pixel holds NaN or ∞ (", nameA, ": ", nonfiniteA,
             ", ", nameB, ": ", nonfiniteB, " of ", selectedCount, ")");
    const double values = static_cast<double>(n) * ch;
    const double floor = kRelErrorFloor * sumAbsB / values;

    Comparison out;
    out.relError.width = b.width;
    out.relError.height = b.height;
    out.relError.channels = 1;
    out.relError.pixels.assign(pixels, -1.0f);
    double sq = 0, rel = 0, maxAbs = 0;
    for (size_t p = 0; p < pixels; ++p) {
        if (!selected(p)) continue;
        double pixelRel = 0;
        for (int c = 0; c < ch; ++c) {
            const double va = a.pixels[p * ch + c], vb = b.pixels[p * ch + c];
            const double d = std::abs(va - vb);
            sq += d * d;
            maxAbs = std::max(maxAbs, d);
            // floor can be 0 (B all zero): then 0/0 counts as no error.
            const double den = std::max(std::abs(vb), floor);
            const double r =
                den > 0 ? d / den : (d > 0 ? std::numeric_limits<double>::infinity() : 0.0);
            rel += r;
            pixelRel += r;
        }
        out.relError.pixels[p] = static_cast<float>(pixelRel / ch);
    }
    CompareMetrics& m = out.metrics;
    m.pixels = n;
    m.nonfiniteA = nonfiniteA;
    m.nonfiniteB = nonfiniteB;
    m.rmse = std::sqrt(sq / values);
    const double meanB = sumB / values;
    m.relRmse = meanB != 0 ? m.rmse / meanB : std::numeric_limits<double>::quiet_NaN();
    m.meanRelErr = rel / values;
    m.maxAbs = maxAbs;
    m.psnr =
        m.rmse > 0 ? 20.0 * std::log10(peak / m.rmse) : std::numeric_limits<double>::infinity();
    return out;
}

Json compareJson(const CompareMetrics& m) {
    Json j = Json::object();
    j["rmse"] = m.rmse;
    j["rel_rmse"] = m.relRmse;
    j["mean_rel_err"] = m.meanRelErr;
    j["max_abs"] = m.maxAbs;
    j["psnr"] = m.psnr;
    j["pixels"] = m.pixels;
    j["nonfinite_a"] = m.nonfiniteA;
    j["nonfinite_b"] = m.nonfiniteB;
    return j;
}

std::string compareTable(const CompareMetrics& m) {
    char buf[512];
    std::snprintf(buf, sizeof buf,
                  "pixels        %lld\n"
                  "rmse          %.6g\n"
                  "rel_rmse      %.4f%%  (rmse / mean of the reference B)\n"
                  "mean_rel_err  %.4f%%\n"
                  "max_abs       %.6g\n"
                  "psnr          %.2f dB\n",
                  m.pixels, m.rmse, 100.0 * m.relRmse, 100.0 * m.meanRelErr, m.maxAbs, m.psnr);
    std::string table = buf;
    if (m.nonfiniteA + m.nonfiniteB > 0)
        table += concat("nonfinite     A ", m.nonfiniteA, ", B ", m.nonfiniteB,
                        " pixels (NaN or ∞; left out)\n");
    return table;
}

std::vector<char> interiorPixels(const ImageF& coverage) {
    const int w = coverage.width, h = coverage.height;
    auto covered = [&](int x, int y) {
        return x >= 0 && y >= 0 && x < w && y < h && coverage.at(x, y, 0) > 0.5f;
    };
    std::vector<char> mask(static_cast<size_t>(w) * h, 0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            mask[static_cast<size_t>(y) * w + x] = covered(x, y) && covered(x - 1, y) &&
                                                   covered(x + 1, y) && covered(x, y - 1) &&
                                                   covered(x, y + 1);
    return mask;
}

}  // namespace tsis
