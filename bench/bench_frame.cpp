// The whole frame with the light moving, stage by stage (the real-time issue):
// for the default scene, cow and bunny00 at 512², the light orbits the object
// (as `tsis animate --orbit`), one step per frame, so nothing is reused. Per
// stage the median, min and max over the frames, for two configurations in
// the same run:
//   * "start": the defaults this work started from — tsis, N = 900, atlas and
//     light maps 1024²;
//   * "now": today's defaults (pyramid, atlas and light-map resolutions of
//     RenderOptions);
// each with its relative RMSE against --method reference on the first frame's
// lighting. With TSIS_BEFORE=/path/to/an/older/tsis, that binary's
// `animate --orbit` whole-frame times are measured too (its own code, same
// machine, same run). Writes frame.{md,csv}.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <sstream>

#include "bench_common.h"
#include "util/progress.h"

namespace tsis::bench {
namespace {

struct Config {
    const char* name;
    std::vector<std::string> args;
    bool cameraMoves = false;  // the camera orbits instead of the light (lighting reused)
};

// The lights (as tsis animate --orbit), or the camera, turned by 2π·f/frames about y.
Scene orbit(const Scene& base, int f, int frames, bool camera) {
    Scene s = base;
    const glm::mat4 rot = glm::rotate(glm::mat4(1.0f), static_cast<float>(2.0 * M_PI * f / frames),
                                      glm::vec3(0.0f, 1.0f, 0.0f));
    auto turn = [&](const glm::vec3& v) { return glm::vec3(rot * glm::vec4(v, 0.0f)); };
    if (camera) {
        s.camera.eye = s.camera.target + turn(base.camera.eye - base.camera.target);
        return s;
    }
    for (size_t i = 0; i < s.lights.size(); ++i) s.lights[i].vec = turn(base.lights[i].vec);
    return s;
}

// Whole-frame ms of an external tsis binary's `animate --orbit` (its stats'
// per-frame render_ms, the first frame left out); empty when it fails.
std::vector<double> externalOrbit(const std::string& binary, const std::vector<std::string>& args,
                                  int frames) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("tsis-bench-frame-" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    std::string cmd = "'" + binary + "' animate --orbit --frames " + std::to_string(frames + 1);
    for (const std::string& a : args) cmd += " '" + a + "'";
    cmd += " -o '" + dir.string() + "' --stats '" + (dir / "s.json").string() + "' 2>/dev/null";
    std::vector<double> ms;
    if (std::system(cmd.c_str()) == 0) {
        std::ifstream in(dir / "s.json");
        const Json stats = Json::parse(in, nullptr, false);
        if (!stats.is_discarded() && stats.contains("per_frame"))
            for (const Json& f : stats["per_frame"])
                ms.push_back(f.value("render_ms", std::nan("")));
        if (!ms.empty()) ms.erase(ms.begin());
    }
    std::filesystem::remove_all(dir);
    return ms;
}

int run(const BenchArgs& a) {
    std::vector<std::string> meshes = {"builtin:default", "cow", "bunny00"};
    if (a.quick) meshes.resize(1);
    const std::vector<Config> configs = {
        {"start",
         {"--method", "tsis", "--samples", "900", "--atlas-res", "1024", "--light-res", "1024"}},
        {"now", {}},
        {"now, camera moving", {}, true},
    };
    const char* before = std::getenv("TSIS_BEFORE");
    Renderer renderer;
    const std::string machine = machineLine(renderer);
    Table csv({"scene", "config", "stage", "ms_median", "ms_min", "ms_max", "frames", "rel_rmse",
               "load1"});
    std::string md =
        "# The frame with the light moving\n\nMade by `bench/run.sh frame` "
        "(`build-bench/bench/bench_frame`) on " +
        timestamp() + ".\nMachine: " + machine +
        ".\n512×512, default lights and camera; the light orbits the object one step a frame ("
        "as `tsis animate --orbit`), so the light maps, the flux atlas and everything after them "
        "are made every frame. Per stage: median (min–max) ms over " +
        std::to_string(a.frames) +
        " frames after one warm-up frame. GL stages are host time around glFinish; CL stages are "
        "OpenCL profiling times. *start* = the defaults this work began from (tsis, N = 900, "
        "atlas and light maps 1024²); *now* = today's defaults (`tsis render` with no options: "
        "pyramid); *now, camera moving* = the same, the camera orbiting instead of the light, "
        "so the light maps and the flux atlas are reused (the method's passes still run). rel. "
        "RMSE = radiance against `--method reference` on the first frame's view and "
        "lighting.\n";
    Progress progress("frame", static_cast<long long>(meshes.size() * configs.size()));
    long long done = 0;
    for (const std::string& mesh : meshes) {
        const std::vector<std::string> sceneArgs = {"--mesh", mesh};
        BenchCase refCase = makeCase(sceneArgs);
        const ReferenceImage ref = renderReference(renderer, refCase);
        std::map<std::string, std::vector<std::string>> cells;  // stage -> one cell per config
        std::vector<std::string> stageOrder;
        std::string line = "\n## " + mesh + "\n\n";
        std::vector<std::string> errors, totals;
        for (size_t ci = 0; ci < configs.size(); ++ci) {
            std::vector<std::string> args = sceneArgs;
            args.insert(args.end(), configs[ci].args.begin(), configs[ci].args.end());
            BenchCase c = makeCase(args);
            c.options.reuseLighting = configs[ci].cameraMoves;
            const double load = loadAverage();
            c.options.keepAovs = true;
            const double err = relativeRmse(renderer.render(c.scene, c.options), ref);
            c.options.keepAovs = false;
            std::vector<FrameStats> frames;
            for (int f = 0; f < a.frames; ++f)
                frames.push_back(
                    renderer
                        .render(orbit(c.scene, f + 1, a.frames + 1, configs[ci].cameraMoves),
                                c.options)
                        .stats);
            for (const FrameStats::Stage& st : frames.back().stages) {
                const std::string& stage = st.name;
                const Summary s = summarize(stageSums(frames, {stage}));
                if (!cells.count(stage)) {
                    stageOrder.push_back(stage);
                    cells[stage].assign(configs.size(), "—");
                }
                cells[stage][ci] = fmtRange(s, 1);
                csv.add({mesh, configs[ci].name, stage, fmt(s.median), fmt(s.min), fmt(s.max),
                         std::to_string(s.count), fmt(err, 5), fmt(load)});
                if (stage == "total") totals.push_back(fmt(s.median, 1));
            }
            errors.push_back(fmt(100 * err, 2) + "%");
            progress.update(++done);
        }
        // Stages in frame order; the total last.
        std::stable_partition(stageOrder.begin(), stageOrder.end(),
                              [](const std::string& s) { return s != "total"; });
        Table t({"stage", "start ms", "now ms", "now, camera moving ms"});
        for (const std::string& s : stageOrder) t.add({s, cells[s][0], cells[s][1], cells[s][2]});
        t.add({"rel. RMSE vs reference", errors[0], errors[1], errors[2]});
        line += t.markdown();
        if (before) {
            const std::vector<double> ext = externalOrbit(before, {"--mesh", mesh}, a.frames);
            if (!ext.empty()) {
                const Summary s = summarize(ext);
                line += "\nThe older binary `" + std::string(before) +
                        "` (its own defaults, `animate --orbit`, whole frame): " + fmtRange(s, 1) +
                        " ms.\n";
                csv.add({mesh, "before-binary", "total", fmt(s.median), fmt(s.min), fmt(s.max),
                         std::to_string(s.count), "", fmt(loadAverage())});
            }
        }
        md += line;
    }
    progress.finish();
    writeResult("frame.md", md);
    writeResult("frame.csv", csv.csv());
    std::printf("%s", md.c_str());
    return 0;
}

}  // namespace
}  // namespace tsis::bench

int main(int argc, char** argv) {
    return tsis::bench::guardedMain(tsis::bench::run, argc, argv, 30);
}
