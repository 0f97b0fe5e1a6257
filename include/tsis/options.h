// The options of `tsis render`, set by name: the names of `tsis render --help`
// without the dashes, the values as typed on the command line, parsed and
// checked by the CLI's own parser (one place for both), so a mistake is the
// same one-line tsis::Error the CLI prints.
#pragma once

#include <initializer_list>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "tsis/render_settings.h"

namespace tsis::api {

class Options {
  public:
    Options() = default;
    // Each pair through set(): Options{{"method", "tsis"}, {"samples", "1024"}}.
    Options(std::initializer_list<std::pair<std::string, std::string>> values);

    // Sets an option (replacing an earlier value; "light" adds one more light).
    // A flag (no-specular, no-reuse-lighting) takes "true" or "false". Throws
    // tsis::Error, leaving the options as they were, for an unknown name or a
    // value the CLI would refuse.
    Options& set(const std::string& name, const std::string& value);
    Options& set(const std::string& name, const char* value);
    Options& set(const std::string& name, double value);  // written exactly
    Options& unset(const std::string& name);
    // The value last set; nullopt when unset.
    std::optional<std::string> get(const std::string& name) const;

    // The options split as `tsis render`'s are: those of the scene (Scene:
    // mesh, material, light, env, eye, …) and those of a frame
    // (Renderer::render: method, samples, width, …); atlas-res is both (the
    // mesh's atlas and the frame's), cl-device and gl neither (Renderer's).
    Options sceneOptions() const;
    Options renderOptions() const;

    // The render options typed: the defaults where unset (a scene's own
    // defaults: Scene::renderSettings()). Throws tsis::Error for what
    // Renderer::render would refuse of them.
    RenderSettings renderSettings() const;
    // The settings as options: method and every field off its default that
    // the method reads (`tsis render`'s command line, as --stats prints it).
    // Throws tsis::Error for a value out of range or a field the method does
    // not read.
    static Options of(const RenderSettings& settings);

    // As on the command line: {"--method", "tsis", "--samples", "1024", ...}.
    const std::vector<std::string>& args() const { return args_; }
    // The names, what they take and their defaults (`tsis render --help`'s table).
    static std::string help();

  private:
    std::vector<std::string> args_;
};

}  // namespace tsis::api
