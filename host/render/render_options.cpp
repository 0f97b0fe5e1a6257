#include "render/render_options.h"

#include <algorithm>
#include <utility>

#include "physics/fresnel.h"
#include "physics/ggx.h"
#include "render/method.h"
#include "render/render_params.h"
#include "util/error.h"

namespace tsis {

namespace {

// Each choice's values and their names, once: parse and name both read it.
template <typename E>
using Choice = std::pair<E, const char*>;

constexpr Choice<PyramidCache> kPyramidCaches[] = {{PyramidCache::Pixels, "off"},
                                                   {PyramidCache::Camera, "camera"},
                                                   {PyramidCache::Texture, "always"}};
constexpr Choice<RdPart> kRdParts[] = {
    {RdPart::Full, "full"}, {RdPart::Local, "local"}, {RdPart::Global, "global"}};
constexpr Choice<ProfileModel> kProfileModels[] = {{ProfileModel::Dipole, "dipole"},
                                                   {ProfileModel::BetterDipole, "better-dipole"},
                                                   {ProfileModel::Pbd, "pbd"},
                                                   {ProfileModel::Mc, "mc"}};
constexpr Choice<ExitTerm> kExitTerms[] = {{ExitTerm::Jensen, "jensen"},
                                           {ExitTerm::Normalized, "normalized"}};
constexpr Choice<EnergyTarget> kEnergyTargets[] = {{EnergyTarget::SemiInfinite, "semi-infinite"},
                                                   {EnergyTarget::Object, "object"}};
constexpr Choice<Transport> kTransports[] = {{Transport::Off, "off"},
                                             {Transport::Object, "object"}};
constexpr Choice<VolumetricEstimator> kEstimators[] = {{VolumetricEstimator::Camera, "camera"},
                                                       {VolumetricEstimator::Light, "light"}};
constexpr Choice<ToneCurve> kToneCurves[] = {
    {ToneCurve::Reinhard, "reinhard"}, {ToneCurve::Aces, "aces"}, {ToneCurve::None, "none"}};
constexpr Choice<AaMethod> kAaMethods[] = {{AaMethod::Samples, "samples"},
                                           {AaMethod::Fxaa, "fxaa"}};
constexpr Choice<Background> kBackgrounds[] = {{Background::Color, "color"},
                                               {Background::Transparent, "transparent"},
                                               {Background::Env, "env"}};

// The value named `name`; anything else is an error naming `option` and the
// names ("expected a, b or c").
template <typename E, size_t N>
E parseChoice(const char* option, const std::string& name, const Choice<E> (&choices)[N]) {
    for (const auto& [value, text] : choices)
        if (name == text) return value;
    std::string expected;
    for (size_t i = 0; i < N; ++i)
        expected += std::string(i == 0 ? "" : i + 1 == N ? " or " : ", ") + choices[i].second;
    fail(option, " '", name, "': expected ", expected);
}

// The name of `value` (the first's for a value not listed).
template <typename E, size_t N>
const char* choiceName(E value, const Choice<E> (&choices)[N]) {
    for (const auto& [v, text] : choices)
        if (v == value) return text;
    return choices[0].second;
}

}  // namespace

PyramidCache parsePyramidCache(const std::string& name) {
    return parseChoice("--pyramid-cache", name, kPyramidCaches);
}
const char* pyramidCacheName(PyramidCache cache) {
    return choiceName(cache, kPyramidCaches);
}

ToneCurve parseToneCurve(const std::string& name) {
    return parseChoice("--tone", name, kToneCurves);
}
const char* toneCurveName(ToneCurve tone) {
    return choiceName(tone, kToneCurves);
}

AaMethod parseAaMethod(const std::string& name) {
    return parseChoice("--aa-method", name, kAaMethods);
}
const char* aaMethodName(AaMethod method) {
    return choiceName(method, kAaMethods);
}

Background parseBackground(const std::string& name) {
    return parseChoice("--background", name, kBackgrounds);
}
const char* backgroundName(Background background) {
    return choiceName(background, kBackgrounds);
}

RdPart parseRdPart(const std::string& name) {
    return parseChoice("--rd-part", name, kRdParts);
}
const char* rdPartName(RdPart part) {
    return choiceName(part, kRdParts);
}

ProfileModel parseProfileModel(const std::string& name) {
    return parseChoice("--profile", name, kProfileModels);
}
const char* profileModelName(ProfileModel model) {
    return choiceName(model, kProfileModels);
}

ExitTerm parseExitTerm(const std::string& name) {
    return parseChoice("--exit", name, kExitTerms);
}
const char* exitTermName(ExitTerm exit) {
    return choiceName(exit, kExitTerms);
}

EnergyTarget parseEnergyTarget(const std::string& name) {
    return parseChoice("--energy", name, kEnergyTargets);
}
const char* energyTargetName(EnergyTarget energy) {
    return choiceName(energy, kEnergyTargets);
}

Transport parseTransport(const std::string& name) {
    return parseChoice("--transport", name, kTransports);
}
const char* transportName(Transport transport) {
    return choiceName(transport, kTransports);
}

VolumetricEstimator parseVolumetricEstimator(const std::string& name) {
    return parseChoice("--estimator", name, kEstimators);
}
const char* volumetricEstimatorName(VolumetricEstimator estimator) {
    return choiceName(estimator, kEstimators);
}

double exitScale(ExitTerm exit, double eta) {
    return exit == ExitTerm::Normalized ? normalizedExitScale(eta) : 1.0;
}

double surfaceRoughness(float optionRoughness, double fileRoughness) {
    if (optionRoughness >= 0) return optionRoughness;
    return fileRoughness >= 0 ? fileRoughness : kDefaultRoughness;
}

void validateRenderOptions(const RenderOptions& o) {
    const std::vector<std::string> names = methodNames();
    if (std::find(names.begin(), names.end(), o.method) == names.end()) {
        std::string list;
        for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
        fail("unknown method '", o.method, "'; available: ", list);
    }
    // Each value through its parameter's parser: the ranges typed once, in
    // render_params.cpp. A default may lie outside them (0: automatic).
    for (const RenderParam& p : renderParams()) {
        if (p.flag || p.isDefault(o)) continue;
        RenderOptions copy = o;
        p.set(copy, p.text(o));
    }
    if (o.maxScatterings > 0 && o.minScatterings > o.maxScatterings)
        fail("--min-scatterings ", o.minScatterings, " exceeds --max-scatterings ",
             o.maxScatterings, ": no scattering order is left to sum");
}

}  // namespace tsis
