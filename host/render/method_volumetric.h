// --method volumetric: volumetric light transport in the mesh's interior, the
// physical truth the dipole model approximates (docs/design.md §4; measured in
// docs/guide/accuracy.md "Physical accuracy").
//
// The problem. A homogeneous medium fills the closed mesh: σs = σs′ with an
// isotropic phase function (the similarity relation the dipole rests on),
// σa, and a smooth dielectric boundary of relative index η with the exact
// Fresnel reflectance, chosen stochastically (reflect with probability Fr) at
// every hit from inside. Point and directional lights and the pinhole camera
// of the other methods; refraction at the flat facets' geometric normals.
//
// The estimators (--estimator). camera, the default: a path tracer from the camera. Each covered
// pixel's ray (eye → the G-buffer's surface point) refracts in (deterministic: Ft/η² for the
// radiance crossing out), then random-walks: free flights with the σt of a
// hero channel drawn per path, the other two channels weighted by the
// one-sample balance heuristic (volumetric/medium.h), internal Fresnel
// reflection or exit at the boundary, Russian roulette on weak paths. At every
// scattering vertex x, next-event estimation *through the boundary*: a point
// or directional light reaches x only along the refracted path light → y → x,
// whose entry point y Snell's law fixes; volumetric/refracted_light.h solves
// it on the facet and gives the refracted irradiance (Fresnel transmittance
// and the beam's spreading included).
// light: its twin from the lights (volumetric/light_trace.h): photons refract
// in and random-walk the same way, and every scattering vertex is connected
// to the pinhole through the boundary by the same solve with the eye as the
// source; each connection lands in the pixel its exit point projects to, so
// it estimates each pixel's mean radiance (the camera walk: its centre's).
// A pass traces as many photons as there are covered pixels. The two agree
// within noise (light_trace_test.cpp; tests/volumetric_truth_test.cpp holds
// the camera walk to the light tracer's truth of two spheres).
//
// Bias. None for the paths it samples; it misses light reflected inside the
// object between entering and its first scattering (Fr ≈ 2–4% of light that
// crossed the object unscattered, e^(−σt·thickness) of it), entry points
// neither the facet iteration nor the search around its cycle finds
// (`volumetric_nee_unsettled` of `volumetric_nee` in --stats) and, of the
// facets whose refracted beams overlap at a point, those not connected to
// the settled one through facets that reach it too (a lens' caustic near the
// far side: light that crossed the object unscattered). Before every
// overlapping facet was summed (the focusing of a curved surface), it was
// 5–8% dark on a 10 mm marble sphere and the tests' cone-lit sphere 9–14%.
// It excludes, like every method, the specular reflection of the lights at
// the camera's point and light transmitted without scattering. Both vanish
// on optically thick objects; the semi-infinite slab is exact
// (volumetric_test.cpp checks it against an independent light tracer and
// closed forms).
//
// Variance falls as 1/√spp (tested). The output: B_eq = π·L / (Ft(η, cos θo)·s)
// with cos θo at the interpolated normal and s the --exit term's scale, the
// radiosity that the renderer's exit term (L = Ft/π·s·B) turns into the
// path-traced radiance L; so
// radiance.exr is the volumetric radiance and `tsis compare` of radiance.exr
// (or radiosity.exr) against another method measures the whole model's error.
//
// Budgets: `--spp N` paths per pixel (default 16; light: N passes of photons) and `--time S` (stop
// after the pass that passes S seconds; without --spp it runs until then). Each (pixel, path) pair
// has its own random stream from --seed, so an --spp render is the same bytes for any thread count.
// Progress on a terminal. Cost: ~ events per path × (1 + 2–3 per NEE) rays; Embree on the host
// cores.
#pragma once

#include <memory>

#include "render/method.h"
#include "volumetric/mesh_boundary.h"

namespace tsis {

class VolumetricMethod : public Method {
  public:
    explicit VolumetricMethod(ClRuntime& cl);
    const char* name() const override { return "volumetric"; }
    void addPasses(FrameGraph& graph, const FrameContext& ctx) override;

    // The default paths per pixel when neither --spp nor --time is given.
    static constexpr int kDefaultSpp = 16;

  private:
    void render(const FrameContext& ctx, const SurfacePoints& points, cl::Buffer& radiosity,
                FrameStats& stats);

    ClRuntime& cl_;
    std::unique_ptr<MeshBoundary> boundary_;
    uint64_t meshKey_ = 0;
};

}  // namespace tsis
