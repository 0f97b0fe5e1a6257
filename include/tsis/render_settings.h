// How a frame is rendered, typed: the settings Renderer::render takes (what
// the frame shows is the Scene's). Each field is one option of `tsis render`
// (its name in the comment; docs/guide/options.md lists its range and the
// methods that read it); the renderer itself renders from this struct, so a
// field is what the option sets, default included. A field the chosen method
// does not read, left off its default, is an error (tsis::Error naming it),
// as the option is on the command line.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace tsis::api {

// pyramid-cache: where the pyramid reads the radiosity it gathers: the frame's
// pixels (off), their texture-space copy when only the camera moved (camera),
// or that copy always (always).
enum class PyramidCache { Pixels, Camera, Texture };
// rd-part: what tsis and ltsm integrate: Rd, Rd·Wl or Rd·Wg (the hybrid's split).
enum class RdPart { Full, Local, Global };
// profile: the radial profile every method integrates: the classical dipole
// (Jensen et al. 2001), d'Eon's better dipole, photon beam diffusion, or the
// slab's Monte Carlo (cached on disk).
enum class ProfileModel { Dipole, BetterDipole, Pbd, Mc };
// exit: radiance from radiosity: Jensen's Ft(η, cosθo)/π or the normalised
// Ft(η, cosθo)/(c·π) whose exitance is the radiosity.
enum class ExitTerm { Jensen, Normalized };
// energy: the light the profile lets out: the semi-infinite profile's own ∫Rd,
// or scaled up to what the finite closed object lets out.
enum class EnergyTarget { SemiInfinite, Object };
// transport: the object's own patch-to-patch transport (from the volumetric
// walk) in place of the profile's far field, or off (the thesis' model).
enum class Transport { Off, Object };
// estimator: volumetric's paths from the camera or photons from the lights.
enum class VolumetricEstimator { Camera, Light };
// tone: the display's curve: Reinhard's Ls/(1 + Ls), ACES fitted (Narkowicz
// 2015) or none (the exposed radiance clamped to [0, 1]).
enum class ToneCurve { Reinhard = 0, Aces = 1, None = 2 };
// aa-method: the silhouettes antialiased by aa × aa composite samples at
// the pixels along them, or by an FXAA-style pass over the display image
// (one sample a pixel; aa not read).
enum class AaMethod { Samples = 0, Fxaa = 1 };
// background: where the object is not: the dark gradient (color), nothing
// (transparent: alpha 0), or the scene's environment map (env).
enum class Background { Color = 0, Transparent = 1, Env = 2 };

// One render option as RenderSettings::set and get take it.
struct RenderParameter {
    enum class Kind {
        Integer,
        Real,
        RealOrFile,  // a number or "file" (the scene file's own, per object)
        Choice,      // a name: "aces", "camera", …
        Flag,        // "true" or "false"; given on the command line it is "true"
    };
    std::string name;                  // the option: "mis-distance"
    std::string help;                  // its line of `tsis render --help`
    std::vector<std::string> methods;  // the methods that read it; empty: every method
    Kind kind = Kind::Choice;
};

struct RenderSettings {
    // method: pyramid, tsis, hybrid, mis, ltsm, tsm, lss, hierarchical,
    // reference or volumetric (docs/guide/methods.md); pyramid is the most
    // accurate per millisecond measured.
    std::string method = "pyramid";
    int width = 512, height = 512;  // width, height (pixels)
    // atlas-res: the flux/position atlas (a power of two); 0 = from the
    // object's size in mean free paths (autoAtlasResolution: 256 or 512)
    int atlasResolution = 0;
    // light-res: shadow map and light-view flux map; 0 = from the object's
    // size in diffusion lengths.
    int lightResolution = 0;
    // light-lod: the shadow maps of a mesh of over twice this many triangles
    // are drawn from a coarser copy of about this many; 0 = always the mesh.
    int lightLodTriangles = 300000;
    int samples = 900;  // samples: N, the shared importance samples (tsis, hybrid)
    uint32_t seed = 1;  // seed: the same seed and inputs give the same image
    // exposure: radiance × 2^exposure before the tone curve; auto-exposure:
    // each frame's key / log-average luminance instead (key).
    float exposure = 3.3f;
    bool autoExposure = false;
    float key = 0.18f;
    ToneCurve tone = ToneCurve::Reinhard;
    Background background = Background::Color;
    // no-specular turns the GGX lobe off; roughness R (α = R²) for every
    // object, < 0 ("file"): each object's from its file, else 0.3.
    bool specular = true;
    float roughness = -1.0f;
    int aa = 2;  // aa: composite samples per pixel along each axis
    AaMethod aaMethod = AaMethod::Samples;
    // rp-bound, rp-k: the hybrid's split (Rp where Rd·2πr crosses rp-bound;
    // Wl's slope K in mm⁻¹).
    double rpBound = 0.1;
    double rpK = 1.5;
    RdPart rdPart = RdPart::Full;
    // profile, exit, single-scatter, energy, transport: the model the methods
    // integrate (docs/guide/accuracy.md "Physical accuracy"); the default is
    // the one closest to volumetric truth, --model thesis the thesis'.
    ProfileModel profile = ProfileModel::Dipole;
    ExitTerm exit = ExitTerm::Jensen;
    bool singleScatter = false;
    EnergyTarget energy = EnergyTarget::SemiInfinite;
    Transport transport = Transport::Object;
    VolumetricEstimator estimator = VolumetricEstimator::Camera;
    int ltsmRings = 4;  // ltsm-rings, ltsm-per-ring: L rings of C samples + the centre
    int ltsmPerRing = 4;
    int misDistanceSamples = 16;  // mis-distance: distance-driven samples per pixel and light
    double spacingMm = 0;   // spacing: reference/hierarchical sample spacing; 0 = the method's rule
    bool force = false;     // force: reference runs past its cost bounds
    float epsilon = 0.05f;  // epsilon: hierarchical uses a node whole when ΔA/r² < epsilon
    // pyramid-epsilon: a node is used whole when max(radius², area/π) < ε·(d² + ℓ²)
    float pyramidEpsilon = 0.05f;
    // pyramid-stride: evaluate every s-th pixel, interpolate between; 0 = by
    // the profile's length and the pixel's size, 1 = every pixel.
    int pyramidStride = 0;
    PyramidCache pyramidCache = PyramidCache::Camera;
    double tsmRadius = 2.0;  // tsm-radius: filter radius in 1/σtr of the widest channel
    // spp, time: volumetric's paths per pixel (0 = 16, or unbounded with a
    // time) and its time budget in seconds (0 = none).
    int spp = 0;
    double timeSeconds = 0;
    // spp-offset: the index of volumetric's first pass, so that batches of one
    // frame (offsets 0, N, 2N, … of spp N each) draw the passes the whole frame
    // draws: their spp-weighted mean is its image.
    int sppOffset = 0;
    // max-scatterings: volumetric's paths end at their N-th scattering (after
    // its connection to the lights or the eye); 0 = none (all orders), 1 =
    // single scattering alone.
    int maxScatterings = 0;
    // min-scatterings: volumetric sums each path from its N-th scattering on
    // (0: from none, the environment seen straight through the object
    // counted; 1: without it; 2: multiple scattering alone).
    int minScatterings = 0;
    // Renderer::render always keeps the AOVs (Frame's images); the CLI keeps
    // them only for --aov.
    bool keepAovs = false;
    // Average this frame's radiosity with the frames before it while nothing
    // that changes it changed (each frame draws a new sample set).
    bool progressive = false;
    // no-reuse-lighting clears it: keep the light maps and the flux atlas from
    // the frame before while the mesh, lights, η and resolutions are unchanged.
    bool reuseLighting = true;

    // The field of option `name` ("method" or one of parameters()) set from
    // its value as typed ("2.5", "aces", "file"; a flag "true" or "false"),
    // checked as the command line checks it: throws tsis::Error and keeps
    // the field.
    void set(const std::string& name, const std::string& value);
    // The field of option `name` as typed (a flag: "true" when its option
    // is given, "no-specular" so when specular is false).
    std::string get(const std::string& name) const;
    // The render options, one row each, in `tsis render --help`'s order.
    static const std::vector<RenderParameter>& parameters();
};

}  // namespace tsis::api
