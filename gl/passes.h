// The GL passes of a frame (docs/design.md §1). Each owns its program and its render
// target and is reused across frames; a target is re-made only when its size
// changes. What each reads and writes is declared where the frame graph
// schedules it (host/render/renderer.cpp).
#pragma once

#include <functional>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <vector>

#include "gl/gl_worker.h"
#include "gl/gpu_mesh.h"
#include "gl/light_view.h"
#include "gl/material_tables.h"
#include "gl/render_target.h"
#include "gl/shader.h"
#include "scene/scene.h"

namespace tsis {

// Pass B: per light, depth (shadow map) and, when the light views have colour
// targets (makeLightView with maps), the light-view flux and position maps.
// Without maps only depth is drawn (no fragment shading).
class LightViewPass {
  public:
    LightViewPass();
    ~LightViewPass();
    LightViewPass(const LightViewPass&) = delete;
    LightViewPass& operator=(const LightViewPass&) = delete;
    // Depth-only views drawn every other one on `worker`'s thread, in
    // parallel with the others, for a mesh of `minTriangles` set up or more
    // (kWorkerMinTriangles: where it pays; else, or null, all on this one).
    // The worker outlives this pass.
    void setWorker(GlWorker* worker, size_t minTriangles = kWorkerMinTriangles) {
        side_.setWorker(worker, minTriangles);
    }
    void run(const GpuMesh& mesh, std::vector<LightView>& lights, const MaterialTables& media);
    // Only the views `changed` (indices into lights), the others' kept
    // (all, when the shadow map array is made again); a view without maps
    // drawn from `depthMesh` when given (a coarser copy, mesh/lod.h).
    // Returns how many were drawn on the worker.
    size_t run(const GpuMesh& mesh, std::vector<LightView>& lights, const MaterialTables& media,
               const std::vector<size_t>& changed, const GpuMesh* depthMesh = nullptr);
    // The shadow maps of the last run, for the passes that light.
    const ShadowMapArray& shadows() const { return shadows_; }

  private:
    // Clears and draws depth-only view `view` into layer `layer` with
    // `program` through `framebuffer`, this context's or a worker's
    // (WorkerSide) as `vertexArray` (0: the mesh's own).
    void drawDepth(const GpuMesh& mesh, const LightView& view, int layer,
                   const ShaderProgram& program, GLuint framebuffer, GLuint vertexArray) const;

    ShaderProgram program_, depthProgram_;
    ShadowMapArray shadows_;
    GLuint framebuffer_ = 0;  // this context's, for any view (bindAndClearLightView)
    WorkerSide side_{"mesh.vert", "depth.frag"};
};

// Pass B′, for the single-scattering term (render/single_scatter.h): per
// light the surface it sees, position and normal, into the view's own
// target (updateScatterView), at a resolution of its own.
class ScatterViewPass {
  public:
    ScatterViewPass();
    ~ScatterViewPass();
    ScatterViewPass(const ScatterViewPass&) = delete;
    ScatterViewPass& operator=(const ScatterViewPass&) = delete;
    // As LightViewPass's: every other view on `worker`'s thread.
    void setWorker(GlWorker* worker, size_t minTriangles = kWorkerMinTriangles) {
        side_.setWorker(worker, minTriangles);
    }
    // Draws views[i] for each i in `changed`.
    void run(const GpuMesh& mesh, const std::vector<LightView>& views, const MaterialTables& media,
             const std::vector<size_t>& changed);
    // In place of a draw: each view's depth, the map's (layer i for view i)
    // at the view's texels. The term's kernel makes the surface point and
    // the facet's normal from it (kernels/single_scatter.cl), where the map
    // holds what a draw would: one medium, no normal map, a closed, outward
    // mesh (render/raster_passes.cpp).
    void copyDepth(const ShadowMapArray& shadows, const std::vector<LightView>& views,
                   const std::vector<size_t>& changed);

  private:
    void draw(const GpuMesh& mesh, const LightView& view, const MaterialTables& media,
              const ShaderProgram& program, GLuint framebuffer, GLuint vertexArray) const;

    ShaderProgram program_;
    GLuint readFramebuffer_ = 0;
    WorkerSide side_{"mesh.vert", "scatter_view.frag"};
};

// Pass A, part 1 (once per mesh and resolution): the geometry atlas —
// position (w = coverage) and normal (w = the texel's surface area, mm²).
class GeometryAtlasPass {
  public:
    GeometryAtlasPass();
    void run(const GpuMesh& mesh, int resolution);
    const RenderTarget& target() const { return *target_; }

  private:
    ShaderProgram program_;
    std::unique_ptr<RenderTarget> target_;
};

// Pass A, part 2 (every frame): the flux atlas, flux per texel (attachment 0),
// shaded over the geometry atlas; `envIrradiance` (0: none) is a texture of
// the environment's residual E per texel (render/env_light.h), added to the lights'.
class FluxAtlasPass {
  public:
    FluxAtlasPass();
    void run(const RenderTarget& geometry, const std::vector<LightView>& lights,
             const ShadowMapArray& shadows, const MaterialTables& media, GLuint envIrradiance = 0);
    const RenderTarget& target() const { return *target_; }

  private:
    ShaderVariants programs_;  // with the environment, with the albedo factor
    std::unique_ptr<RenderTarget> target_;
    GLuint emptyVao_ = 0;
};

// Pass C: camera G-buffer: position (w = coverage), normal and, by
// `outputs`: kIrradiance (for the camera-view methods), E at each pixel's
// surface point (attachment 2), to which `envIrradiance` (0: none;
// FluxAtlasPass's) adds the environment's residual at each pixel's atlas
// texel; kUv, the atlas coordinates (RG, the attachment after). Each variant
// is compiled on first use. `cull`: back faces culled (the caller knows the
// mesh is closed and outward and the eye outside it).
class GBufferPass {
  public:
    // clearColor false: only depth is cleared, and a reader takes coverage
    // from it (< 1): an uncovered pixel's colour is an earlier frame's.
    explicit GBufferPass(bool clearColor = true) : clearColor_(clearColor) {}
    static constexpr unsigned kIrradiance = 1, kUv = 2;  // outputs
    // start() draws on `worker`'s thread for a mesh of `minTriangles` set
    // up or more (kWorkerMinTriangles: where it pays), else (or null) here
    // at once; finish() waits for it. The worker outlives this pass.
    void setWorker(GlWorker* worker, size_t minTriangles = kWorkerMinTriangles) {
        side_.setWorker(worker, minTriangles);
    }
    bool onWorker(const GpuMesh& mesh, bool cull) const {
        return side_.workerFor(mesh.trianglesSetUp(cull)) != nullptr;
    }
    void run(const GpuMesh& mesh, const std::vector<LightView>& lights,
             const ShadowMapArray& shadows, const MaterialTables& media, const glm::mat4& viewProj,
             int width, int height, unsigned outputs, GLuint envIrradiance = 0, bool cull = false) {
        start(mesh, lights, shadows, media, viewProj, width, height, outputs, envIrradiance, cull);
        finish();
    }
    // The eye, for the normal maps' shading normals (kept where the eye
    // sees them); the next start() draws from it.
    void setEye(const glm::vec3& eye) { eye_ = eye; }
    // The arguments stay alive until finish().
    void start(const GpuMesh& mesh, const std::vector<LightView>& lights,
               const ShadowMapArray& shadows, const MaterialTables& media,
               const glm::mat4& viewProj, int width, int height, unsigned outputs,
               GLuint envIrradiance = 0, bool cull = false);
    void finish();
    const RenderTarget& target() const { return *targets_[current_]; }

  private:
    struct Draw {
        const GpuMesh* mesh;
        const std::vector<LightView>* lights;
        const ShadowMapArray* shadows;
        const MaterialTables* media;
        glm::mat4 viewProj;
        unsigned outputs;
        GLuint envIrradiance;
        bool cull;
        glm::vec3 eye;
    };
    // `framebuffer` and `vertexArray`: a worker's (WorkerSide), 0 for this context's.
    void draw(const Draw& d, const ShaderProgram& program, GLuint framebuffer, GLuint vertexArray);

    // The outputs' bits, in order.
    static inline const std::vector<std::string> kVariants{"TSIS_GBUFFER_IRRADIANCE",
                                                           "TSIS_GBUFFER_UV"};
    ShaderVariants programs_{"mesh.vert", "gbuffer.frag", kVariants};
    std::unique_ptr<RenderTarget> targets_[4];  // by outputs
    int current_ = 0;
    bool clearColor_;
    bool started_ = false;  // on the worker, not yet finished
    glm::vec3 eye_{0.0f};
    WorkerSide side_{"mesh.vert", "gbuffer.frag", kVariants};
};

// B at the frame's pixels from a method's copy of B over the atlas
// (shaders/radiosity_lookup.frag; docs/design.md §6), on the GL side: a
// frame that only moved the camera needs no points on the CL side, no B
// read back and none uploaded again for the composite.
class RadiosityLookupPass {
  public:
    RadiosityLookupPass();
    ~RadiosityLookupPass();
    RadiosityLookupPass(const RadiosityLookupPass&) = delete;
    RadiosityLookupPass& operator=(const RadiosityLookupPass&) = delete;
    // The copy: res² float4 texel positions (with the ring; w = medium tag,
    // 0 for none) and their B, GL order, each uploaded again only when its
    // key changed.
    void setAtlas(const float* positions, uint64_t positionsKey, const float* radiosity,
                  uint64_t radiosityKey, int resolution);
    // B at the covered pixels of `frameGbuffer` (by its depth; positions in
    // attachment 0, atlas coordinates in `uvAttachment`) from the texels
    // within maxMm of each. Then texture(): RGBA float, GL order.
    struct Counts {
        int covered = 0;
        int offAtlas = 0;  // pixels with no texel: they take their nearest neighbour's
    };
    Counts run(const RenderTarget& frameGbuffer, int uvAttachment, float maxMm);
    GLuint texture() const { return target_->color(0); }

  private:
    ShaderProgram lookup_, fill_;
    std::unique_ptr<FloatTexture> xyz_, b_;
    uint64_t xyzKey_ = 0, bKey_ = 0;
    std::unique_ptr<RenderTarget> target_;
    GLuint counter_ = 0, query_ = 0, emptyVao_ = 0;
};

// The environment's reflection for the composite (render/env_reflection.h):
// the prefiltered residual (lat-long, map frame; 0: none; `layers` bands of
// rows, one per roughness: MediumSurface::envLayer, then with a roughness
// map the ladder's `ladderSteps` from `ladderLayer`) and the albedo table
// (a row per medium, then per medium and ladder step from `ladderRow`), the
// rotation world → map and the map's intensity.
struct EnvReflectionTextures {
    GLuint prefiltered = 0, albedo = 0;
    int layers = 1;
    glm::mat3 worldToMap{1.0f};
    float scale = 0;
    int ladderSteps = 0, ladderLayer = 0, ladderRow = 0;
    float ladderMin = 0;
};

// The display image's background (common.glsl backgroundAt; render_options.h
// Background): mode 0 the dark gradient, 1 transparent (alpha 0), 2 the
// environment map (`envMap`, lat-long RGBA floats in the map's frame, × `scale`)
// along each pixel's camera ray.
struct DisplayBackground {
    int mode = 0;
    GLuint envMap = 0;
    glm::mat4 inverseViewProj{1.0f};
    glm::mat3 worldToMap{1.0f};
    float scale = 1;
};

// Composite (docs/design.md "The composite"): radiance L = Ft/π·B (× the
// exit term's scale) + the GGX lobe at each pixel's centre; where a silhouette
// or depth jump passes (aa > 1), at aa × aa samples from the composite's own
// G-buffer as well; then exposure, tone curve, the samples' box filter and
// sRGB in one full-screen pass, which also leaves each pixel's log luminance
// for the log-average, summed on the GPU side. The frame's radiance as floats
// only when asked (resolve()).
class CompositePass {
  public:
    CompositePass();
    ~CompositePass();
    CompositePass(const CompositePass&) = delete;
    CompositePass& operator=(const CompositePass&) = delete;
    // radiosity: B at the frame's pixels, RGBA floats, GL row order.
    // `sampleGbuffer`: aa × the frame's size (the frame's G-buffer at 1×),
    // its coverage read from its depth (its colour need not be cleared).
    // `materials`: η, the exit term's factor over Ft/π (render_options.h
    // exitScale) and the lobe's α of each pixel's medium; `specular`: the lobe;
    // `env`: the environment's reflection. `gbufferVersion`: changes when the
    // frame's G-buffer (and so the pixels to supersample) does. Then
    // toneMap(), or resolve() first where the log-average or the radiance is
    // needed before it. With `displayScale` (toneMap's), the display image
    // straight from the centres and the samples instead, no frame of
    // radiance between: colorTarget() and logAverageLuminance() follow.
    // `radiosity`: B as host RGBA floats (uploaded), or a texture of it
    // (RadiosityLookupPass) where the host pointer is null.
    void radiance(const float* radiosityRGBA, GLuint radiosityTexture,
                  const RenderTarget& frameGbuffer, uint64_t gbufferVersion,
                  const RenderTarget& sampleGbuffer, int aa, const std::vector<LightView>& lights,
                  const ShadowMapArray& shadows, const glm::vec3& eye,
                  const MaterialTables& materials, bool specular,
                  const EnvReflectionTextures& env = {},
                  std::optional<float> displayScale = std::nullopt);
    // The frame's radiance (frameRadiance()) and log luminance, without the
    // display image.
    void resolve();
    // The radiance at the frame's pixels (RGBA, GL order): the centre's, or
    // in a supersampled pixel the mean over its covered samples (alpha their
    // fraction). Needs resolve().
    std::vector<float> frameRadiance() const;
    // Ls = scale·L, the tone curve, the mean over a pixel's samples, sRGB.
    void toneMap(float scale);
    // The tone curve and background of the display images that follow:
    // common.glsl's u_tone (0 Reinhard, 1 ACES fitted, 2 none;
    // render_options.h ToneCurve) and backgroundAt.
    void setDisplay(int tone, const DisplayBackground& background) {
        tone_ = tone;
        background_ = background;
    }
    // Reinhard's L_avg = exp(mean log(1e-12 + Y)) over the pixels with
    // alpha > 0, of the last resolve() or toneMap(); 1 when none is covered.
    // Summed in blocks on the GPU, the blocks' sums on the host.
    float logAverageLuminance();
    // --aa-method fxaa: radiance() lists the edge pixels as for aa > 1, and
    // fxaa() then antialiases them in the display image of the last
    // radiance() or toneMap() (fxaa.frag), the display image from now on.
    void setFxaa(bool on) { fxaa_ = on; }
    void fxaa();
    const RenderTarget& colorTarget() const { return *display_; }

  private:
    // resolve.frag into `target` (its attachment 1: the log luminance).
    // The covered pixels' centres, the others' `background` (none: left 0),
    // then the supersampled pixels' averages (packed, stored) over them.
    void resolveInto(const ShaderProgram& centres, const ShaderProgram* background,
                     const ShaderProgram& edges, std::unique_ptr<RenderTarget>& target,
                     std::vector<GLenum> formats);
    // Before the centres, into the bound `target` whose coverage changed
    // since `backgroundKey`: a background that does not follow the camera
    // (the gradient, transparent) copied whole from backgroundCache_, the
    // log luminance (attachment 1) cleared; the centres then cover their
    // pixels, and the background stays while the coverage does. Nothing for
    // the environment's (drawAroundCentres draws it).
    void copyStaticBackground(RenderTarget& target, uint64_t& backgroundKey);
    // The part after the centres, into the bound target: the environment's
    // background, and the supersampled pixels' averages.
    void drawAroundCentres(RenderTarget& target, const ShaderProgram* background,
                           const ShaderProgram& edges);
    void setToneMapScale(float scale, int width, int height);
    // `program` once per listed edge pixel (its u_edgePixels bound, then
    // `bindInputs`): a full-screen pass over edgesPacked_ (one texel a pixel,
    // in u_edgePixels' slots; its colour is not read), whose fragments write
    // with image stores; waits for them.
    void drawPackedEdges(const ShaderProgram& program, const std::function<void()>& bindInputs);

    // radiance.frag's: with the lobe, the environment's reflection, (the
    // centres) marking the pixels to supersample
    ShaderVariants centrePrograms_, samplePrograms_;
    ShaderProgram resolveProgram_, resolveEdgesProgram_, toneMapProgram_, toneMapEdgesProgram_,
        backgroundProgram_, reduceProgram_, fxaaProgram_;
    std::unique_ptr<FloatTexture> radiosity_;
    // centre: radiance and the supersampled pixels' mask (attachment 1); its
    // depth the frame G-buffer's, so that only covered pixels are shaded.
    // direct: the display colour, the log luminance and the mask, of
    // radiance() with a display scale.
    // backgroundCache_: the gradient or transparent background of the whole
    // frame, drawn once per size and mode (backgroundCacheKey_).
    std::unique_ptr<RenderTarget> centreTarget_, directTarget_, sampleTarget_, frameTarget_,
        colorTarget_, fxaaTarget_, edgesPacked_, backgroundCache_;
    uint64_t backgroundCacheKey_ = 0;
    // The log-average's sums, a level each pass; the last one's read.
    std::vector<std::unique_ptr<RenderTarget>> sumTargets_;
    const RenderTarget* logLuminance_ = nullptr;  // the last resolve's, attachment 1
    const RenderTarget* display_ = nullptr;       // the last display image's
    int aa_ = 1;
    bool fxaa_ = false;
    int tone_ = 0;
    DisplayBackground background_;
    // The display's uniforms of the tone curve and background on `p`.
    void setDisplayUniforms(const ShaderProgram& p, float scale, int width, int height) const;
    void bindBackgroundMap() const;  // the env map on its unit, for the next draws
    GLuint emptyVao_ = 0, depthSampler_ = 0, linearSampler_ = 0, clampSampler_ = 0;
    // The supersampled pixels, (x, y) in a texture of slots (the samples'
    // packed layout, which the resolve and fxaa passes share), listed
    // again only when the G-buffer changed: the marks follow the camera, not
    // the lights.
    GLsizei edgeCount_ = 0;
    std::unique_ptr<FloatTexture> edgePixels_;
    uint64_t edgesKey_ = 0;
    // The G-buffer's coverage and supersampled pixels this frame (edgesKey_'s
    // key), and those the tone map's background was copied for.
    uint64_t coverageKey_ = 0, backgroundKey_ = 0, directBackgroundKey_ = 0;
    // The marks to list: `target`'s attachment `index`.
    void updateEdgePoints(uint64_t key, const RenderTarget& target, int index);
};

}  // namespace tsis
