// The interface every rendering method implements (docs/design.md §4). A method turns
// the frame's shared inputs into radiosity B for every covered pixel by adding
// passes to the frame graph; the renderer owns the GL passes, the hand-offs
// and the composite around it.
#pragma once

#include <glm/mat4x4.hpp>
#include <memory>
#include <string>
#include <vector>

#include "cl/cl_runtime.h"
#include "gl/light_view.h"
#include "physics/dipole.h"
#include "render/frame_graph.h"
#include "render/frame_stats.h"
#include "render/render_options.h"
#include "render/scene.h"

namespace tsis {

// What the passes share in one frame. Resource names used in the frame graph
// are given beside each member.
struct FrameContext {
    const Scene* scene = nullptr;
    const RenderOptions* options = nullptr;
    ClRuntime* cl = nullptr;
    FrameStats* stats = nullptr;
    float boundingRadius = 0;     // the object fits in a sphere of this radius at the origin
    int atlasResolution = 0;
    cl::Buffer fluxAtlas;         // "flux_atlas_cl": res² float4 (flux rgb)
    uint64_t fluxKey = 0;         // "flux_atlas_cl" too: equal keys, equal flux (0: unknown)
    cl::Buffer positionAtlas;     // "position_atlas_cl": res² float4 (xyz, 1 where covered)
    cl::Buffer normalAtlas;       // "normal_atlas_cl": res² float4 (normal, w = texel area mm²)
    int geometryVersion = 0;      // "position_atlas_cl" too: changes with the mesh or resolution
    std::vector<LightView>* lights = nullptr;  // "light_maps": depth, flux, position per light
    int pointCount = 0;           // covered pixels
    cl::Buffer points;            // "points_cl": pointCount float4 (xyz of each covered pixel)
    std::vector<float> pointsHost;  // "points_cl" too: the same float4s on the host
    std::vector<int> pointPixel;  // "points_cl" too: GL pixel index y*width+x (row 0 = bottom)
    cl::Buffer radiosity;         // "radiosity_cl": pointCount float4, written by the method

    // Camera: "gbuffer_cl" holds width*height float4 per buffer, GL row order.
    int width = 0, height = 0;
    glm::mat4 viewProj{1.0f};
    glm::vec3 eye{0.0f};
    cl::Buffer gbufferPosition;   // xyz, w = coverage
    cl::Buffer gbufferNormal;     // xyz
    cl::Buffer gbufferIrradiance; // E rgb at the pixel's surface point (docs/design.md §2)

    // Light views: "light_maps_cl", per light lightResolution² float4 (GL row order);
    // matrices in lights[i].viewProj.
    int lightResolution = 0;
    std::vector<cl::Buffer> lightFlux;      // flux per texel rgb (docs/design.md §2), a = covered
    std::vector<cl::Buffer> lightPosition;  // xyz, w = distance to the light (mm)

    // Progressive accumulation: frames of the same view already averaged, so
    // this frame draws sample set `sampleSet` (0 when not accumulating).
    uint32_t sampleSet = 0;
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
    // Resources the method reads from the renderer ("flux_atlas_cl", "points_cl", …),
    // so passes nobody needs are culled.
    virtual void addPasses(FrameGraph& graph, FrameContext& ctx) = 0;
};

std::unique_ptr<Method> makeMethod(const std::string& name, ClRuntime& cl);
std::vector<std::string> methodNames();

}  // namespace tsis
