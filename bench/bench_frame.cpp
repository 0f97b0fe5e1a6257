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
//
// Then the composite (issue 21) on the default scene, the camera orbiting:
// its cost without the GGX lobe at one sample, with it, and with --aa 2, 3, 4
// samples per pixel, and each one's silhouette error against --aa 4; with
// TSIS_BEFORE, the older binary's composite stage (`render --frames`) in the
// same run. `bench_frame --composite` measures only this and replaces that
// section of frame.md.
//
// `bench_frame --side-by-side [--frames N] [--stages] [RENDER ARGS…]` (issue 25, for
// bench/eevee_side_by_side.sh) writes nothing: for the scene RENDER ARGS make
// (`--mesh cow --material marble`), today's defaults with the light orbiting
// and with the camera orbiting (lighting reused), N frames each after one
// warm-up frame, it prints one line: `TSIS light_moving_ms=… camera_moving_ms=…
// frames=N gl_renderer=…` (medians of the whole frame, the stage `total`);
// with --stages, each stage's median on stderr too.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <sstream>

#include "bench_common.h"
#include "gl/gpu_mesh.h"
#include "gl/render_target.h"
#include "gl/shader.h"
#include "scene/projection.h"
#include "util/progress.h"
#include "util/timer.h"

namespace tsis::bench {
namespace {

struct Config {
    const char* name;
    std::vector<std::string> args;
    bool cameraMoves = false;  // the camera orbits instead of the light (lighting reused)
};

// What turns about y by 2π·f/frames a frame: the lights (as tsis animate
// --orbit, the environment's sun left to the map), the camera, or the
// environment's map (with its sun).
enum class Motion { Lights, Camera, Environment };

Scene orbit(const Scene& base, int f, int frames, Motion motion) {
    Scene s = base;
    const double degrees = 360.0 * f / frames;
    const glm::mat4 rot = glm::rotate(glm::mat4(1.0f), static_cast<float>(glm::radians(degrees)),
                                      glm::vec3(0.0f, 1.0f, 0.0f));
    auto turn = [&](const glm::vec3& v) { return glm::vec3(rot * glm::vec4(v, 0.0f)); };
    switch (motion) {
        case Motion::Camera:
            s.camera.eye = s.camera.target + turn(base.camera.eye - base.camera.target);
            break;
        case Motion::Lights:
            for (size_t i = 0; i < s.lights.size(); ++i)
                if (!s.lights[i].environment) s.lights[i].vec = turn(base.lights[i].vec);
            break;
        case Motion::Environment:
            s.env.rotateDegrees = base.env.rotateDegrees + degrees;
            applyEnvironment(s);
            break;
    }
    return s;
}

// The stats of `frames` frames of c, the lights (or the camera, or the map)
// a step further round each (steps 1 … frames of frames + 1).
std::vector<FrameStats> orbitFrames(Renderer& renderer, const BenchCase& c, int frames,
                                    Motion motion) {
    std::vector<FrameStats> stats;
    stats.reserve(size_t(frames));
    for (int f = 0; f < frames; ++f)
        stats.push_back(
            renderer.render(orbit(c.scene, f + 1, frames + 1, motion), c.options).stats);
    return stats;
}

std::vector<FrameStats> orbitFrames(Renderer& renderer, const BenchCase& c, int frames,
                                    bool camera) {
    return orbitFrames(renderer, c, frames, camera ? Motion::Camera : Motion::Lights);
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

const char* const kCompositeHeading = "\n## The composite: GGX lobe and antialiasing";

// The silhouette pixels' RMS difference (8-bit levels) between two frames of
// the same view: pixels whose coverage differs from a 4-neighbour's.
double silhouetteRms(const FrameResult& a, const FrameResult& b) {
    const ImageF& cov = a.coverage;
    double sq = 0;
    long n = 0;
    for (int y = 1; y + 1 < cov.height; ++y)
        for (int x = 1; x + 1 < cov.width; ++x) {
            const float c = cov.at(x, y, 0);
            if (cov.at(x - 1, y, 0) == c && cov.at(x + 1, y, 0) == c && cov.at(x, y - 1, 0) == c &&
                cov.at(x, y + 1, 0) == c)
                continue;
            for (int ch = 0; ch < 3; ++ch) {
                const size_t k = (static_cast<size_t>(y) * cov.width + x) * 3 + ch;
                const double d = double(a.rgb8[k]) - double(b.rgb8[k]);
                sq += d * d;
                ++n;
            }
        }
    return n ? std::sqrt(sq / n) : 0;
}

// The older binary's composite stage: `render --frames` (the last, warm frame).
double externalComposite(const std::string& binary, int frames) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                      ("tsis_bench_composite_" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    std::vector<double> ms;
    for (int f = 0; f < frames; ++f) {
        const std::string cmd = "'" + binary + "' render --frames 3 -o '" +
                                (dir / "x.png").string() + "' --stats '" +
                                (dir / "s.json").string() + "' 2>/dev/null";
        if (std::system(cmd.c_str()) != 0) break;
        std::ifstream in(dir / "s.json");
        const Json stats = Json::parse(in, nullptr, false);
        if (!stats.is_discarded() && stats.contains("ms"))
            ms.push_back(stats["ms"].value("composite", std::nan("")));
    }
    std::filesystem::remove_all(dir);
    return ms.empty() ? std::nan("") : summarize(ms).median;
}

std::string compositeSection(Renderer& renderer, int frames) {
    const std::vector<Config> configs = {
        {"no lobe, 1 sample (`--no-specular --aa 1`)", {"--no-specular", "--aa", "1"}, true},
        {"GGX, 1 sample (`--aa 1`)", {"--aa", "1"}, true},
        {"GGX, 1 sample and FXAA at the edge pixels (`--aa-method fxaa`)",
         {"--aa-method", "fxaa"},
         true},
        {"GGX, 2×2 samples (default)", {}, true},
        {"GGX, 3×3 samples (`--aa 3`)", {"--aa", "3"}, true},
        {"GGX, 4×4 samples (`--aa 4`)", {"--aa", "4"}, true},
    };
    std::string md = std::string(kCompositeHeading) + "\n\nMade on " + timestamp() +
                     ". builtin:default, 512×512, the camera orbiting (the G-buffer and the "
                     "composite's samples are rasterised every frame; the light maps are "
                     "reused). Median (min–max) ms over " +
                     std::to_string(frames) +
                     " frames after one warm-up frame; load average (1 min) " +
                     fmt(loadAverage(), 1) +
                     " on 2 cores at the start, so compare the rows, not the absolute ms with "
                     "the tables above. Silhouette RMS: the 8-bit difference from the `--aa 4` "
                     "image on the pixels where the coverage changes, first frame.\n\n";
    Table t({"composite", "gl_gbuffer ms", "gl_composite_samples ms", "composite ms", "total ms",
             "silhouette RMS"});
    std::vector<FrameResult> firsts;
    std::vector<std::vector<std::string>> rows;
    for (const Config& cfg : configs) {
        std::vector<std::string> args = cfg.args;
        BenchCase c = makeCase(args);
        c.options.keepAovs = true;
        firsts.push_back(renderer.render(c.scene, c.options));
        c.options.keepAovs = false;
        const std::vector<FrameStats> stats = orbitFrames(renderer, c, frames, true);
        std::vector<std::string> row = {cfg.name};
        for (const char* stage : {"gl_gbuffer", "gl_composite_samples", "composite", "total"})
            row.push_back(fmtRange(summarize(stageSums(stats, {stage})), 1));
        rows.push_back(row);
    }
    for (size_t i = 0; i < rows.size(); ++i) {
        rows[i].push_back(fmt(silhouetteRms(firsts[i], firsts.back()), 1));
        t.add(rows[i]);
    }
    md += t.markdown();
    if (const char* before = std::getenv("TSIS_BEFORE")) {
        const double ms = externalComposite(before, frames);
        md += "\nThe older binary `" + std::string(before) +
              "` (its own defaults; `render --frames 3`, the last frame, median of " +
              std::to_string(frames) + " runs): composite " + fmt(ms, 1) + " ms.\n";
    }
    return md;
}

// The medians of --side-by-side: the light orbiting, then the camera, and
// with --env the map turning.
int sideBySide(const BenchArgs& a) {
    std::vector<std::string> args;
    for (const std::string& s : a.rest)
        if (s != "--side-by-side") args.push_back(s);
    const bool stages = std::erase(args, "--stages") > 0;
    Renderer renderer;
    const Motion motions[] = {Motion::Lights, Motion::Camera, Motion::Environment};
    const char* names[] = {"light", "camera", "env"};
    double ms[3] = {0, 0, 0};
    for (int m = 0; m < 3; ++m) {
        BenchCase c = makeCase(args);
        if (motions[m] == Motion::Environment && !c.scene.env) break;
        c.options.reuseLighting = motions[m] == Motion::Camera;
        renderer.render(c.scene, c.options);  // warm-up: programs, atlas, first light maps
        const std::vector<FrameStats> frames = orbitFrames(renderer, c, a.frames, motions[m]);
        ms[m] = summarize(stageSums(frames, {"total"})).median;
        // --stages: each stage's median, on stderr (stdout stays one line).
        if (!stages) continue;
        // Every stage any frame ran (the first camera move's differ from the later ones').
        std::vector<std::string> stageNames;
        for (const FrameStats& f : frames)
            for (const FrameStats::Stage& s : f.stages)
                if (std::find(stageNames.begin(), stageNames.end(), s.name) == stageNames.end())
                    stageNames.push_back(s.name);
        for (const std::string& name : stageNames) {
            std::vector<double> cpu;
            for (const FrameStats& f : frames)
                for (const FrameStats::Stage& s : f.stages)
                    if (s.name == name) cpu.push_back(s.cpuMs);
            std::fprintf(stderr, "%s %s %.2f cpu %.2f\n", names[m], name.c_str(),
                         summarize(stageSums(frames, {name})).median,
                         cpu.empty() ? 0.0 : summarize(cpu).median);
        }
    }
    std::printf("TSIS light_moving_ms=%.1f camera_moving_ms=%.1f", ms[0], ms[1]);
    if (ms[2] > 0) std::printf(" env_rotating_ms=%.1f", ms[2]);
    std::printf(" frames=%d gl_renderer=%s\n", a.frames, renderer.glRenderer().c_str());
    return 0;
}

// Median ms of `body` (GL work) over `n` runs, each ended by glFinish.
template <typename F>
double glMs(int n, F body) {
    std::vector<double> ms;
    for (int i = 0; i < n; ++i) {
        const Timer t;
        body();
        glFinish();
        ms.push_back(t.ms());
    }
    return summarize(ms).median;
}

// `bench_frame --gl-floors`: each GL pass of the default scene's frame
// against its floor on this GL — the same targets and triangles with
// constant shaders (gl/shaders/floor.frag), and the clears and read-backs
// alone — in rounds that interleave the two (bench/results/gl_floors.md).
int glFloors(const BenchArgs& a) {
    Renderer renderer;
    BenchCase c = makeCase({});
    const FrameStats first = renderer.render(c.scene, c.options).stats;
    const int lightRes = static_cast<int>(first.number("light_resolution"));
    const int atlasRes = static_cast<int>(first.number("atlas_resolution")), w = c.options.width,
              h = c.options.height, aa = c.options.aa;
    const size_t lights = c.scene.lights.size();
    GlContext gl;
    const ShaderProgram depthOnly("mesh.vert", "depth.frag"), meshFloor("mesh.vert", "floor.frag"),
        screenFloor("fullscreen.vert", "floor.frag");
    const GpuMesh mesh(c.scene.mesh, GpuMesh::PositionsOnly{});
    GLuint vao = 0;
    glGenVertexArrays(1, &vao);
    RenderTarget depth(lightRes, lightRes, {}, true);
    RenderTarget atlas(atlasRes, atlasRes, {GL_RGBA32F, GL_RGBA32F}, false);
    RenderTarget frame(w, h, {GL_RGBA32F, GL_RGBA32F}, true);
    RenderTarget samples(w * aa, h * aa, {GL_RGBA32F, GL_RGBA32F}, true);
    RenderTarget display(w, h, {GL_RGBA8}, false);
    const float radius = boundingRadius(c.scene.mesh);
    const glm::mat4 lightViewProj = lightProjection(c.scene.lights[0], radius, lightRes).viewProj;
    const glm::mat4 viewProj = cameraViewProj(c.scene.camera, float(w) / float(h), radius);
    // As the frame's passes clear: the samples' G-buffer and the flux atlas keep their colour.
    auto drawMesh = [&](const ShaderProgram& p, RenderTarget& t, const glm::mat4& m, bool cull,
                        bool clearColor) {
        if (clearColor)
            t.bindAndClear();
        else
            t.bindAndClearDepth();
        p.use();
        p.set("u_viewProj", m);
        glEnable(GL_DEPTH_TEST);
        if (cull) glEnable(GL_CULL_FACE);
        mesh.draw();
        glDisable(GL_CULL_FACE);
        glDisable(GL_DEPTH_TEST);
    };
    auto fullScreen = [&](RenderTarget& t, bool clear) {
        if (clear)
            t.bindAndClear();
        else
            t.bind();
        screenFloor.use();
        glBindVertexArray(vao);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    };
    const int n = std::max(3, a.frames);
    std::map<std::string, std::vector<double>> now, floors;
    const std::vector<std::string> lightStages = {"gl_light_view", "gl_flux_atlas", "composite"},
                                   cameraStages = {"gl_gbuffer", "gl_composite_samples"};
    const bool cull = mesh.closedOutward();
    for (int round = 0; round < 3; ++round) {
        for (int camera = 0; camera < 2; ++camera) {
            BenchCase k = c;
            k.options.reuseLighting = camera == 1;
            const std::vector<FrameStats> frames = orbitFrames(renderer, k, n, camera == 1);
            for (const std::string& st : camera ? cameraStages : lightStages)
                now[st].push_back(summarize(stageSums(frames, {st})).median);
        }
        gl.makeCurrent();
        floors["light view: clear"].push_back(glMs(n, [&] { depth.bindAndClear(); }) *
                                              double(lights));
        floors["light view: clear + depth of the mesh"].push_back(
            glMs(n, [&] { drawMesh(depthOnly, depth, lightViewProj, cull, true); }) *
            double(lights));
        floors["flux atlas: constant full-screen pass"].push_back(
            glMs(n, [&] { fullScreen(atlas, false); }));
        floors["G-buffer: clear + constant mesh pass"].push_back(
            glMs(n, [&] { drawMesh(meshFloor, frame, viewProj, cull, true); }));
        floors["composite samples: depth clear + constant mesh pass"].push_back(
            glMs(n, [&] { drawMesh(meshFloor, samples, viewProj, cull, false); }));
        floors["composite: constant full-screen pass + 8-bit read-back"].push_back(glMs(n, [&] {
            fullScreen(display, true);
            (void)display.readRGBA8(0);
        }));
    }
    glDeleteVertexArrays(1, &vao);
    const std::vector<std::pair<std::string, std::string>> rows = {
        {"gl_light_view", "light view: clear + depth of the mesh"},
        {"gl_flux_atlas", "flux atlas: constant full-screen pass"},
        {"gl_gbuffer", "G-buffer: clear + constant mesh pass"},
        {"gl_composite_samples", "composite samples: depth clear + constant mesh pass"},
        {"composite", "composite: constant full-screen pass + 8-bit read-back"}};
    Table t({"pass", "now ms", "floor ms", "its floor", "what is left: shading"});
    for (const auto& [stage, floor] : rows) {
        const double nowMs = summarize(now[stage]).median,
                     floorMs = summarize(floors[floor]).median;
        t.add({"`" + stage + "`", fmt(nowMs, 1), fmt(floorMs, 1), floor, fmt(nowMs - floorMs, 1)});
    }
    std::string md =
        "# Each GL pass against its floor on this GL\n\nMade by `build-bench/bench/bench_frame "
        "--gl-floors` on " +
        timestamp() + ".\nMachine: " + machineLine(renderer) +
        ".\nDefault scene, today's defaults (" + std::to_string(w) + "×" + std::to_string(h) +
        ", --aa " + std::to_string(aa) + ", atlas " + std::to_string(atlasRes) + "², light maps " +
        std::to_string(lightRes) + "², " + std::to_string(lights) + " lights, " +
        std::to_string(c.scene.mesh.triangles.size()) +
        " triangles). *now*: the pass in the frame (light moving for the light view, flux atlas "
        "and composite; camera moving for the G-buffers), median of 3 rounds of " +
        std::to_string(n) +
        " frames. *floor*: the same targets and triangles with constant shaders "
        "(`gl/shaders/floor.frag`), back faces culled where the frame culls them, a clear per "
        "light view, median of 3 rounds interleaved with the frames. What is left is the "
        "shading the pass does: the part a faster shader could cut; the floor is what llvmpipe "
        "costs for the pass' pixels and triangles whatever the shader.\n\n" +
        t.markdown() +
        "\nThe light views' clear alone: " + fmt(summarize(floors["light view: clear"]).median, 1) +
        " ms.\n";
    writeResult("gl_floors.md", md);
    std::printf("%s", md.c_str());
    return 0;
}

int run(const BenchArgs& a) {
    if (std::find(a.rest.begin(), a.rest.end(), "--side-by-side") != a.rest.end())
        return sideBySide(a);
    if (std::find(a.rest.begin(), a.rest.end(), "--gl-floors") != a.rest.end()) return glFloors(a);
    if (std::find(a.rest.begin(), a.rest.end(), "--composite") != a.rest.end()) {
        Renderer renderer;
        const std::string section = compositeSection(renderer, a.frames);
        std::ifstream in(std::filesystem::path(resultsDir()) / "frame.md");
        std::stringstream text;
        text << in.rdbuf();
        std::string md = text.str();
        // That section alone: the sections after it (the next "## ") stay.
        const size_t at = md.find(kCompositeHeading);
        const size_t next = at == std::string::npos ? at : md.find("\n## ", at + 1);
        md = (at == std::string::npos ? md : md.substr(0, at)) + section +
             (next == std::string::npos ? "" : md.substr(next));
        writeResult("frame.md", md);
        std::printf("%s", section.c_str());
        return 0;
    }
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
        "lighting. Against EEVEE's viewport on the same machine, side by side: "
        "`bench/eevee_side_by_side.sh` → eevee.md.\n";
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
            const std::vector<FrameStats> frames =
                orbitFrames(renderer, c, a.frames, configs[ci].cameraMoves);
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
    md += compositeSection(renderer, a.frames);
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
