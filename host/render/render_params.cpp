#include "render/render_params.h"

#include <algorithm>
#include <cstdint>
#include <type_traits>

#include "util/error.h"
#include "util/parse.h"

namespace tsis {

namespace {

// The values a number accepts as typed: lo to hi, optionally only powers of
// two, optionally 0 as well, meaning `zero` ("automatic", "off").
struct Range {
    double lo, hi;
    bool powerOfTwo = false;
    const char* zero = nullptr;
};

template <typename T>
RenderParam number(RenderParam p, T RenderOptions::*field, Range r) {
    p.kind = std::is_integral_v<T> ? api::RenderParameter::Kind::Integer
                                   : api::RenderParameter::Kind::Real;
    p.text = [field](const RenderOptions& o) { return exactText(o.*field); };
    p.set = [field, r, what = "--" + p.name](RenderOptions& o, const std::string& value) {
        double v;
        if constexpr (std::is_integral_v<T>)
            v = static_cast<double>(parseInteger(what, value));
        else
            v = parseNumber(what, value);
        if (!(r.zero && v == 0)) {
            const bool inRange = v >= r.lo && v <= r.hi;
            const auto i = static_cast<int64_t>(v);
            const std::string zero = r.zero ? std::string(" (0: ") + r.zero + ")" : std::string();
            if (r.powerOfTwo && (!inRange || (i & (i - 1))))
                fail(what, " ", value, " must be a power of two from ", exactText(r.lo), " to ",
                     exactText(r.hi), zero);
            if (!inRange)
                fail(what, " ", value, " is out of range [", exactText(r.lo), ", ", exactText(r.hi),
                     "]", zero);
        }
        o.*field = static_cast<T>(v);
    };
    const T def = RenderOptions{}.*field;
    p.example = exactText(static_cast<T>(static_cast<T>(r.lo) == def ? r.hi : r.lo));
    return p;
}

template <typename E>
RenderParam choice(RenderParam p, E RenderOptions::*field, E (*parse)(const std::string&),
                   const char* (*name)(E), E example) {
    p.text = [field, name](const RenderOptions& o) { return std::string(name(o.*field)); };
    p.set = [field, parse](RenderOptions& o, const std::string& value) { o.*field = parse(value); };
    p.example = name(example);
    return p;
}

// A number or "file" (stored as −1): the scene file's value per object,
// else the default.
template <typename T>
RenderParam fileOrNumber(RenderParam p, T RenderOptions::*field, Range r) {
    RenderParam n = number(std::move(p), field, r);
    n.kind = api::RenderParameter::Kind::RealOrFile;
    n.text = [field, text = n.text](const RenderOptions& o) {
        return o.*field < 0 ? std::string("file") : text(o);
    };
    n.set = [field, set = n.set](RenderOptions& o, const std::string& value) {
        if (value == "file")
            o.*field = -1;
        else
            set(o, value);
    };
    return n;
}

// A flag: given, it sets its bool field to `whenGiven` ("--no-specular"
// turns the highlight off, "--force" turns the cost bounds' override on).
RenderParam flag(RenderParam p, bool RenderOptions::*field, bool whenGiven) {
    p.flag = true;
    p.kind = api::RenderParameter::Kind::Flag;
    p.showDefault = false;
    p.text = [field, whenGiven](const RenderOptions& o) {
        return std::string(o.*field == whenGiven ? "1" : "0");
    };
    p.set = [field, whenGiven](RenderOptions& o, const std::string& value) {
        o.*field = (value == "1") == whenGiven;
    };
    p.example = std::string(1, '1');  // not = "1": GCC 12 warns -Wrestrict when inlined
    return p;
}

// --model: "thesis" sets the thesis' model whole (the rows after it may
// change a part), "object" turns the object's transport on; it reads back
// "thesis" while the transport is off.
RenderParam model(RenderParam p) {
    p.text = [](const RenderOptions& o) {
        return std::string(o.transport == Transport::Off ? "thesis" : "object");
    };
    p.set = [](RenderOptions& o, const std::string& value) {
        if (value == "object") {
            o.transport = Transport::Object;
        } else if (value == "thesis") {
            o.transport = Transport::Off;
            o.profile = ProfileModel::Dipole;
            o.exit = ExitTerm::Jensen;
            o.energy = EnergyTarget::SemiInfinite;
            o.singleScatter = false;
        } else {
            fail("--model ", value, " is not a model (object or thesis)");
        }
    };
    p.example = "thesis";
    return p;
}

using M = std::vector<std::string>;
const M kEvery;  // a frame-wide setting
// The methods that integrate a profile: every one but volumetric.
const M kProfiled{"pyramid", "tsis", "hybrid",       "mis",      "ltsm",
                  "tsm",     "lss",  "hierarchical", "reference"};
constexpr auto kLighting = ParamEffect::Lighting;
constexpr auto kRadiosity = ParamEffect::Radiosity;
constexpr auto kDisplay = ParamEffect::Display;

std::vector<RenderParam> makeParams() {
    using O = RenderOptions;
    return {
        number({"width", "W  image width", kEvery, kRadiosity}, &O::width, {1, 8192}),
        number({"height", "H  image height", kEvery, kRadiosity}, &O::height, {1, 8192}),
        number({"samples", "N  importance samples; lss: samples per pixel",
                M{"tsis", "hybrid", "mis", "lss"}, kRadiosity},
               &O::samples, {1, 1 << 22}),
        number({"seed", "S  random seed", kEvery, kRadiosity}, &O::seed, {0, 0x7fffffff}),
        number({"spacing",
                "MM  sample spacing of reference (default ℓ/2) and hierarchical (default ℓ); ℓ = "
                "1/max σt', the smallest mean free path",
                M{"reference", "hierarchical"}, kRadiosity, false, false},
               &O::spacingMm, {1e-4, 1e4}),
        number({"epsilon", "E  use an octree node whole when its area/distance^2 < E",
                M{"hierarchical"}, kRadiosity},
               &O::epsilon, {0, 1e3}),
        number({"pyramid-epsilon",
                "E  use a node whole when max(radius^2, area/pi) < E·(d^2 + l^2), 0 ≤ E "
                "≤ 1",
                M{"pyramid"}, kRadiosity},
               &O::pyramidEpsilon, {0, 1}),
        number({"pyramid-stride",
                "S  evaluate every S-th pixel and interpolate where the cell is one "
                "surface; 0 = from the mean free path and the pixel size, 1 = every pixel",
                M{"pyramid"}, kRadiosity},
               &O::pyramidStride, {0, 16}),
        choice({"pyramid-cache",
                "C  read B from its copy over the atlas, made once per lighting: on frames "
                "where only the camera moved (camera), never (off) or always",
                M{"pyramid"}, kRadiosity},
               &O::pyramidCache, parsePyramidCache, pyramidCacheName, PyramidCache::Texture),
        // tsis and ltsm split Rd at Rp too when --rd-part is local or global.
        number({"rp-bound",
                "B  Rp is the largest r where Rd(r)·2πr crosses B (tsis, ltsm: with --rd-part "
                "local or global)",
                M{"hybrid", "tsis", "ltsm"}, kRadiosity},
               &O::rpBound, {1e-9, 1e9}),
        number({"rp-k",
                "K  slope of the local/global weights around Rp, 1/mm (tsis, ltsm: with --rd-part "
                "local or global)",
                M{"hybrid", "tsis", "ltsm"}, kRadiosity},
               &O::rpK, {0, 1e6}),
        choice({"rd-part", "P  integrate Rd (full), Rd·Wl (local) or Rd·Wg (global)",
                M{"tsis", "ltsm"}, kRadiosity},
               &O::rdPart, parseRdPart, rdPartName, RdPart::Local),
        model({"model",
               "M  the subsurface model: object (the default: the profile with the object's own "
               "transport, chosen by error against volumetric truth) or thesis (the thesis' "
               "dipole and exit term alone; sets --transport off, --profile dipole, --exit "
               "jensen, --energy semi-infinite); docs/guide/accuracy.md",
               kProfiled, kRadiosity}),
        choice({"profile",
                "P  the radial profile: dipole (Jensen's), better-dipole (d'Eon's), pbd (photon "
                "beam diffusion) or mc (Monte Carlo, cached on disk); docs/guide/accuracy.md",
                kProfiled, kRadiosity},
               &O::profile, parseProfileModel, profileModelName, ProfileModel::Pbd),
        choice({"energy",
                "T  the light the profile lets out: semi-infinite (its own ∫Rd) or object (scaled "
                "up to what the closed object lets out, 1 − σa·4η²·V/S); docs/guide/accuracy.md",
                kProfiled, kRadiosity},
               &O::energy, parseEnergyTarget, energyTargetName, EnergyTarget::Object),
        choice({"transport",
                "T  the object's own transport: off (the profile alone) or object (the "
                "volumetric walk's flux between patches of the surface in place of the "
                "profile's, fitted once per mesh and material and cached); docs/guide/accuracy.md",
                kProfiled, kRadiosity},
               &O::transport, parseTransport, transportName, Transport::Off),
        // The exit term changes only the radiance, but volumetric's radiosity
        // is divided by it.
        choice(
            {"exit", "E  the exit term: jensen (Ft/pi·B) or normalized (Ft/(c·pi)·B, exitance B)",
             kEvery, kRadiosity},
            &O::exit, parseExitTerm, exitTermName, ExitTerm::Normalized),
        flag({"single-scatter",
              "add Jensen et al. 2001's single-scattering term L(1) (docs/guide/accuracy.md, "
              "\"Where the "
              "error lives now\")",
              kProfiled, kRadiosity},
             &O::singleScatter, true),
        number({"ltsm-rings", "L  rings of the light-view filter", M{"ltsm", "hybrid"}, kRadiosity},
               &O::ltsmRings, {0, 64}),
        number({"ltsm-per-ring", "C  samples per ring (L×C+1 in all)", M{"ltsm", "hybrid"},
                kRadiosity},
               &O::ltsmPerRing, {1, 256}),
        number({"mis-distance", "M  distance-driven samples per pixel and light", M{"mis"},
                kRadiosity},
               &O::misDistanceSamples, {0, 1 << 16}),
        number({"tsm-radius",
                "K  filter radius K/σtr of the widest channel, at most the object's "
                "bounding radius",
                M{"tsm"}, kRadiosity},
               &O::tsmRadius, {1e-3, 1e3}),
        number({"spp", "N  paths per pixel (default 16; with --time: until the time is up)",
                M{"volumetric"}, kRadiosity, false, false},
               &O::spp, {1, 1 << 20}),
        number({"spp-offset",
                "K  the first pass's index: batches of one frame (--spp N each at offsets 0, N, "
                "2N, …; tsis.distributed) whose spp-weighted mean is the whole frame",
                M{"volumetric"}, kRadiosity},
               &O::sppOffset, {0, 1 << 19}),
        number({"max-scatterings",
                "N  sum each path's scattering orders up to N (its N-th scattering's "
                "connection and, with --env, its leaving into the map; 1: single scattering "
                "alone, the term --single-scatter models; 0 = every order)",
                M{"volumetric"}, kRadiosity},
               &O::maxScatterings, {1, 1 << 20, false, "every order"}),
        number({"min-scatterings",
                "N  sum each path from its N-th scattering on (1: without the environment seen "
                "straight through the object, which no subsurface model makes; 2: multiple "
                "scattering alone)",
                M{"volumetric"}, kRadiosity},
               &O::minScatterings, {0, 1 << 20}),
        choice({"estimator",
                "E  camera (paths from each pixel, connected to the lights) or light (photons "
                "from the lights, connected to the pinhole; --spp N: N × the covered pixels "
                "photons)",
                M{"volumetric"}, kRadiosity},
               &O::estimator, parseVolumetricEstimator, volumetricEstimatorName,
               VolumetricEstimator::Light),
        number({"time", "S  stop after S seconds of paths (whole passes)", M{"volumetric"},
                kRadiosity, false, false},
               &O::timeSeconds, {1e-3, 1e6}),
        number({"atlas-res",
                "R  atlas resolution, a power of two; 0 = 256 when a 256² atlas' texels are "
                "within 1/8 of the shortest mean free path 1/σt' and no texture or surface map "
                "is read, else 512",
                kEvery, kLighting},
               &O::atlasResolution, {16, 4096, true, "automatic"}),
        number({"light-res",
                "R  shadow/light-view map resolution; 0 = 2048 when the object is over 100 "
                "diffusion lengths 1/max σtr across, else 1024",
                kEvery, kLighting},
               &O::lightResolution, {16, 8192, false, "automatic"}),
        number(
            {"light-lod",
             "T  a mesh of over 2T triangles (T ≥ 1000) casts its shadows from a coarser copy of "
             "about T; 0 = always the mesh itself",
             kEvery, kLighting},
            &O::lightLodTriangles, {1000, 1 << 30, false, "off"}),
        number({"exposure",
                "EV  radiance × 2^EV before the tone curve (fixed: the same for every frame and "
                "light; docs/guide/rendering.md \"Exposure, reflection and antialiasing\")",
                kEvery, kDisplay},
               &O::exposure, {-30, 30}),
        flag({"auto-exposure",
              "expose each frame by its own log-average luminance (--key) instead of --exposure",
              kEvery, kDisplay},
             &O::autoExposure, true),
        number({"key", "K  --auto-exposure's key: key/L_avg × radiance", kEvery, kDisplay}, &O::key,
               {1e-4, 100}),
        choice({"tone",
                "T  the display's tone curve after the exposure: reinhard (Ls/(1+Ls)), aces "
                "(Narkowicz's ACES fit) or none (linear, clamped to 1)",
                kEvery, kDisplay},
               &O::tone, parseToneCurve, toneCurveName, ToneCurve::Aces),
        choice({"background",
                "B  what the image shows around the object: color (a dark gradient), "
                "transparent (alpha 0 in the PNG) or env (the --env map through the camera)",
                kEvery, kDisplay},
               &O::background, parseBackground, backgroundName, Background::Env),
        fileOrNumber({"roughness",
                      "R  the surface's GGX roughness (alpha = R^2), 0.05 to 1, for every "
                      "object; file: each object's from its file (glTF roughnessFactor and "
                      "metallic-roughness texture, OBJ Pr or Ns and map_Pr), 0.3 where it has "
                      "none",
                      kEvery, kDisplay},
                     &O::roughness, {0.05, 1}),
        flag({"no-specular", "turn off the surface reflection (the GGX lobe)", kEvery, kDisplay},
             &O::specular, false),
        number({"aa", "N  N×N composite samples per pixel (antialiased silhouettes); 1 = off",
                kEvery, kDisplay},
               &O::aa, {1, 4}),
        choice({"aa-method",
                "M  how silhouettes are antialiased: samples (--aa N×N composite samples at the "
                "pixels along them) or fxaa (one sample a pixel, then an FXAA-style pass over the "
                "display image; --aa not read)",
                kEvery, kDisplay},
               &O::aaMethod, parseAaMethod, aaMethodName, AaMethod::Fxaa),
        // Not the pixels: whether a costly run may start (method_reference.h).
        flag({"force", "run even past the cost bounds (points, memory, Rd evaluations)",
              M{"reference"}, ParamEffect::None},
             &O::force, true),
        flag({"no-reuse-lighting",
              "make the light maps and flux atlas every frame, even when the lighting did not "
              "change",
              kEvery, ParamEffect::None},
             &O::reuseLighting, false),
    };
}

}  // namespace

bool RenderParam::usedBy(const std::string& method) const {
    return methods.empty() || std::find(methods.begin(), methods.end(), method) != methods.end();
}

std::string RenderParam::usage() const {
    // "METAVAR  text": the methods go between.
    const size_t gap = help.find("  ");
    std::string owners;
    for (const std::string& m : methods) owners += (owners.empty() ? "" : ", ") + m;
    std::string line = owners.empty() ? help
                       : gap == std::string::npos
                           ? owners + ": " + help  // a flag
                           : help.substr(0, gap + 2) + owners + ": " + help.substr(gap + 2);
    if (showDefault) line += " (default " + text(RenderOptions{}) + ")";
    return line;
}

bool RenderParam::isDefault(const RenderOptions& o) const {
    return text(o) == text(RenderOptions{});
}

const std::vector<RenderParam>& renderParams() {
    static const std::vector<RenderParam> params = makeParams();
    return params;
}

const RenderParam* findRenderParam(const std::string& name) {
    for (const RenderParam& p : renderParams())
        if (p.name == name) return &p;
    return nullptr;
}

std::string foreignParamMessage(const RenderParam& p, const std::string& method) {
    if (p.usedBy(method)) return "";
    std::string owners;
    for (size_t i = 0; i < p.methods.size(); ++i)
        owners += (i == 0 ? "" : i + 1 == p.methods.size() ? " and " : ", ") + p.methods[i];
    return "--" + p.name + " is a parameter of " + owners + ", not of " + method;
}

void checkParamsRead(const RenderOptions& o) {
    for (const RenderParam& p : renderParams())
        if (!p.isDefault(o))
            if (const std::string foreign = foreignParamMessage(p, o.method); !foreign.empty())
                fail(foreign);
}

}  // namespace tsis
