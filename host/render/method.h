// The interface every rendering method implements (docs/design.md §4). A method turns
// the frame's shared inputs into radiosity B for every covered pixel by adding
// passes to the frame graph; the renderer owns the GL passes, the hand-offs
// and the composite around it.
#pragma once

#include <glm/mat4x4.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cl/cl_runtime.h"
#include "physics/dipole.h"
#include "render/albedo_atlas.h"
#include "render/frame_graph.h"
#include "render/frame_resources.h"
#include "render/frame_stats.h"
#include "render/profiles.h"
#include "render/render_options.h"
#include "render/scene_media.h"
#include "render/surface_atlas.h"
#include "scene/projection.h"
#include "scene/scene.h"

namespace tsis {

// What the passes share in one frame: plain values known at setup, and the
// handles of the resources the renderer's passes make (resolve them inside a
// pass, through FrameGraph::Resources, after declaring them).
struct FrameContext {
    const Scene* scene = nullptr;
    // The medium this run of the method integrates: the scene's material, or
    // with several, one of them — the renderer runs the method once per
    // material and keeps each point's own (docs/design.md §2 "Materials").
    const Material* material = nullptr;
    // The scene's media, their materials and η (render/scene_media.h).
    const SceneMedia* media = nullptr;
    // The albedo factor per atlas texel (render/albedo_atlas.h; empty: none).
    const AlbedoAtlas* albedo = nullptr;
    // The normal and roughness maps per atlas texel (render/surface_atlas.h; empty: none).
    const SurfaceAtlas* surface = nullptr;
    const RenderOptions* options = nullptr;
    ClRuntime* cl = nullptr;
    FrameStats* stats = nullptr;  // setup-time values; passes report through Resources
    float boundingRadius = 0;     // the object fits in a sphere of this radius at the origin
    uint64_t meshKey = 0;         // render/frame_keys.h meshHash, taken once a frame
    int atlasResolution = 0;
    int width = 0, height = 0;  // the camera image
    glm::mat4 viewProj{1.0f};
    glm::vec3 eye{0.0f};
    int lightResolution = 0;
    // Rd's per-channel scale from --energy (render/energy_target.h); 1 for
    // the semi-infinite profile.
    glm::dvec3 profileScale{1.0};
    // Progressive accumulation: frames of the same view already averaged, so
    // this frame draws sample set `sampleSet` (0 when not accumulating).
    uint32_t sampleSet = 0;
    // The lighting's key (render/frame_keys.h): the light views and the flux
    // atlas are those of the last frame with the same one. cameraMoved: the
    // view or the image size differs from the renderer's last frame.
    uint64_t lighting = 0;
    bool cameraMoved = true;
    // The caller's request to stop (null: none): long passes ask it between
    // pieces of their work (stopping() inside parallel loops, which then
    // return early; checkCancel() between them, which throws tsis::Cancelled).
    Cancel* cancel = nullptr;
    bool stopping() const { return cancel && cancel->stopping(); }
    void checkCancel() const {
        if (cancel) cancel->check();
    }

    FrameGraphId<AtlasCl> fluxAtlas;  // flux rgb per texel
    // The environment residual's share of fluxAtlas alone (docs/design.md
    // §12): the texture-space run that lights it for light-view methods reads it.
    FrameGraphId<AtlasCl> residualFluxAtlas;
    FrameGraphId<AtlasCl> positionAtlas;  // xyz, w = 1 where covered
    FrameGraphId<AtlasCl> normalAtlas;    // normal, w = texel area mm²
    FrameGraphId<SurfacePoints> points;   // the covered camera pixels
    // Read by a method that wants its points' atlas coordinates
    // (SurfacePoints::uv): the camera's G-buffer draws them then.
    FrameGraphId<Marker> pointUvs;
    FrameGraphId<CameraBuffersCl> gbuffer;
    FrameGraphId<LightMapsCl> lightMaps;
    // The method's output: points.count float4 (rgb B). Reserve it with
    // radiosityBuffer() inside the pass that writes it.
    FrameGraphId<RadiosityCl> radiosity;

    // The longest distance between two surface points: profile tables reach it.
    double maxDistance() const { return maxSurfaceDistance(boundingRadius); }
    // The part of Rd this run integrates where its method does not choose:
    // all of it, but the part a light-view method misses of the residual.
    RdPart rdPart = RdPart::Full;
    // The profile every method integrates: --profile's Rd (or one of the
    // hybrid's parts), scaled by --energy.
    KeyedProfile profile(RdPart part) const {
        return scaledProfile(radialProfile(*material, *options, part), profileScale);
    }
    KeyedProfile profile() const { return profile(rdPart); }
    cl::Buffer& radiosityBuffer(const FrameGraph::Resources& res, int pointCount) const {
        return res.write(radiosity).storage->reserve(
            cl->context(), static_cast<size_t>(std::max(pointCount, 1)) * 16);
    }
};

// The seed of a frame's hashed random numbers: --seed, moved on for each
// progressive sample set (--seed itself for set 0).
inline uint32_t frameSeed(const FrameContext& ctx) {
    return ctx.options->seed + 0x9e3779b9u * ctx.sampleSet;
}

class Method {
  public:
    virtual ~Method() = default;
    virtual const char* name() const = 0;
    // Adds the passes that write ctx.radiosity, declaring what each reads
    // (ctx's handles, the method's own), so passes nobody needs are culled.
    // Setup only declares: tables, buffers and kernels are made inside the
    // passes that need them.
    virtual void addPasses(FrameGraph& graph, const FrameContext& ctx) = 0;
    // The part of Rd through which the method cannot see the environment's
    // residual (it reads only the lights' views): the renderer adds that part
    // by a texture-space run over the residual's flux alone (docs/design.md
    // §12). None: the method sees the residual itself.
    virtual std::optional<RdPart> missesResidual(const RenderOptions&) const {
        return std::nullopt;
    }
    // B over the atlas, when the method holds a copy made for this frame's
    // surface (ctx.lighting, the profile, the options), for the composite to
    // read B at the pixels from instead of running the method (a frame that
    // only moved the camera: docs/design.md §6); nullptr: none.
    virtual const AtlasRadiosity* atlasRadiosity(const FrameContext&) { return nullptr; }
};

std::unique_ptr<Method> makeMethod(const std::string& name, ClRuntime& cl);
std::vector<std::string> methodNames();

}  // namespace tsis
