#include "tsis/options.h"

#include <algorithm>
#include <charconv>

#include "api/api_internal.h"
#include "description/scene_params.h"
#include "render/render_params.h"
#include "util/args.h"
#include "util/error.h"

namespace tsis::api {

namespace {

// The spec named `name`, or null (Args then reports the unknown option).
const OptionSpec* specOf(const std::string& name) {
    for (const OptionSpec& s : sceneOptionSpecs())
        if (s.name.substr(0, s.name.find('|')) == name) return &s;
    return nullptr;
}

// Each value as `tsis render` checks it; what options say together (--albedo
// needs --mfp) is checked where they are used: Scene, Renderer::render.
void check(const std::vector<std::string>& argv) {
    const Args args("render", sceneOptionSpecs(), argv);
    sceneDescriptionFromArgs(args);
    renderOptionsFromArgs(args);
}

// argv without option `name` (argv holds known options only: "--x" and, when
// x takes one, its value).
std::vector<std::string> without(const std::vector<std::string>& argv, const std::string& name) {
    std::vector<std::string> rest;
    for (size_t i = 0; i < argv.size(); ++i) {
        const OptionSpec* spec = specOf(argv[i].substr(2));
        TSIS_CHECK(spec);
        const size_t n = spec->takesValue ? 2 : 1;
        if (argv[i] != "--" + name) rest.insert(rest.end(), argv.begin() + i, argv.begin() + i + n);
        i += n - 1;
    }
    return rest;
}

// The options of argv (known only) for which keep(name) holds.
template <typename Keep>
std::vector<std::string> kept(const std::vector<std::string>& argv, Keep keep) {
    std::vector<std::string> out;
    for (size_t i = 0; i < argv.size(); ++i) {
        const std::string name = argv[i].substr(2);
        const OptionSpec* spec = specOf(name);
        TSIS_CHECK(spec);
        const size_t n = spec->takesValue ? 2 : 1;
        if (keep(name)) out.insert(out.end(), argv.begin() + i, argv.begin() + i + n);
        i += n - 1;
    }
    return out;
}

bool renderersOwn(const std::string& name) {
    return name == "cl-device" || name == "gl";
}

}  // namespace

Options Options::sceneOptions() const {
    Options o;
    o.args_ = kept(args_, [](const std::string& n) {
        return findSceneParam(n) != nullptr || n == "atlas-res";
    });
    return o;
}

Options Options::renderOptions() const {
    Options o;
    o.args_ = kept(args_, [](const std::string& n) {
        return findSceneParam(n) == nullptr && !renderersOwn(n);
    });
    return o;
}

RenderSettings Options::renderSettings() const {
    return renderOptionsFromArgs(Args("render", sceneOptionSpecs(), renderOptions().args_));
}

Options Options::of(const RenderSettings& settings) {
    validateRenderOptions(settings);
    checkParamsRead(settings);
    return optionsOfArgs(renderOptionArgs(settings));
}

Options optionsOfArgs(const std::vector<std::string>& argv) {
    Options o;
    for (size_t i = 0; i < argv.size();) {
        const std::string name = argv[i].substr(2);
        const OptionSpec* spec = specOf(name);
        TSIS_CHECK(spec);
        o.set(name, spec->takesValue ? argv[i + 1] : "true");
        i += spec->takesValue ? 2 : 1;
    }
    return o;
}

Options::Options(std::initializer_list<std::pair<std::string, std::string>> values) {
    for (const auto& [name, value] : values) set(name, value);
}

Options& Options::set(const std::string& name, const char* value) {
    return set(name, std::string(value));
}

Options& Options::set(const std::string& name, double value) {
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, value);
    return set(name, std::string(buf, r.ptr));
}

Options& Options::set(const std::string& name, const std::string& value) {
    const OptionSpec* spec = specOf(name);
    std::vector<std::string> next = spec && !spec->repeatable ? without(args_, name) : args_;
    if (spec && spec->takesValue) {
        next.insert(next.end(), {"--" + name, value});
    } else if (!spec || value == "true") {
        next.push_back("--" + name);  // unknown: Args names it as the CLI does
    } else if (value != "false") {
        fail("option --", name, " is a flag: true or false, not '", value, "'");
    }
    check(next);
    args_ = std::move(next);
    return *this;
}

Options& Options::unset(const std::string& name) {
    if (specOf(name)) args_ = without(args_, name);
    return *this;
}

std::optional<std::string> Options::get(const std::string& name) const {
    std::optional<std::string> v;
    const OptionSpec* spec = specOf(name);
    for (size_t i = 0; spec && i < args_.size(); ++i)
        if (args_[i] == "--" + name) v = spec->takesValue ? args_[i + 1] : "true";
    return v;
}

std::string Options::help() {
    return usageText("tsis::api::Options (as tsis render)", sceneOptionSpecs());
}

}  // namespace tsis::api
