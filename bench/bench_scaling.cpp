// Scaling of tsis at fixed everything else (marble, 10 mm, default lights):
//   * integration (gather) time against triangle count, N = 900, 512²: the
//     method's claim is that it does not grow with the mesh;
//   * against pixel count (128² … 1024², cow, N = 900);
//   * against atlas resolution (16² … 1024², cow, N = 900; thesis Fig. 4.6)
//     with the relative RMSE against --method reference.
// Against N: see tables.csv. Writes scaling.{md,csv}.
#include <cstdio>

#include "bench_common.h"
#include "util/progress.h"

namespace tsis::bench {
namespace {

const std::vector<std::string> kPre = {"gl_flux_atlas", "gl_to_cl_flux_atlas",
                                       "gl_to_cl_position_atlas", "cdf", "sample"};

int run(const BenchArgs& a) {
    std::vector<std::string> meshes = {"head",           "elephant",  "cow",
                                       "fandisk",        "lion-head", "ChineseDragon-10kv",
                                       "builtin:sphere", "armadillo", "bunny00"};
    std::vector<int> sizes = {128, 256, 512, 768, 1024};
    std::vector<int> atlases = {16, 32, 64, 128, 256, 512, 1024};
    if (a.quick) {
        meshes = {"head", "cow"};
        sizes = {256, 512};
        atlases = {64, 1024};
    }
    Renderer renderer;
    const std::string machine = machineLine(renderer);
    Table csv({"sweep", "mesh", "triangles", "width", "atlas", "covered_pixels", "gather_ms_median",
               "gather_ms_min", "gather_ms_max", "ns_per_evaluation", "preprocessing_ms_median",
               "frame_ms_median", "rel_rmse", "load1"});
    Table mdTri({"mesh", "triangles", "covered pixels", "gather ms", "ns / evaluation",
                 "preprocessing ms", "frame ms"});
    Table mdPix({"pixels", "covered", "gather ms", "ns / evaluation", "frame ms"});
    Table mdAtlas({"atlas", "preprocessing ms", "cdf ms", "gather ms", "rel. RMSE"});
    Progress progress("scaling",
                      static_cast<long long>(meshes.size() + sizes.size() + atlases.size()));
    long long done = 0;
    auto measure = [&](const std::string& sweep, BenchCase& c, const std::string& mesh,
                       const ReferenceImage* ref) {
        const double load = loadAverage();
        double err = -1;
        if (ref) {
            c.options.keepAovs = true;
            err = relativeRmse(renderer.render(c.scene, c.options), *ref);
            c.options.keepAovs = false;
        }
        std::vector<FrameStats> fs = renderFrames(renderer, c, a.frames, ref ? 0 : 1);
        Summary g = summarize(stageSums(fs, {"gather"}));
        Summary pre = summarize(stageSums(fs, kPre));
        Summary cdf = summarize(stageSums(fs, {"cdf"}));
        Summary frame = summarize(stageSums(fs, {"total"}));
        const double covered = fs.back().number("covered_pixels");
        const double nsPerEval = 1e6 * g.median / (covered * c.options.samples);
        const std::string tris = std::to_string(c.scene.mesh.triangles.size());
        csv.add({sweep, mesh, tris, std::to_string(c.options.width),
                 std::to_string(c.options.atlasResolution), fmt(covered, 0), fmt(g.median),
                 fmt(g.min), fmt(g.max), fmt(nsPerEval, 3), fmt(pre.median), fmt(frame.median),
                 err < 0 ? "" : fmt(err, 5), fmt(load)});
        if (sweep == "triangles")
            mdTri.add({mesh, tris, fmt(covered, 0), fmtRange(g, 1), fmt(nsPerEval, 2),
                       fmt(pre.median, 1), fmt(frame.median, 0)});
        else if (sweep == "pixels")
            mdPix.add({std::to_string(c.options.width) + "²", fmt(covered, 0), fmtRange(g, 1),
                       fmt(nsPerEval, 2), fmt(frame.median, 0)});
        else
            mdAtlas.add({std::to_string(c.options.atlasResolution) + "²", fmtRange(pre, 1),
                         fmt(cdf.median, 2), fmt(g.median, 1), fmt(100 * err, 2) + "%"});
        progress.update(++done);
    };
    for (const std::string& mesh : meshes) {
        BenchCase c = makeThesisCase({"--mesh", mesh, "--material", "marble"});
        measure("triangles", c, mesh, nullptr);
    }
    BenchCase cow = makeThesisCase({"--mesh", "cow", "--material", "marble"});
    for (int s : sizes) {
        BenchCase c = cow;
        c.options.width = c.options.height = s;
        measure("pixels", c, "cow", nullptr);
    }
    const ReferenceImage ref = renderReference(renderer, cow);
    // The same parameterisation (made for 1024²) rasterised at each resolution,
    // as in Fig. 4.6; a chart layout packed for 16² texels does not exist.
    for (int r : atlases) {
        BenchCase c = cow;
        c.options.atlasResolution = r;
        measure("atlas", c, "cow", &ref);
    }
    progress.finish();
    std::string text =
        "# Scaling (tsis, marble, 10 mm, N = 900)\n\nMade by `bench/run.sh "
        "scaling` (`build-bench/bench/bench_scaling`) on " +
        timestamp() + ".\nMachine: " + machine + ".\nMedian (min–max) of " +
        std::to_string(a.frames) +
        " frames; load average per row in scaling.csv. Plots: scaling_*.png.\n\n";
    text +=
        "## Against triangle count (512², atlas 1024²)\n\nThe gather costs covered pixels "
        "× N evaluations whatever the mesh: ns per evaluation is the figure to compare.\n\n" +
        mdTri.markdown() + "\n## Against pixel count (cow)\n\n" + mdPix.markdown() +
        "\n## Against atlas resolution (cow, 512²; error against --method reference)\n\n" +
        mdAtlas.markdown();
    writeResult("scaling.csv", csv.csv());
    writeResult("scaling.md", text);
    std::printf("%s", text.c_str());
    return 0;
}

}  // namespace
}  // namespace tsis::bench

int main(int argc, char** argv) {
    return tsis::bench::guardedMain(tsis::bench::run, argc, argv, 3);
}
