// render_frame OUT.png [NAME=VALUE…]: a marble sphere lit from above, any
// `tsis render` option by name on top.
#include <tsis/tsis.h>

#include <cstdio>
#include <string>

int main(int argc, char** argv) {
    try {
        tsis::api::Options options{{"mesh", "builtin:sphere"}, {"material", "marble"}};
        for (int i = 2; i < argc; ++i) {
            const std::string a = argv[i];
            options.set(a.substr(0, a.find('=')), a.substr(a.find('=') + 1));
        }
        // The scene's options make the scene, the rest the frame's typed
        // settings (a scene's own defaults under them).
        tsis::api::Scene scene(options.sceneOptions());
        scene.setLights({{false, {0, 12, 6}, {150, 150, 150}}});
        tsis::api::RenderSettings settings = options.renderSettings();
        if (!options.get("exposure")) settings.exposure = scene.renderSettings().exposure;
        tsis::api::Renderer renderer;
        const tsis::api::Frame frame = renderer.render(scene, settings);
        tsis::api::writeImage(frame, argc > 1 ? argv[1] : "frame.png");
        std::printf("%dx%d, log-average luminance %g\n", frame.width, frame.height, frame.lavg);
    } catch (const tsis::Error& e) {
        std::fprintf(stderr, "tsis: error: %s\n", e.what());
        return 1;
    }
}
