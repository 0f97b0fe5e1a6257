// How a frame is rendered (as opposed to what it shows: scene/scene.h).
#pragma once

#include <cstdint>
#include <string>

#include "tsis/render_settings.h"

namespace tsis {

using api::AaMethod;
using api::Background;
using api::EnergyTarget;
using api::ExitTerm;
using api::ProfileModel;
using api::PyramidCache;
using api::RdPart;
using api::ToneCurve;
using api::Transport;
using api::VolumetricEstimator;

// Where the pyramid reads B (render/method_pyramid.h): at the frame's pixels
// always (Pixels), from its texture-space copy when only the camera moved
// (Camera), or from that copy always (Texture).
// "off", "camera" or "always"; throws tsis::Error for anything else.
PyramidCache parsePyramidCache(const std::string& name);
const char* pyramidCacheName(PyramidCache cache);

// What tsis and ltsm integrate: Rd, Rd·Wl or Rd·Wg (the hybrid's split).
// "full", "local" or "global"; throws tsis::Error for anything else.
RdPart parseRdPart(const std::string& name);
const char* rdPartName(RdPart part);

// The radial profile Rd every method integrates (render/profiles.h): the
// classical dipole (Jensen et al. 2001), d'Eon's better dipole
// (physics/better_dipole.h), photon beam diffusion (physics/beam_diffusion.h)
// or the slab's Monte Carlo, cached on disk (volumetric/mc_profile.h).
// "dipole", "better-dipole" or "pbd"; throws tsis::Error for anything else.
ProfileModel parseProfileModel(const std::string& name);
const char* profileModelName(ProfileModel model);

// The composite's exit term, radiance from radiosity: Jensen's Ft(η, cosθo)/π
// or pbrt's normalised Ft(η, cosθo)/(c·π), whose exitance is B
// (physics/fresnel.h normalizedExitScale).
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
// "semi-infinite" or "object"; throws tsis::Error for anything else.
EnergyTarget parseEnergyTarget(const std::string& name);
const char* energyTargetName(EnergyTarget energy);

// The object's own transport (render/object_transport.h): off, or the
// volumetric walk's patch-to-patch flux in place of the profile's, added to
// every profile method's radiosity.
// "off" or "object"; throws tsis::Error for anything else.
Transport parseTransport(const std::string& name);
const char* transportName(Transport transport);

// volumetric's estimator (render/method_volumetric.h): paths from the camera
// (connected to the lights through the boundary) or photons from the lights
// (connected to the pinhole).
// "camera" or "light"; throws tsis::Error for anything else.
VolumetricEstimator parseVolumetricEstimator(const std::string& name);
const char* volumetricEstimatorName(VolumetricEstimator estimator);

// The display's tone curve (gl/shaders/common.glsl toneCurve, docs/guide/rendering.md
// "Exposure, reflection and antialiasing"): Reinhard's Ls/(1 + Ls), ACES
// fitted (Narkowicz 2015) or none (the exposed radiance clamped to [0, 1]).
// The values are the shader's u_tone.
// "reinhard", "aces" or "none"; throws tsis::Error for anything else.
ToneCurve parseToneCurve(const std::string& name);
const char* toneCurveName(ToneCurve tone);
AaMethod parseAaMethod(const std::string& name);
const char* aaMethodName(AaMethod method);

// What the display shows where the object does not (gl/passes.h
// DisplayBackground): the dark gradient (color), nothing (transparent: alpha
// 0 in the PNG, the radiance EXR's alpha the coverage) or the --env map seen
// through the camera (env). The values are the shader's u_background.
// "color", "transparent" or "env"; throws tsis::Error for anything else.
Background parseBackground(const std::string& name);
const char* backgroundName(Background background);

// The fields' names, ranges, help and the methods that read them are declared
// once, in render/render_params.cpp; a new field needs a row there. The struct
// is the public API's RenderSettings (include/tsis/render_settings.h): the
// library's callers and the renderer share one type.
using RenderOptions = api::RenderSettings;

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
