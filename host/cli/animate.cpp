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
// frame's milliseconds and the steady rate (frames after the first).
#include "cli/animate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <glm/gtc/matrix_transform.hpp>
#include <iostream>
#include <sstream>

#include "cli/args.h"
#include "cli/scene_options.h"
#include "image/image_io.h"
#include "mesh/mesh_io.h"
#include "render/renderer.h"
#include "util/error.h"
#include "util/output_file.h"
#include "util/progress.h"
#include "util/timer.h"

namespace tsis {

namespace {

std::vector<OptionSpec> animateSpecs() {
    std::vector<OptionSpec> specs = sceneOptionSpecs();
    specs.push_back({"output|o", true, false, "DIR  folder for frame_NNNN.png (required; created)"});
    specs.push_back({"frames", true, false, "N  number of frames (default 30)"});
    specs.push_back({"orbit", false, false, "the lights orbit the object (one turn)"});
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

bool haveFfmpeg() { return std::system("command -v ffmpeg >/dev/null 2>&1") == 0; }

}  // namespace

int runAnimate(const std::vector<std::string>& argv) {
    const std::vector<OptionSpec> specs = animateSpecs();
    for (const std::string& a : argv)
        if (a == "--help" || a == "-h") {
            std::cout << usageText("tsis animate -o DIR [--frames N] [--orbit] [--size-to S] "
                                   "[--materials A,B] [render options]",
                                   specs);
            return 0;
        }
    Args args("animate", specs, argv);
    if (!args.positional().empty()) fail("unexpected argument '", args.positional()[0], "'");
    auto out = args.value("output");
    if (!out) fail("tsis animate needs -o DIR");
    const int frames = args.getInt("frames", 30, 1, 100000);
    const double size0 = args.getDouble("size-mm", 10.0, 1e-3, 1e5);
    const double size1 = args.getDouble("size-to", size0, 1e-3, 1e5);
    std::vector<std::string> materials;
    if (auto m = args.value("materials")) {
        std::stringstream ss(*m);
        for (std::string name; std::getline(ss, name, ',');)
            if (!name.empty()) materials.push_back(name);
        for (const std::string& name : materials) presetMaterial(name);  // fails early on a typo
    }
    if (auto s = args.value("stats")) {
        std::filesystem::path dir = std::filesystem::path(*s).parent_path();
        if (!dir.empty() && !std::filesystem::is_directory(dir))
            fail("cannot write '", *s, "': directory '", dir.string(), "' does not exist");
    }
    std::filesystem::create_directories(*out);

    const Scene base = sceneFromArgs(args);
    const RenderOptions options = renderOptionsFromArgs(args);
    Scene scene = base;
    Renderer renderer(args.getString("cl-device", ""));
    Progress progress("animate", frames);
    Json perFrame = Json::array();
    std::vector<double> ms;
    for (int f = 0; f < frames; ++f) {
        Timer t;
        const double phase = frames > 1 ? static_cast<double>(f) / (frames - 1) : 0.0;
        if (size1 != size0) rescale(scene, base, size0, size0 + (size1 - size0) * phase);
        if (!materials.empty()) scene.material = presetMaterial(materials[f % materials.size()]);
        if (args.flag("orbit")) {
            const glm::mat4 rot = glm::rotate(glm::mat4(1.0f),
                                              static_cast<float>(2.0 * M_PI * f / frames),
                                              glm::vec3(0.0f, 1.0f, 0.0f));
            for (size_t i = 0; i < scene.lights.size(); ++i) {
                const glm::vec3 v = size1 != size0 ? scene.lights[i].vec : base.lights[i].vec;
                scene.lights[i].vec = glm::vec3(rot * glm::vec4(v, 0.0f));
            }
        }
        FrameResult frame = renderer.render(scene, options);
        char name[32];
        std::snprintf(name, sizeof name, "frame_%04d.png", f);
        writeImage8((std::filesystem::path(*out) / name).string(), frame.width, frame.height, 3,
                    frame.rgb8);
        ms.push_back(t.ms());  // everything: scene update, frame, PNG
        Json j = Json::object();
        j.set("frame", f);
        j.set("ms", ms.back());
        j.set("render_ms", frame.stats.stageMs("total"));
        perFrame.push(j);
        progress.update(f + 1);
    }
    progress.finish();
    // Steady rate: frames after the first (which builds programs and the atlas).
    double steadyMs = 0;
    for (size_t i = 1; i < ms.size(); ++i) steadyMs += ms[i];
    const double fps = ms.size() > 1 ? (ms.size() - 1) * 1000.0 / steadyMs : 1000.0 / ms[0];
    std::fprintf(stderr, "tsis: %d frames in %s; first %.0f ms, steady %.2f fps\n", frames,
                 out->c_str(), ms[0], fps);
    if (args.flag("video")) {
        if (!haveFfmpeg()) {
            std::fprintf(stderr, "tsis: ffmpeg not found; no video written\n");
        } else {
            const std::filesystem::path video = std::filesystem::path(*out) / "animation.mp4";
            writeAtomically(video, [&](const std::filesystem::path& tmp) {
                std::ostringstream cmd;
                cmd << "ffmpeg -loglevel error -y -framerate "
                    << args.getInt("fps", 15, 1, 240) << " -i '"
                    << (std::filesystem::path(*out) / "frame_%04d.png").string()
                    << "' -pix_fmt yuv420p '" << tmp.string() << "'";
                if (std::system(cmd.str().c_str()) != 0) fail("ffmpeg failed: ", cmd.str());
            });
        }
    }
    if (auto s = args.value("stats")) {
        Json j = Json::object();
        j.set("frames", frames);
        j.set("first_ms", ms[0]);
        j.set("steady_fps", fps);
        j.set("method", options.method);
        j.set("width", options.width);
        j.set("height", options.height);
        j.set("samples", options.samples);
        j.set("per_frame", perFrame);
        writeTextFile(*s, j.dump() + "\n");
    }
    return 0;
}

}  // namespace tsis
