// The frame: owns the GL context and passes, the OpenCL runtime and buffers,
// and the methods, and reuses them across frames (a moving light, a new
// material or size re-renders without re-creating anything).
#pragma once

#include <algorithm>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "cl/cl_runtime.h"
#include "gl/gl_context.h"
#include "gl/gpu_mesh.h"
#include "gl/passes.h"
#include "image/image_io.h"
#include "render/accumulator.h"
#include "render/frame_stats.h"
#include "render/method.h"
#include "render/render_options.h"
#include "render/scene.h"

namespace tsis {

struct FrameResult {
    int width = 0, height = 0;
    std::vector<uint8_t> rgb8;  // tone-mapped sRGB image, row 0 = top
    // With RenderOptions::keepAovs (row 0 = top; atlas row 0 = v = 1):
    ImageF radiosity, radiance, position, normal, coverage, fluxAtlas;
    float lavg = 0;  // log-average radiance luminance over covered pixels
    FrameStats stats;
};

class Renderer {
  public:
    // clDevice: see ClRuntime. Throws tsis::Error when GL or OpenCL is missing.
    explicit Renderer(const std::string& clDevice = "");
    ~Renderer();

    FrameResult render(const Scene& scene, const RenderOptions& options);
    // The next progressive frame starts a new mean even if nothing changed.
    void restartAccumulation() { accumulator_ = RadiosityAccumulator(); }

    ClRuntime& cl() { return cl_; }
    std::string glRenderer() const { return gl_.renderer(); }

  private:
    void uploadMeshIfChanged(const Mesh& mesh, uint64_t hash);
    Method& method(const std::string& name);

    GlContext gl_;
    ClRuntime cl_;
    LightViewPass lightPass_;
    GeometryAtlasPass geometryAtlasPass_;
    FluxAtlasPass fluxAtlasPass_;
    std::pair<uint64_t, int> geometryKey_{0, 0};  // (mesh hash, resolution) of the geometry atlas
    int geometryVersion_ = 0,
        positionVersion_ = -1,  // position atlas on the CL side is current when equal
        normalVersion_ = -1;    // normal atlas likewise
    GBufferPass gbufferPass_;
    CompositePass compositePass_;
    std::unique_ptr<GpuMesh> gpuMesh_;
    uint64_t meshHash_ = 0;
    RadiosityAccumulator accumulator_;
    // Lighting keys (renderer.cpp) of what the GL targets and CL buffers hold;
    // 0 = nothing current. A frame with the same key reuses them.
    uint64_t lightViewKey_ = 0, fluxKey_ = 0, fluxUploadKey_ = 0, lightMapsUploadKey_ = 0;
    bool lightMapsMade_ = false;  // the light views have flux and position maps
    std::map<std::string, std::unique_ptr<Method>> methods_;
    std::vector<LightView> lights_;
    // CL buffers, grown as needed and kept across frames.
    struct GrowingBuffer {
        cl::Buffer buffer;
        size_t capacity = 0;
        void reserve(const cl::Context& ctx, size_t bytes) {
            if (capacity >= bytes && capacity > 0) return;
            capacity = std::max<size_t>(bytes, 16);
            buffer = cl::Buffer(ctx, CL_MEM_READ_WRITE, capacity);
        }
    };
    GrowingBuffer fluxAtlas_, positionAtlas_, normalAtlas_, points_, radiosity_, gbufferCl_[3];
    std::vector<GrowingBuffer> lightCl_;
};

// The light-map resolution RenderOptions::lightResolution = 0 stands for:
// 2048² when the object is more than 100 of its shortest diffusion lengths
// 1/σtr across (bounding diameter), else 1024².
int autoLightResolution(const Scene& scene);

// FNV-1a over the mesh's geometry and UVs: decides when to re-upload.
uint64_t meshHash(const Mesh& mesh);

// The log-average luminance (Reinhard's L_avg) of RGBA pixels whose alpha > 0.
float logAverageLuminance(const std::vector<float>& rgba);

}  // namespace tsis
