// The hand-off between GL and CL. OSMesa + PoCL have no cl_khr_gl_sharing, so
// render targets are read back and written to CL buffers — each only when its
// contents changed (versions), the camera's covered pixels packed — and the
// methods' radiosity is read back to the host for the composite.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "render/frame_graph.h"
#include "render/frame_resources.h"
#include "render/method.h"
#include "render/raster_passes.h"

namespace tsis {

class GlClStaging {
  public:
    // Declares the CL-side resources in ctx (the handles methods read and
    // the radiosity they write), before any pass is added.
    void declare(FrameGraph& graph, FrameContext& ctx);
    // The uploads that write ctx's handles from the GL targets.
    void addUploads(FrameGraph& graph, const FrameContext& ctx, const RasterHandles& gl);
    // The radiosity of the method's run for material slot `slot` > 0 (slot 0
    // writes ctx.radiosity of declare).
    FrameGraphId<RadiosityCl> declareRadiosity(FrameGraph& graph, size_t slot);
    // ctx.points split by material slot (render/scene_media.h), one handle a
    // slot: each run of the method computes its own medium's points only.
    // With one slot, ctx.points itself.
    std::vector<FrameGraphId<SurfacePoints>> addSlotPoints(FrameGraph& graph,
                                                           const FrameContext& ctx);
    // The methods' radiosity, back into a width×height image: each run's
    // points' (its slot's, addSlotPoints) times their albedo's exit factor. `residual`, empty or
    // one per run: B that the environment's residual adds to each run (Renderer::render).
    FrameGraphId<RadiosityImage> addReadback(FrameGraph& graph,
                                             const std::vector<FrameContext>& runs,
                                             const std::vector<FrameContext>& residual);
    // Takes back the frame's B image (addReadback's) when the frame is done:
    // the next frame's is made in its memory.
    void recycle(RadiosityImage& image) { spareRadiosity_ = std::move(image.rgba); }

  private:
    // One attachment of a GL target into a CL buffer, when its version changed.
    void addAtlasUpload(FrameGraph& graph, const FrameContext& ctx, const char* name,
                        FrameGraphId<GlTarget> source, int attachment, GrowingBuffer& buffer,
                        uint64_t& uploaded, FrameGraphId<AtlasCl> out);

    GrowingBuffer fluxAtlas_, residualFluxAtlas_, positionAtlas_, normalAtlas_, points_, pointUvs_,
        radiosity_, gbuffer_[3];
    std::vector<std::unique_ptr<GrowingBuffer>> slotRadiosity_;  // slots 1, 2, …
    // The points of each slot (addSlotPoints), of the G-buffer version slotPointsOf_.
    std::vector<SurfacePoints> slotPoints_;
    std::vector<std::unique_ptr<GrowingBuffer>> slotXyz_, slotUv_;
    uint64_t slotPointsOf_ = 0;
    std::vector<uint32_t> slotOfMedium_;
    uint64_t slotAlbedo_ = 0;  // the albedo atlas' key the split was made for
    std::vector<GrowingBuffer> lightMaps_;
    // Host memory of every frame kept across frames: past 32 MB (a 2048²
    // frame's G-buffer or B) the allocator maps a fresh block each time and
    // every page faults in again (read_radiosity 31.6 → 14.1 ms at 2048²).
    std::vector<float> gbufferPositions_, gbufferNormals_, gbufferUvs_, spareRadiosity_;
    uint64_t fluxUploaded_ = 0, residualUploaded_ = 0, positionUploaded_ = 0, normalUploaded_ = 0,
             lightsUploaded_ = 0;
    // The covered pixels of the G-buffer version pointsOf_ (kept while the
    // camera stands still: a frame that only moves the light reuses them).
    SurfacePoints cachedPoints_;
    uint64_t pointsOf_ = 0, gbufferUploaded_ = 0;
};

}  // namespace tsis
