// The frame: owns the GL context and passes, the OpenCL runtime and buffers,
// and the methods, and reuses them across frames (a moving light, a new
// material or size re-renders without re-creating anything).
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "cl/cl_runtime.h"
#include "gl/gl_context.h"
#include "gl/gl_worker.h"
#include "image/image_io.h"
#include "render/accumulator.h"
#include "render/frame_stats.h"
#include "render/gl_cl_sharing.h"
#include "render/gl_cl_staging.h"
#include "render/method.h"
#include "render/object_transport.h"
#include "render/raster_passes.h"
#include "render/render_options.h"
#include "render/single_scatter.h"
#include "scene/scene.h"
#include "util/cancel.h"

namespace tsis {

struct FrameResult {
    int width = 0, height = 0;
    std::vector<uint8_t> rgb8;  // tone-mapped sRGB image, row 0 = top
    // With --background transparent: its alpha (straight, the fraction of
    // the pixel the object covers), row 0 = top; else empty.
    std::vector<uint8_t> alpha8;
    // rgb8 (3 channels) or with alpha8 RGBA (4), as the PNG holds it.
    std::vector<uint8_t> displayPixels(int& channels) const;
    // With RenderOptions::keepAovs (row 0 = top; atlas row 0 = v = 1):
    ImageF radiosity, radiance, position, normal, coverage, fluxAtlas;
    ImageF medium;   // the pixel's medium (mesh/media.h), −1 where uncovered
    float lavg = 0;  // log-average radiance luminance over covered pixels
    FrameStats stats;
};

class Renderer {
  public:
    // clDevice: see ClRuntime; gl: "auto", "osmesa" or "egl" ("": $TSIS_GL,
    // else auto; gl_context.h). Throws tsis::Error when GL or OpenCL is missing.
    explicit Renderer(const std::string& clDevice = "", const std::string& gl = "");
    ~Renderer();

    // cancel (null: none) is asked between passes and inside the long ones
    // (volumetric, reference): tsis::Cancelled then, and the next frame starts
    // afresh. Throws tsis::Error in a child forked after this renderer was made.
    FrameResult render(const Scene& scene, const RenderOptions& options, Cancel* cancel = nullptr);
    // What the first frame to move only the camera after a lighting change
    // would otherwise do, done now (a window calls it while its last frame is
    // shown): pyramid's copy of B over the atlas (method_pyramid.h), 80–160
    // ms in that frame against ~20 for the next camera moves. `scene` and
    // `options` are the last frame's; nothing changes for it but the copy,
    // so the camera moves that follow read it at once. Returns false, doing
    // nothing, where no frame would make a copy (another method,
    // pyramid-cache off or always, progressive frames, AOVs kept).
    bool prepareCameraMoves(const Scene& scene, const RenderOptions& options);
    // The object's transport fitted in the background (ObjectTransport::
    // setBackgroundFits), for a window: a frame whose fit is new renders
    // without the correction (stat transport_pending = 1) and the window
    // renders it again once backgroundFitReady(). Off by default (a frame
    // waits for its fit); never for progressive frames, whose mean would mix.
    void setBackgroundFits(bool on) { backgroundFits_ = on; }
    bool backgroundFitReady() const;
    // Whether this process is not the one that made the renderer (a fork's
    // child): it may then only be leaked, as its GL and CL threads are gone.
    bool forkedAway() const;
    // Leaves the calling thread with no context of this renderer current, so
    // that another thread may make it current (render() does).
    void releaseGl() { gl_.release(); }
    // The next progressive frame starts a new mean even if nothing changed.
    void restartAccumulation() { accumulator_ = RadiosityAccumulator(); }

    ClRuntime& cl() { return cl_; }
    std::string glRenderer() const { return gl_.renderer(); }
    std::string glPlatform() const { return gl_.platform(); }

  private:
    // The instance of method `name` for material slot `slot` in `role` ("":
    // the frame's method; "residual": the environment's run, render()).
    Method& method(const std::string& name, size_t slot, const char* role = "");
    // The scene's media and their materials (made again when the mesh or a
    // material changed).
    const SceneMedia& media(const Scene& scene, uint64_t meshKey);
    // Mesh::surfaceArea, summed again only when the mesh changed (not every
    // frame: a triangle's square root each, on the frame's path).
    double surfaceArea(const Mesh& mesh, uint64_t meshKey);
    // The albedo factors (baked again when the mesh, a material or the atlas changed).
    const AlbedoAtlas& albedoAtlas(const Scene& scene, const SceneMedia& media,
                                   const RenderOptions& opt, uint64_t meshKey);
    // The normal and roughness maps per atlas texel, and R per texel where a
    // medium holds several (baked again when the mesh, a map, a roughness,
    // --roughness or the atlas changed).
    const SurfaceAtlas& surfaceAtlas(const Scene& scene, const Media& media,
                                     const RenderOptions& opt, uint64_t meshKey);
    // The method's copy of B over the atlas for this frame (Method::
    // atlasRadiosity), where the frame can read B from it on the GL side:
    // lighting unchanged, one material, nothing added to B on the CL side
    // (the residual's run, L⁽¹⁾, the progressive mean, an albedo's exit
    // factor) and no AOVs of B at the points; else null.
    const AtlasRadiosity* atlasRadiosity(const Scene& scene, const RenderOptions& opt,
                                         const FrameContext& ctx, bool residual);

    // What the next frame cannot reuse after one that stopped early.
    void forgetAfterAbort();

    pid_t pid_;  // the process that made this renderer
    GlContext gl_;
    // A second GL thread for passes that overlap (gl/gl_worker.h); null where
    // no shared context is offered or TSIS_GL_WORKER=0. Outlives raster_.
    std::unique_ptr<GlWorker> glWorker_;
    ClRuntime cl_;
    RasterPasses raster_;
    GlClStaging staging_;
    GlClSharing sharing_;  // decided, not yet used: staging_ copies (gl_cl_sharing.h)
    RadiosityAccumulator accumulator_;
    std::unique_ptr<SingleScatter> singleScatter_;  // made on first use (its kernel)
    std::unique_ptr<ObjectTransport> transport_;    // made on first use
    bool backgroundFits_ = false;
    std::map<std::string, std::unique_ptr<Method>> methods_;
    uint64_t mediaOf_ = 0;  // the mesh and materials media_ was made for
    uint64_t areaOf_ = 0;   // the mesh area_ was summed for
    double area_ = 0;
    std::unique_ptr<SceneMedia> media_;
    AlbedoAtlas albedo_;
    uint64_t albedoOf_ = 0;
    SurfaceAtlas surface_;
    uint64_t surfaceOf_ = 0;
    uint64_t lastView_ = 0;  // the last frame's view and size (FrameContext::cameraMoved)
};

// The light-map resolution RenderOptions::lightResolution = 0 stands for:
// 2048² when the object is more than 100 of its shortest diffusion lengths
// 1/σtr across (bounding diameter), else 1024².
int autoLightResolution(const Scene& scene);

// The atlas resolution RenderOptions::atlasResolution = 0 stands for, and
// the one a mesh's atlas is packed for then (kAtlasPackResolution): 256²
// when such an atlas' texels, √(area)/256 with every texel covered, are at
// most 1/8 of the shortest mean free path 1/σt' of the object's media and
// the scene reads no texture or surface map (their detail is the atlas'),
// else 512². A texel that small integrates the profile as well as 512²
// does (docs/guide/performance.md "Atlas resolution") at a quarter of the
// flux atlas, pyramid and fit texels. `surfaceAreaMm2`: scene.mesh's
// (Mesh::surfaceArea).
constexpr int kAtlasPackResolution = 512;
int autoAtlasResolution(const Scene& scene, double surfaceAreaMm2);

}  // namespace tsis
