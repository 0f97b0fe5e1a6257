// `tsis animate --frames N -o DIR [--orbit] [--size-to S] [--materials A,B,…]`
//
// Renders N frames with one Renderer (GL context, CL programs, atlas and
// buffers made once) and writes DIR/frame_0000.png, … plus, when ffmpeg is on
// the PATH and --video is given, DIR/animation.mp4. What changes per frame:
//   --orbit         every light turns about the y axis, one full turn over the sequence
//   --size-to S     the size goes linearly from --size-mm to S (Fig. 4.5: 10 → 70 mm);
//                   the camera and the default lights follow the size
//   --materials L   the presets in L, in turn, one per frame
// The scene options are those of `tsis render`. --stats FILE.json records every
// frame's milliseconds and resident memory and the steady rate (frames after the first).
#include "cli/animate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <glm/gtc/matrix_transform.hpp>
#include <iostream>
#include <optional>
#include <sstream>

#include "cli/scene_options.h"
#include "gl/gl_context.h"
#include "image/image_io.h"
#include "mesh/mesh_io.h"
#include "render/frame_memory.h"
#include "render/renderer.h"
#include "util/args.h"
#include "util/error.h"
#include "util/memory.h"
#include "util/output_set.h"
#include "util/process.h"
#include "util/progress.h"
#include "util/timer.h"

namespace tsis {

namespace {

std::vector<OptionSpec> animateSpecs() {
    std::vector<OptionSpec> specs = sceneOptionSpecs();
    specs.push_back(
        {"output|o", true, false, "DIR  folder for frame_NNNN.png (required; created)"});
    specs.push_back({"frames", true, false, "N  number of frames (default 30)"});
    specs.push_back(
        {"orbit", false, false, "the lights (and the --env map) orbit the object (one turn)"});
    specs.push_back({"size-to", true, false, "S  size at the last frame, mm (from --size-mm)"});
    specs.push_back({"materials", true, false, "A,B,…  presets, one per frame in turn"});
    specs.push_back({"video", false, false, "also write DIR/animation.mp4 when ffmpeg exists"});
    specs.push_back({"fps", true, false, "F  video frame rate (default 15)"});
    specs.push_back({"stats", true, false, "FILE.json  per-frame ms and the steady frame rate"});
    return specs;
}

// Uniform scale of the normalised mesh (centred at the origin): size s0 → s.
void rescale(Scene& scene, const Scene& base, double s0, double s) {
    const float k = static_cast<float>(s / s0);
    for (size_t i = 0; i < base.mesh.positions.size(); ++i)
        scene.mesh.positions[i] = base.mesh.positions[i] * k;
    scene.camera.eye = base.camera.eye * k;
    scene.camera.target = base.camera.target * k;
    for (size_t i = 0; i < base.lights.size(); ++i) {
        Light& l = scene.lights[i];
        if (l.type != Light::Type::Point) continue;
        // Same irradiance at the object: position and intensity scale together.
        l.vec = base.lights[i].vec * k;
        l.rgb = base.lights[i].rgb * (k * k);
    }
}

// ffmpeg's image-sequence input for the frames in `dir`: absolute, so that
// no path reads as an option or a protocol, and '%' doubled (ffmpeg's pattern).
std::string framePattern(const std::filesystem::path& dir) {
    std::string d = std::filesystem::absolute(dir).string(), out;
    for (char c : d) out += c == '%' ? std::string("%%") : std::string(1, c);
    return out + "/frame_%04d.png";
}

}  // namespace

int runAnimate(const std::vector<std::string>& argv) {
    const std::vector<OptionSpec> specs = animateSpecs();
    for (const std::string& a : argv)
        if (a == "--help" || a == "-h") {
            std::cout << usageText(
                "tsis animate -o DIR [--frames N] [--orbit] [--size-to S] "
                "[--materials A,B] [render options]",
                specs);
            return 0;
        }
    Args args("animate", specs, argv);
    if (!args.positional().empty()) fail("unexpected argument '", args.positional()[0], "'");
    auto out = args.value("output");
    if (!out) fail("tsis animate needs -o DIR");
    // Every option first, then every output, then the mesh, GL and CL.
    const int frames = args.getInt("frames", 30, 1, 100000);
    const double size0 = sizeMmFromArgs(args);
    const double size1 = args.getDouble("size-to", size0, 1e-3, 1e5);
    const int videoFps = args.getInt("fps", 15, 1, 240);
    std::vector<std::string> materials;
    if (auto m = args.value("materials")) {
        std::stringstream ss(*m);
        for (std::string name; std::getline(ss, name, ',');)
            if (!name.empty()) materials.push_back(name);
        for (const std::string& name : materials) presetMaterial(name);  // fails early on a typo
    }
    Scene base = parseScene(args);
    const RenderOptions options = renderOptionsFromArgs(args);
    const std::string gl = args.getString("gl", "");
    parseGlChoice(gl);
    requireFrameMemory(options);
    const auto statsPath = args.value("stats");

    // The frames are staged in a hidden folder inside DIR (ffmpeg reads them
    // there) and move to DIR with the video and the stats when all succeeded.
    OutputSet outputs;
    outputs.makeDirectory(*out);
    const std::filesystem::path stage = outputs.makeStagingDirectory(*out);
    auto framePath = [&](int f) {
        char name[32];
        std::snprintf(name, sizeof name, "frame_%04d.png", f);
        return (std::filesystem::path(*out) / name).string();
    };
    for (int f = 0; f < frames; ++f) outputs.add(framePath(f), "", stage);
    const std::string video = (std::filesystem::path(*out) / "animation.mp4").string();
    const std::optional<std::string> ffmpeg =
        args.flag("video") ? findInPath("ffmpeg") : std::nullopt;
    if (ffmpeg) outputs.add(video);
    if (statsPath) outputs.add(*statsPath, ".json");

    loadSceneMesh(base, args);
    Scene scene = base;
    Renderer renderer(args.getString("cl-device", ""), gl);
    Progress progress("animate", frames);
    Json perFrame = Json::array();
    std::vector<double> ms;
    for (int f = 0; f < frames; ++f) {
        Timer t;
        const double phase = frames > 1 ? static_cast<double>(f) / (frames - 1) : 0.0;
        if (size1 != size0) rescale(scene, base, size0, size0 + (size1 - size0) * phase);
        if (!materials.empty()) scene.material = presetMaterial(materials[f % materials.size()]);
        if (args.flag("orbit")) {
            const glm::mat4 rot =
                glm::rotate(glm::mat4(1.0f), static_cast<float>(2.0 * M_PI * f / frames),
                            glm::vec3(0.0f, 1.0f, 0.0f));
            for (size_t i = 0; i < scene.lights.size(); ++i) {
                if (scene.lights[i].environment) continue;  // turns with the map, below
                const glm::vec3 v = size1 != size0 ? scene.lights[i].vec : base.lights[i].vec;
                scene.lights[i].vec = glm::vec3(rot * glm::vec4(v, 0.0f));
            }
            // --env: the map turns with the lights (the same angle about +y).
            scene.env.rotateDegrees = base.env.rotateDegrees + 360.0 * f / frames;
            applyEnvironment(scene);
        }
        FrameResult frame = renderer.render(scene, options);
        outputs.write(framePath(f), [&](const std::filesystem::path& file) {
            int channels = 3;
            const std::vector<uint8_t> pixels = frame.displayPixels(channels);
            writeImage8(file.string(), frame.width, frame.height, channels, pixels);
        });
        ms.push_back(t.ms());  // everything: scene update, frame, PNG
        Json j = Json::object();
        j["frame"] = f;
        j["ms"] = ms.back();
        j["render_ms"] = frame.stats.stageMs("total");
        // Each pass's ms, to see which ones the change made run (`render
        // --stats` "ms").
        j["stage_ms"] = frame.stats.stageMsJson();
        // Follows memory over long runs (a test bounds its growth).
        j["rss_mb"] = residentMegabytes();
        perFrame.push_back(j);
        progress.update(f + 1);
    }
    progress.finish();
    // Steady rate: frames after the first (which builds programs and the atlas).
    double steadyMs = 0;
    for (size_t i = 1; i < ms.size(); ++i) steadyMs += ms[i];
    const double fps = ms.size() > 1 ? (ms.size() - 1) * 1000.0 / steadyMs : 1000.0 / ms[0];
    if (args.flag("video") && !ffmpeg)
        std::fprintf(stderr, "tsis: ffmpeg not found on the PATH; no video written\n");
    if (ffmpeg) {
        outputs.write(video, [&](const std::filesystem::path& file) {
            // No shell: every path reaches ffmpeg as one argument, whatever it holds.
            const int rc = runProgram(
                *ffmpeg, {"-nostdin", "-loglevel", "error", "-y", "-framerate",
                          std::to_string(videoFps), "-i", framePattern(stage), "-pix_fmt",
                          "yuv420p", std::filesystem::absolute(file).string()});
            if (rc != 0) fail("cannot write '", file.string(), "': ffmpeg exited with ", rc);
        });
    }
    if (statsPath) {
        Json j = Json::object();
        j["frames"] = frames;
        j["first_ms"] = ms[0];
        j["steady_fps"] = fps;
        j["method"] = options.method;
        j["width"] = options.width;
        j["height"] = options.height;
        j["samples"] = options.samples;
        j["per_frame"] = perFrame;
        outputs.write(*statsPath, [&](const std::filesystem::path& file) {
            writeText(file, dumpJson(j) + "\n");
        });
    }
    outputs.commit();
    std::fprintf(stderr, "tsis: %d frames in %s; first %.0f ms, steady %.2f fps\n", frames,
                 printable(*out).c_str(), ms[0], fps);
    return 0;
}

}  // namespace tsis
