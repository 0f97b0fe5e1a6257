// How a frame is rendered (as opposed to what it shows: scene/scene.h).
#pragma once

#include <cstdint>
#include <string>

namespace tsis {

// Where the pyramid reads B (render/method_pyramid.h): at the frame's pixels
// always (Pixels), from its texture-space copy when only the camera moved
// (Camera), or from that copy always (Texture).
enum class PyramidCache { Pixels, Camera, Texture };
// "off", "camera" or "always"; throws tsis::Error for anything else.
PyramidCache parsePyramidCache(const std::string& name);
const char* pyramidCacheName(PyramidCache cache);

// What tsis and ltsm integrate: Rd, Rd·Wl or Rd·Wg (the hybrid's split).
enum class RdPart { Full, Local, Global };
// "full", "local" or "global"; throws tsis::Error for anything else.
RdPart parseRdPart(const std::string& name);
const char* rdPartName(RdPart part);

// The radial profile Rd every method integrates (render/profiles.h): the
// classical dipole (Jensen et al. 2001), d'Eon's better dipole
// (physics/better_dipole.h), photon beam diffusion (physics/beam_diffusion.h)
// or the slab's Monte Carlo, cached on disk (volumetric/mc_profile.h).
enum class ProfileModel { Dipole, BetterDipole, Pbd, Mc };
// "dipole", "better-dipole" or "pbd"; throws tsis::Error for anything else.
ProfileModel parseProfileModel(const std::string& name);
const char* profileModelName(ProfileModel model);

// The composite's exit term, radiance from radiosity: Jensen's Ft(η, cosθo)/π
// or pbrt's normalised Ft(η, cosθo)/(c·π), whose exitance is B
// (physics/fresnel.h normalizedExitScale).
enum class ExitTerm { Jensen, Normalized };
// "jensen" or "normalized"; throws tsis::Error for anything else.
ExitTerm parseExitTerm(const std::string& name);
const char* exitTermName(ExitTerm exit);
// The exit term's factor over Jensen's Ft/π for relative index eta.
double exitScale(ExitTerm exit, double eta);

// The lobe's roughness R of an object whose file gives `fileRoughness` (< 0:
// none) under RenderOptions::roughness.
double surfaceRoughness(float optionRoughness, double fileRoughness);

// The light the profile lets out (render/energy_target.h): the semi-infinite
// profile's own ∫Rd, or scaled up to what the finite closed object lets out.
enum class EnergyTarget { SemiInfinite, Object };
// "semi-infinite" or "object"; throws tsis::Error for anything else.
EnergyTarget parseEnergyTarget(const std::string& name);
const char* energyTargetName(EnergyTarget energy);

// The object's own transport (render/object_transport.h): off, or the
// volumetric walk's patch-to-patch flux in place of the profile's, added to
// every profile method's radiosity.
enum class Transport { Off, Object };
// "off" or "object"; throws tsis::Error for anything else.
Transport parseTransport(const std::string& name);
const char* transportName(Transport transport);

// volumetric's estimator (render/method_volumetric.h): paths from the camera
// (connected to the lights through the boundary) or photons from the lights
// (connected to the pinhole).
enum class VolumetricEstimator { Camera, Light };
// "camera" or "light"; throws tsis::Error for anything else.
VolumetricEstimator parseVolumetricEstimator(const std::string& name);
const char* volumetricEstimatorName(VolumetricEstimator estimator);

// The display's tone curve (gl/shaders/common.glsl toneCurve, docs/guide/rendering.md
// "Exposure, reflection and antialiasing"): Reinhard's Ls/(1 + Ls), ACES
// fitted (Narkowicz 2015) or none (the exposed radiance clamped to [0, 1]).
// The values are the shader's u_tone.
enum class ToneCurve { Reinhard = 0, Aces = 1, None = 2 };
// "reinhard", "aces" or "none"; throws tsis::Error for anything else.
ToneCurve parseToneCurve(const std::string& name);
const char* toneCurveName(ToneCurve tone);

// What the display shows where the object does not (gl/passes.h
// DisplayBackground): the dark gradient (color), nothing (transparent: alpha
// 0 in the PNG, the radiance EXR's alpha the coverage) or the --env map seen
// through the camera (env). The values are the shader's u_background.
enum class Background { Color = 0, Transparent = 1, Env = 2 };
// "color", "transparent" or "env"; throws tsis::Error for anything else.
Background parseBackground(const std::string& name);
const char* backgroundName(Background background);

// The user-set fields' names, ranges, help and the methods that read them
// are declared once, in render/render_params.cpp; a new field needs a row there.
struct RenderOptions {
    std::string method = "pyramid";  // the most accurate per ms measured (docs/guide/methods.md)
    int width = 512, height = 512;
    int atlasResolution = 512;  // flux/position atlas (power of two; bench/results/frame.md)
    // Shadow map and light-view flux map; 0 = from the object's size in
    // diffusion lengths (autoLightResolution in render/renderer.h)
    int lightResolution = 0;
    // The shadow maps of a mesh of over twice this many triangles are drawn
    // from a coarser copy of about this many (mesh/lod.h); 0 = always the mesh.
    int lightLodTriangles = 300000;
    int samples = 900;  // N, the shared importance samples (tsis, hybrid global part)
    uint32_t seed = 1;
    // The display (docs/design.md "The composite"): radiance × 2^exposure before the tone
    // curve, a fixed exposure (docs/guide/rendering.md "Exposure, reflection and antialiasing"), or
    // with autoExposure each frame's key/L_avg (Reinhard's key, the log-average luminance).
    float exposure = 3.3f;
    bool autoExposure = false;
    float key = 0.18f;
    ToneCurve tone = ToneCurve::Reinhard;
    Background background = Background::Color;
    // The GGX lobe (physics/ggx.h): on, and its roughness R (α = R²) for
    // every object; < 0 ("file"): each object's from its file where it has
    // one, else kDefaultRoughness (0.3 reads as polished marble or skin).
    bool specular = true;
    float roughness = -1.0f;
    // Composite samples per pixel along each axis (docs/design.md "The composite").
    int aa = 2;
    // Hybrid split (docs/design.md §4): Rp where Rd·2πr crosses rpBound; Wl's slope K (mm⁻¹).
    double rpBound = 0.1;
    double rpK = 1.5;
    RdPart rdPart = RdPart::Full;  // tsis/ltsm: Rd, Rd·Wl or Rd·Wg
    // The thesis' model (bench/tables keeps it); docs/guide/accuracy.md "Physical accuracy"
    // measures the others against volumetric transport.
    ProfileModel profile = ProfileModel::Dipole;
    ExitTerm exit = ExitTerm::Jensen;
    // Add Jensen et al. 2001's single-scattering term L⁽¹⁾ to the profile
    // methods' radiosity (render/single_scatter.h; volumetric has it already).
    bool singleScatter = false;
    EnergyTarget energy = EnergyTarget::SemiInfinite;  // docs/guide/accuracy.md "Physical accuracy"
    // The object's own transport (render/object_transport.h): the default,
    // chosen by error against volumetric truth; --model thesis turns it off.
    Transport transport = Transport::Object;
    VolumetricEstimator estimator = VolumetricEstimator::Camera;
    int ltsmRings = 4;  // ltsm / hybrid local part: L rings of C samples + the centre
    int ltsmPerRing = 4;
    int misDistanceSamples = 16;  // mis: distance-driven samples per pixel and light
    double spacingMm = 0;         // reference / hierarchical sample spacing; 0 = the method's rule
    bool force = false;           // reference: run past its cost bounds (method_reference.h)
    float epsilon = 0.05f;        // hierarchical: a node is used whole when ΔA/r² < epsilon
    // pyramid: a node is used whole when max(radius², area/π) < ε·(d² + ℓ²)
    float pyramidEpsilon = 0.05f;
    // pyramid: evaluate every s-th pixel, interpolate between; 0 = by ℓ and the
    // pixel's size (method_pyramid.h), 1 = every pixel
    int pyramidStride = 0;
    PyramidCache pyramidCache = PyramidCache::Camera;
    double tsmRadius = 2.0;  // tsm: filter radius in 1/σtr of the widest channel
    // volumetric: paths per pixel (0 = 16, or unbounded with timeSeconds) and
    // a time budget in seconds (0 = none); render/method_volumetric.h.
    int spp = 0;
    double timeSeconds = 0;
    // volumetric: the index of the first pass, so that batches of one frame
    // (offsets 0, N, 2N, … of --spp N each) draw the passes the whole frame
    // draws: their spp-weighted mean is its image.
    int sppOffset = 0;
    // Copy radiosity/radiance/position/normal/coverage/atlas to the host result.
    bool keepAovs = false;
    // Average this frame's radiosity with the frames before it while nothing
    // that changes the radiosity changed (render/accumulator.h); each frame
    // draws a new sample set.
    bool progressive = false;
    // Keep the light maps and the flux atlas (GL and CL copies) from the frame
    // before while the mesh, lights, η and resolutions are unchanged: a frame
    // that moves only the camera or changes σ, N or the method skips them.
    bool reuseLighting = true;
};

// Whether the frame adds the single-scattering term (render/single_scatter.h).
inline bool addsSingleScatter(const RenderOptions& o) {
    return o.singleScatter && o.method != "volumetric";
}

// Whether the frame adds the object's transport (render/object_transport.h).
inline bool addsTransport(const RenderOptions& o) {
    return o.transport == Transport::Object && o.method != "volumetric";
}

// Checks the method's name and every parameter's value against its row of
// render/render_params.h, what the renderer and the methods would otherwise
// refuse only after the mesh is loaded and GL/CL started. Throws tsis::Error.
void validateRenderOptions(const RenderOptions& o);

}  // namespace tsis
