// The GL side of a frame (gl/passes.h) as frame-graph passes: the mesh upload,
// the light views, the geometry and flux atlases, the camera G-buffer and the
// composite. Each is redone only when what it depends on changed; the
// versions it hands on change exactly when its contents do.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "gl/gpu_mesh.h"
#include "gl/passes.h"
#include "render/env_light.h"
#include "render/frame_graph.h"
#include "render/frame_resources.h"
#include "render/method.h"

namespace tsis {

// A GL render target a pass wrote, and the version of its contents.
struct GlTarget {
    const RenderTarget* target = nullptr;
    uint64_t version = 0;
};

struct GlLights {
    const std::vector<LightView>* views = nullptr;
    const ShadowMapArray* shadows = nullptr;
    uint64_t version = 0;  // changes whenever the views are drawn again
    // Scatter views only: the views hold the shadow maps' depth alone
    // (ScatterViewPass::copyDepth), not a draw's position and normal.
    bool depthOnly = false;
};

// The tone-mapped frame and the radiance it was made from.
struct FrameImage {
    std::vector<uint8_t> rgb8;    // sRGB, row 0 = top
    std::vector<uint8_t> alpha8;  // with Background::Transparent the coverage, else empty
    std::vector<float> radiance;  // RGBA, GL row order; only with RenderOptions::keepAovs
    float lavg = 1;               // log-average luminance of the radiance
    float exposureScale = 1;      // Ls = exposureScale·L before the tone curve
};

struct RasterHandles {
    FrameGraphId<const GpuMesh*> mesh;
    FrameGraphId<GlLights> lights;
    // The single-scattering term's views (gl/light_view.h
    // updateScatterView); none without --single-scatter.
    FrameGraphId<GlLights> scatterViews;
    FrameGraphId<GlTarget> geometryAtlas, fluxAtlas, gbuffer;
    // The flux atlas of the environment's residual alone (none without --env).
    FrameGraphId<GlTarget> residualFluxAtlas;
    // The composite's geometry: positions and normals at --aa × the frame's
    // size (the G-buffer itself at 1×).
    FrameGraphId<GlTarget> samples;
};

// The log-average luminance (Reinhard's L_avg) of RGBA pixels whose alpha > 0:
// the reference for the composite's, summed on the GPU side.
float logAverageLuminance(const std::vector<float>& rgba);

// The factor on radiance before the tone curve: 2^exposure, or with
// autoExposure key/L_avg (docs/design.md "The composite").
float exposureScale(const RenderOptions& o, float lavg);

class RasterPasses {
  public:
    // Adds the passes up to the G-buffer. `lightMapsCl` and `gbufferCl` say
    // (through FrameGraph::isRead) whether the light views need their flux and
    // position maps and the G-buffer its irradiance.
    RasterHandles addPasses(FrameGraph& graph, const FrameContext& ctx, uint64_t meshHash,
                            uint64_t lightingKey, FrameGraphId<LightMapsCl> lightMapsCl,
                            FrameGraphId<CameraBuffersCl> gbufferCl);
    // Radiance L = Ft/π·B (× the exit term's scale) + the GGX lobe per
    // sample, then exposure, the tone curve, the samples' mean and sRGB.
    FrameGraphId<FrameImage> addComposite(FrameGraph& graph, const FrameContext& ctx,
                                          const RasterHandles& gl,
                                          FrameGraphId<RadiosityImage> radiosity);
    // B at the frame's pixels from a method's copy over the atlas, on the GL
    // side (gl/passes.h RadiosityLookupPass), instead of the method's run and
    // B's trip through the host. `copy` is read when the pass runs.
    FrameGraphId<RadiosityImage> addRadiosityLookup(FrameGraph& graph, const FrameContext& ctx,
                                                    const RasterHandles& gl,
                                                    const AtlasRadiosity& copy);
    // A second GL thread for the passes that overlap (null: none): the
    // light views, and the composite's samples' G-buffer beside the frame's.
    void setGlWorker(GlWorker* worker);
    // Whether the light views of the last frame were drawn for `lightingKey`.
    bool lightingCurrent(uint64_t lightingKey) const { return lightViewKey_ == lightingKey; }
    // Forget every lighting result (--no-reuse-lighting).
    void invalidateLighting() {
        lightViewKey_ = fluxKey_ = residualKey_ = envTextureKey_ = 0;
        viewKeys_.clear();
        scatterKeys_.clear();
    }

  private:
    void uploadMesh(const Mesh& mesh, uint64_t hash);
    uint64_t samplesKey(const FrameContext& ctx) const;
    // The composite's samples' G-buffer (GBufferPass::start: on the worker's
    // thread where it pays, else drawn at once).
    void startSamples(const FrameContext& ctx, const GpuMesh& mesh, const GlLights& lights);
    // What the shadow maps are drawn from: the coarser copy (mesh/lod.h) of a
    // mesh over 2 × `budget` triangles, made once per mesh and budget; null
    // for the mesh itself.
    const GpuMesh* depthMesh(const Mesh& mesh, int budget, FrameStats& stats);
    // The environment residual's E per atlas texel as a texture (0 without --env).
    GLuint environmentTexture(const FrameContext& ctx, const RenderTarget& geometry,
                              FrameStats& stats);
    // The environment's reflection (render/env_reflection.h) for the
    // composite: none without --env or with --no-specular; re-filtered only
    // when the map or the roughness changed, the albedo table when an η did.
    EnvReflectionTextures environmentReflection(const FrameContext& ctx, FrameStats& stats);
    // What the display shows around the object (--background); with env the
    // whole map as a texture (at most kBackgroundMapWidth wide), uploaded
    // when the map changes.
    DisplayBackground displayBackground(const FrameContext& ctx);
    static constexpr int kBackgroundMapWidth = 4096;

    LightViewPass lightPass_;
    ScatterViewPass scatterPass_;
    GeometryAtlasPass geometryAtlasPass_;
    FluxAtlasPass fluxAtlasPass_, residualFluxPass_;
    GBufferPass gbufferPass_, sampleGbufferPass_{false};
    CompositePass compositePass_;
    RadiosityLookupPass radiosityLookupPass_;
    MaterialTables
        materials_;  // η and exit scale per medium (updated each frame, uploaded on change)
    EnvTransfer envTransfer_;
    std::unique_ptr<FloatTexture> envTexture_;
    uint64_t envTextureKey_ = 0;  // transfer and lighting the texture holds
    std::unique_ptr<FloatTexture> envPrefiltered_, envAlbedo_;
    uint64_t envPrefilteredKey_ = 0, envAlbedoKey_ = 0;
    // The map's prefiltered bands by roughness (of the map envBandsOf_): a
    // changed layer list filters only the roughnesses it did not hold.
    std::map<float, std::vector<float>> envBands_;
    uint64_t envBandsOf_ = 0;
    std::unique_ptr<FloatTexture> envBackground_;
    uint64_t envBackgroundKey_ = 0;
    std::unique_ptr<GpuMesh> gpuMesh_;
    uint64_t meshHash_ = 0;
    std::unique_ptr<GpuMesh> lodMesh_;
    std::pair<uint64_t, int> lodKey_{0, -1};  // (mesh hash, budget)
    float lodMm_ = 0;                         // its deviation (MeshLod)
    size_t lodTriangles_ = 0;
    std::vector<LightView> lights_;
    std::vector<uint64_t> viewKeys_;  // per light view: what it was drawn for (frame_keys.h)
    std::vector<LightView> scatterViews_;
    std::vector<uint64_t> scatterKeys_;
    uint64_t scatterVersion_ = 0;
    // What the targets hold: lighting keys (0 = nothing) and versions.
    uint64_t lightViewKey_ = 0, fluxKey_ = 0, residualKey_ = 0;
    std::pair<uint64_t, int> geometryKey_{0, 0};  // (mesh hash, resolution)
    uint64_t gbufferKey_ = 0;      // mesh, camera, size (and the lighting, with irradiance)
    uint64_t samplesKey_ = 0;      // mesh, camera, size, --aa
    uint64_t samplesStarted_ = 0;  // the key of samples on the worker, not yet waited for
    uint64_t lightsVersion_ = 0, geometryVersion_ = 0, fluxVersion_ = 0, residualVersion_ = 0,
             gbufferVersion_ = 0, samplesVersion_ = 0;
};

}  // namespace tsis
