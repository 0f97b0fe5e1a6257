// The interface every rendering method implements (DESIGN §4). A method turns
// the frame's shared inputs into radiosity B for every covered pixel by adding
// passes to the frame graph; the renderer owns the GL passes, the hand-offs
// and the composite around it.
#pragma once

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
    cl::Buffer positionAtlas;     // "position_atlas_cl": res² float4 (xyz, 1 where covered)
    std::vector<LightView>* lights = nullptr;  // "light_maps": depth, flux, position per light
    int pointCount = 0;           // covered pixels
    cl::Buffer points;            // "points_cl": pointCount float4 (xyz of each covered pixel)
    cl::Buffer radiosity;         // "radiosity_cl": pointCount float4, written by the method
};

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
