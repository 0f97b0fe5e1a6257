// Error against time: each method's relative RMSE of radiance against
// `--method reference` (over the reference's covered pixels) versus its frame
// time, swept over its quality knob, for three cases. Writes error.{md,csv}
// (bench/plot_error.gp makes error_<case>.png).
#include <cmath>
#include <cstdio>
#include <map>

#include "bench_common.h"
#include "render/method.h"
#include "util/progress.h"

namespace tsis::bench {
namespace {

struct Case {
    const char* id;
    const char* what;
    std::vector<std::string> args;
};

struct Sweep {
    const char* method;
    const char* knob;  // the render option swept
    std::vector<std::string> values;
};

int run(const BenchArgs& a) {
    const std::vector<Case> cases = {
        {"cow_marble_10mm",
         "cow, marble, 10 mm (global translucency matters)",
         {"--mesh", "cow", "--material", "marble", "--size-mm", "10"}},
        {"cow_skin2_30mm",
         "cow, skin2, 30 mm (local-dominated)",
         {"--mesh", "cow", "--material", "skin2", "--size-mm", "30"}},
        {"default_skin1_10mm",
         "builtin:default, skin1, 10 mm, back-lit thin parts",
         {"--mesh", "builtin:default", "--material", "skin1", "--size-mm", "10"}},
    };
    std::vector<Sweep> sweeps = {
        {"tsis", "samples", {"16", "49", "100", "256", "900", "2500", "6400"}},
        {"hybrid", "samples", {"16", "49", "100", "256", "900", "2500"}},
        {"mis", "samples", {"16", "49", "100", "256", "900"}},
        {"hierarchical", "epsilon", {"2", "1", "0.5", "0.2", "0.1", "0.05", "0.02"}},
        {"pyramid", "pyramid-epsilon", {"0.8", "0.4", "0.2", "0.1", "0.05", "0.025"}},
        {"tsm", "tsm-radius", {"1", "2", "4", "8"}},
        {"ltsm", "ltsm-rings", {"1", "2", "4", "8"}},
        {"lss", "samples", {"16", "49", "100", "256", "900"}},
    };
    if (a.quick)
        for (Sweep& s : sweeps) s.values.resize(2);
    const std::vector<std::string> registered = methodNames();
    auto has = [&](const std::string& m) {
        return std::find(registered.begin(), registered.end(), m) != registered.end();
    };
    if (!has("reference")) {
        std::fprintf(stderr, "bench_error: --method reference is not registered; nothing to do\n");
        return 1;
    }
    Renderer renderer;
    const std::string machine = machineLine(renderer);
    Table csv({"case", "method", "knob", "value", "frame_ms_median", "frame_ms_min", "frame_ms_max",
               "rel_rmse", "load1"});
    std::string md =
        "# Error against time\n\nMade by `bench/run.sh error` "
        "(`build-bench/bench/bench_error`) on " +
        timestamp() + ".\nMachine: " + machine +
        ".\nRelative RMSE of radiance L against `--method reference` over its "
        "covered pixels, 512×512, atlas 512² (the thesis' model's, bench_common.h "
        "makeThesisCase), light maps at their default (1024² for these cases), default lights; "
        "frame time = the "
        "whole frame (GL passes, hand-offs, kernels, composite), median of " +
        std::to_string(a.frames) +
        " frames after the frame measured for error. Plots: `error_<case>.png`.\n\n";
    const double thresholds[] = {0.05, 0.02, 0.01};
    for (const Case& cs : cases) {
        BenchCase base = makeThesisCase(cs.args);
        const ReferenceImage ref = renderReference(renderer, base);
        std::map<std::string, std::vector<std::pair<double, double>>> curves;  // (ms, err)
        std::map<std::string, std::vector<std::string>> labels;
        Progress progress(cs.id, 40);
        long long done = 0;
        for (const Sweep& s : sweeps) {
            if (!has(s.method)) continue;
            for (const std::string& v : s.values) {
                std::vector<std::string> args = cs.args;
                args.insert(args.end(), {"--method", s.method, std::string("--") + s.knob, v});
                BenchCase c = makeThesisCase(args);
                c.options.keepAovs = true;
                const double load = loadAverage();
                const double err = relativeRmse(renderer.render(c.scene, c.options), ref);
                c.options.keepAovs = false;
                Summary t = summarize(stageSums(renderFrames(renderer, c, a.frames, 0), {"total"}));
                csv.add({cs.id, s.method, s.knob, v, fmt(t.median), fmt(t.min), fmt(t.max),
                         fmt(err, 5), fmt(load)});
                curves[s.method].push_back({t.median, err});
                labels[s.method].push_back(std::string(s.knob) + "=" + v);
                progress.update(++done);
            }
        }
        progress.finish();
        md += "## " + std::string(cs.what) + "\n\n![error against time](error_" + cs.id +
              ".png)\n\nReference frame: " + fmt(ref.ms / 1000.0, 1) +
              " s. Time for each method to reach a relative RMSE (fastest setting that does; "
              "— none of the settings tried):\n\n";
        Table t({"method", "≤ 5%", "≤ 2%", "≤ 1%", "best error (setting, ms)"});
        for (const Sweep& s : sweeps) {
            if (!curves.count(s.method)) continue;
            const auto& cv = curves[s.method];
            std::vector<std::string> row = {s.method};
            for (double thr : thresholds) {
                int best = -1;
                for (size_t i = 0; i < cv.size(); ++i)
                    if (cv[i].second <= thr && (best < 0 || cv[i].first < cv[best].first))
                        best = static_cast<int>(i);
                row.push_back(best < 0 ? "—"
                                       : fmt(cv[best].first, 0) + " ms (" + labels[s.method][best] +
                                             ")");
            }
            size_t lo = 0;
            for (size_t i = 0; i < cv.size(); ++i)
                if (cv[i].second < cv[lo].second) lo = i;
            row.push_back(fmt(100 * cv[lo].second, 2) + "% (" + labels[s.method][lo] + ", " +
                          fmt(cv[lo].first, 0) + " ms)");
            t.add(row);
        }
        md += t.markdown() + "\n";
    }
    writeResult("error.csv", csv.csv());
    writeResult("error.md", md);
    std::printf("wrote %s/error.{md,csv}\n", resultsDir().c_str());
    return 0;
}

}  // namespace
}  // namespace tsis::bench

int main(int argc, char** argv) {
    return tsis::bench::guardedMain(tsis::bench::run, argc, argv, 3);
}
