#include "cli/commands.h"

#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "cli/animate.h"
#include "cli/compare_command.h"
#include "cli/scene_options.h"
#include "cli/view_command.h"
#include "gl/gl_context.h"
#include "image/image_io.h"
#include "mesh/mesh_io.h"
#include "physics/report.h"
#include "render/aov_files.h"
#include "render/frame_memory.h"
#include "render/render_params.h"
#include "render/renderer.h"
#include "render/truth_check.h"
#include "util/args.h"
#include "util/error.h"
#include "util/output_set.h"
#include "util/progress.h"

namespace tsis {

namespace {

constexpr const char* kTopUsage =
    R"(tsis — real-time translucent rendering by texture-space importance sampling

usage: tsis <command> [options]      (no command: render the default scene)

commands:
  render      render a frame to a PNG (and AOVs, stats)
  materials   list the preset materials with their coefficients
  dipole      evaluate the dipole profile Rd(r) of a material
  compare     error metrics (and a heat map) of an image against a reference
  animate     a PNG sequence while the light orbits, the material or the size changes
  view        an interactive window: orbit, drag the light, change material and size
  atlas       build (or check) a mesh's texture atlas and report its quality
  help        this text; `tsis <command> --help` for a command's options
)";

struct Command {
    const char* name;
    int (*run)(const std::vector<std::string>& argv);
};

bool wantsHelp(const std::vector<std::string>& argv) {
    for (const std::string& a : argv)
        if (a == "--help" || a == "-h") return true;
    return false;
}

std::vector<OptionSpec> renderSpecs() {
    std::vector<OptionSpec> specs = sceneOptionSpecs();
    specs.push_back({"output|o", true, false, "FILE  output PNG (default tsis.png)"});
    specs.push_back({"aov", true, false,
                     "DIR  write linear EXRs: radiosity, radiance, position, normal, coverage, "
                     "flux_atlas, medium"});
    specs.push_back({"stats", true, false, "FILE.json  per-stage timings, bytes, counts"});
    specs.push_back({"frames", true, false,
                     "N  render the frame N times, report the last (warm timings; default 1)"});
    specs.push_back({"progressive", false, false,
                     "with --frames N: each frame a new sample set, the image their mean"});
    specs.push_back({"truth-check", true, false,
                     "S  also render --method volumetric for S seconds at the same view and "
                     "print the model's error against it (pooled rel. RMSE of the radiance "
                     "without the surface reflection, the reference's noise taken out)"});
    return specs;
}

// An image output: its place takes a file and its format is known ("-": a PNG on stdout).
void addImageOutput(OutputSet& outputs, const std::string& path) {
    outputs.add(path, ".png");  // "-", /dev/null: a PNG
    requireImageFormat(outputs, path);
}

int runRender(const std::vector<std::string>& argv) {
    const std::vector<OptionSpec> specs = renderSpecs();
    if (wantsHelp(argv)) {
        std::cout << usageText("tsis render [options]", specs);
        return 0;
    }
    Args args("render", specs, argv);
    if (!args.positional().empty()) fail("unexpected argument '", args.positional()[0], "'");
    // Every option is checked first, then every output, and only then the
    // (slow) mesh, GL and CL: a mistake costs no waiting.
    Scene scene = parseScene(args);
    RenderOptions options = renderOptionsFromArgs(args);
    const std::string gl = args.getString("gl", "");
    parseGlChoice(gl);
    const auto aovDir = args.value("aov");
    options.keepAovs = aovDir.has_value();
    options.progressive = args.flag("progressive");
    requireFrameMemory(options);
    const int frames = args.getInt("frames", 1, 1, 100000);
    const std::string output = args.getString("output", "tsis.png");
    const auto statsPath = args.value("stats");
    const std::optional<double> truthSeconds =
        args.value("truth-check")
            ? std::optional<double>(args.getDouble("truth-check", 0, 1e-3, 1e6))
            : std::nullopt;
    if (truthSeconds && options.method == "volumetric")
        fail("--truth-check measures a model against --method volumetric: give another method");

    OutputSet outputs;
    addImageOutput(outputs, output);
    if (aovDir) addAovOutputs(outputs, *aovDir);
    if (statsPath) outputs.add(*statsPath, ".json");

    loadSceneMesh(scene, args);
    Renderer renderer(args.getString("cl-device", ""), gl);
    FrameResult frame = renderer.render(scene, options);
    for (int i = 1; i < frames; ++i) frame = renderer.render(scene, options);
    std::optional<TruthCheck> truth;
    if (truthSeconds) {
        truth = truthCheck(renderer, scene, options, *truthSeconds);
        std::fprintf(stderr,
                     "tsis: truth check: the model is %.1f %% from volumetric transport (pooled "
                     "rel. RMSE over %d pixels, %.1f %% measured, the reference's noise %.1f %%; "
                     "%g s of paths)\n",
                     100 * truth->subtracted, truth->pixels, 100 * truth->relRmse,
                     100 * truth->noise, truth->seconds);
    }

    outputs.write(output, [&](const std::filesystem::path& f) {
        int channels = 3;
        const std::vector<uint8_t> pixels = frame.displayPixels(channels);
        writeImage8(f.string(), frame.width, frame.height, channels, pixels);
    });
    if (aovDir) writeAovOutputs(outputs, *aovDir, frame);
    if (statsPath) {
        Json j = frame.stats.toJson();
        j["mesh"] = scene.mesh.name;
        j["material"] = scene.material.name;
        // The scene as options: a glTF's camera and lights as they were used,
        // its materials the file's unless the command line gave one.
        j["scene_args"] = sceneArgs(scene, sceneDescriptionFromArgs(args));
        j["lavg"] = frame.lavg;
        if (truth)
            j["truth_check"] = Json{{"rel_rmse", truth->relRmse},
                                    {"noise", truth->noise},
                                    {"rel_rmse_noise_subtracted", truth->subtracted},
                                    {"seconds", truth->seconds},
                                    {"pixels", truth->pixels}};
        outputs.write(*statsPath,
                      [&](const std::filesystem::path& f) { writeText(f, dumpJson(j) + "\n"); });
    }
    outputs.commit();
    return 0;
}

int runMaterials(const std::vector<std::string>& argv) {
    if (wantsHelp(argv)) {
        std::cout << "usage: tsis materials\n\nLists the preset materials (Jensen et al. 2001).\n";
        return 0;
    }
    Args args("materials", {}, argv);
    if (!args.positional().empty()) fail("unexpected argument '", args.positional()[0], "'");
    std::cout << materialsTable();
    return 0;
}

int runDipole(const std::vector<std::string>& argv) {
    const std::vector<OptionSpec> specs = {
        {"material", true, false, "NAME  preset (default skin1)"},
        {"sigma-s", true, false, "R,G,B  reduced scattering σs' (1/mm)"},
        {"sigma-a", true, false, "R,G,B  absorption σa (1/mm)"},
        {"eta", true, false, "E  relative index of refraction"},
        {"r", true, false, "LIST  comma-separated radii in mm (default 0,0.1,1)"},
        {"rp-bound", true, false, "B  importance lower bound for Rp (default 0.1)"},
        {"json", false, false, "print JSON"},
    };
    if (wantsHelp(argv)) {
        std::cout << usageText("tsis dipole [options]", specs);
        return 0;
    }
    Args args("dipole", specs, argv);
    if (!args.positional().empty()) fail("unexpected argument '", args.positional()[0], "'");
    Material m = materialFromArgs(args);
    std::vector<double> radii = parseList("--r", args.getString("r", "0,0.1,1"));
    for (double r : radii)
        if (r < 0) fail("--r: radius ", r, " is negative");
    Json report = dipoleReport(m, radii, args.getDouble("rp-bound", 0.1, 1e-9, 1e9));
    std::cout << dumpJson(report) << "\n";
    return 0;
}

int runAtlas(const std::vector<std::string>& argv) {
    const std::vector<OptionSpec> specs = {
        {"mesh", true, false, "M  mesh file, builtin:NAME or a data mesh name (required)"},
        {"size-mm", true, false, "S  bounding-box diagonal in mm (default 10)"},
        {"atlas", true, false, "MODE  auto (default), file or build"},
        {"rotate", true, false, "X,Y,Z  turn the mesh as tsis render --rotate does"},
        {"mesh-up", true, false, "y|z  the mesh's up axis, as tsis render --mesh-up (default y)"},
        {"allow-outside-assets", false, false,
         "read a glTF's buffers also outside its folder, as tsis render"},
        {"atlas-res", true, false, findRenderParam("atlas-res")->usage()},  // as tsis render
        {"output|o", true, false, "FILE  PNG: charts in colour and a heat map of the area ratio r"},
        {"json", false, false, "print the statistics as JSON"},
    };
    if (wantsHelp(argv)) {
        std::cout << usageText("tsis atlas --mesh M [-o atlas.png] [--json]", specs);
        return 0;
    }
    Args args("atlas", specs, argv);
    if (!args.positional().empty()) fail("unexpected argument '", args.positional()[0], "'");
    auto meshSpec = args.value("mesh");
    if (!meshSpec) fail("tsis atlas needs --mesh");
    const double size = sizeMmFromArgs(args);
    const MeshOptions mo = meshOptionsFromArgs(args);
    const AtlasOptions& ao = mo.atlas;
    OutputSet outputs;
    const auto png = args.value("output");
    if (png && *png == "-") fail("-o -: standard output carries the statistics");
    if (png) addImageOutput(outputs, *png);
    // The atlas tsis render would use (its normals play no part).
    AtlasStats built;
    const Mesh mesh = atlasMesh(loadMesh(*meshSpec), size, mo, &built);
    AtlasStats stats = measureAtlas(mesh, ao.resolution);
    stats.seconds = built.seconds;
    stats.fromCache = built.fromCache;
    if (png) {
        outputs.write(*png, [&](const std::filesystem::path& f) {
            writeAtlasPng(f.string(), mesh, ao.resolution);
        });
        outputs.commit();
    }
    Json j = atlasStatsJson(stats);
    if (args.flag("json")) {
        std::cout << dumpJson(j) << "\n";
    } else {
        std::printf("%s: %zu triangles, %d charts, coverage %.3f\n", mesh.name.c_str(),
                    mesh.triangles.size(), stats.charts, stats.coverage);
        std::printf("area ratio r: weighted stddev %.4f, p1 %.3f, p99 %.3f, min %.3f, max %.3f\n",
                    stats.rWstd, stats.rP01, stats.rP99, stats.rMin, stats.rMax);
        std::printf("flipped %zu, overlapping %zu, %.2f s%s\n", stats.flipped, stats.overlaps,
                    stats.seconds, stats.fromCache ? " (from cache)" : "");
    }
    return 0;
}

const Command kCommands[] = {
    {"atlas", runAtlas},   {"render", runRender},   {"materials", runMaterials},
    {"dipole", runDipole}, {"compare", runCompare}, {"animate", runAnimate},
    {"view", runView},
};

}  // namespace

int runCli(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    try {
        Progress::checkEnvironment();
        if (args.empty()) return runRender({});
        const std::string cmd = args[0];
        if (cmd == "help" || cmd == "--help" || cmd == "-h") {
            std::cout << kTopUsage;
            return 0;
        }
        std::vector<std::string> rest(args.begin() + 1, args.end());
        for (const Command& c : kCommands)
            if (cmd == c.name) return c.run(rest);
        if (!cmd.empty() && cmd[0] == '-') return runRender(args);
        fail("unknown command '", cmd, "' (see tsis help)");
    } catch (const Error& e) {
        // Messages quote paths and file contents: printable() keeps them one harmless line.
        std::fprintf(stderr, "tsis: error: %s\n", printable(e.what()).c_str());
        return 1;
    } catch (const cl::Error& e) {
        std::fprintf(stderr, "tsis: error: OpenCL call %s failed with code %d\n", e.what(),
                     e.err());
        return 1;
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "tsis: error: out of memory\n");
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "tsis: error: %s\n", printable(e.what()).c_str());
        return 1;
    }
}

}  // namespace tsis
