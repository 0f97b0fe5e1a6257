#include "cli/compare_command.h"

#include <filesystem>
#include <iostream>

#include "compare/heatmap.h"
#include "compare/image_compare.h"
#include "image/image_io.h"
#include "util/args.h"
#include "util/error.h"
#include "util/input_file.h"
#include "util/output_set.h"

namespace tsis {

namespace {

constexpr const char* kAbout = R"(
Compares image A with the reference B (EXR, or anything OpenImageIO reads) over
the pixels of --mask (> 0.5; all pixels without it), every channel:
  rmse          root mean square of A − B
  rel_rmse      rmse / mean of B (B is the reference)
  mean_rel_err  mean of |A − B| / max(|B|, 0.001 · mean |B|)
  max_abs       largest |A − B|
  psnr          20 log10(max of B / rmse), dB
  pixels        pixels compared
A pixel with a NaN or ∞ (in any channel, of A or of B) is left out of the
metrics and counted (nonfinite_a, nonfinite_b); any such pixel fails the
comparison (exit 1) unless --allow-nonfinite is given.
)";

ImageF readInput(const std::string& path, const char* what) {
    if (!std::filesystem::exists(path)) fail(what, " '", path, "' does not exist");
    requireRegularFile(path, what);  // a FIFO or /dev/zero would hang the image reader
    return readImageF(path);
}

}  // namespace

int runCompare(const std::vector<std::string>& argv) {
    const std::vector<OptionSpec> specs = {
        {"mask", true, false,
         "FILE  compare only pixels where FILE's first channel > 0.5 (e.g. coverage.exr)"},
        {"heatmap", true, false, "FILE.png  false-colour relative error with a legend"},
        {"heat-max", true, false,
         "X  relative error at the top of the heat map's scale (default: a round value ≥ the 99th "
         "percentile)"},
        {"json", false, false, "print the metrics as JSON"},
        {"allow-nonfinite", false, false,
         "pixels with NaN or ∞ do not fail the comparison (they stay out of the metrics)"},
    };
    bool help = false;
    for (const std::string& a : argv) help = help || a == "--help" || a == "-h";
    if (help) {
        std::cout << usageText("tsis compare A.exr B.exr [options]", specs) << kAbout;
        return 0;
    }
    Args args("compare", specs, argv);
    if (args.positional().size() != 2)
        fail("compare takes two images, A and the reference B (got ", args.positional().size(),
             ")");
    const std::string pathA = args.positional()[0], pathB = args.positional()[1];
    const auto heatPath = args.value("heatmap");
    const double heatMax = args.has("heat-max") ? args.getDouble("heat-max", 0, 1e-9, 1e9) : 0;
    OutputSet outputs;
    if (heatPath) {
        if (*heatPath == "-") fail("--heatmap '-': standard output is for the metrics");
        outputs.add(*heatPath, ".png");
        requireImageFormat(outputs, *heatPath);
    }
    const ImageF a = readInput(pathA, "image"), b = readInput(pathB, "reference image");
    ImageF mask;
    const auto maskPath = args.value("mask");
    if (maskPath) mask = readInput(*maskPath, "mask");
    const Comparison cmp =
        compareImages(a, b, maskPath ? &mask : nullptr, pathA, pathB, maskPath.value_or(""));
    std::cout << (args.flag("json") ? dumpJson(compareJson(cmp.metrics)) + "\n"
                                    : compareTable(cmp.metrics));
    const CompareMetrics& m = cmp.metrics;
    if (m.nonfiniteA + m.nonfiniteB > 0 && !args.flag("allow-nonfinite")) {
        std::cout.flush();
        fail("pixels with NaN or ∞: ", m.nonfiniteA, " in ", pathA, ", ", m.nonfiniteB, " in ",
             pathB, " (left out of the metrics; --allow-nonfinite accepts them)");
    }
    if (heatPath) {
        const double scale = heatMax > 0 ? heatMax : heatmapScale(cmp.relError);
        const Heatmap hm = renderHeatmap(cmp.relError, scale);
        outputs.write(*heatPath, [&](const std::filesystem::path& f) {
            writeImage8(f.string(), hm.width, hm.height, 3, hm.rgb);
        });
        outputs.commit();
        if (!args.flag("json"))
            std::cout << "heat map      " << *heatPath << " (scale 0 to " << 100 * scale
                      << "% relative error)\n";
    }
    return 0;
}

}  // namespace tsis
