// Each light's view of the object: the projection used for its shadow map and
// light-view flux map, and the uniforms every shader that lights reads.
#pragma once

#include <glm/mat4x4.hpp>
#include <memory>
#include <vector>

#include "gl/render_target.h"
#include "gl/shader.h"
#include "scene/scene.h"

namespace tsis {

struct LightView {
    Light light;
    glm::mat4 viewProj{1.0f};
    float tanHalf = 0;      // point lights: tan of half the field of view
    float texelAreaMm = 0;  // directional: area of one texel (mm²)
    float texelMm = 0;      // a texel's size at the object centre (shadow offsets)
    int resolution = 0;     // texels a side
    // With maps: flux and position; no depth of its own, the shadow map is
    // drawn into the light's layer of ShadowMapArray. Null without. A
    // scatter view's (updateScatterView): position and normal, with depth,
    // or depth alone.
    std::unique_ptr<RenderTarget> target;
};

// The light's projection (scene/projection.h) with its render target.
// maps: a target of the flux and position maps (the light-view methods read
// them); without, none (depth only). Throws tsis::Error for a
// point light inside that sphere or a zero direction.
LightView makeLightView(const Light& light, float boundingRadius, int resolution, bool maps = true);
// The same in place: `view` for `light`, its target kept when it has the size
// and the maps asked for (a light that moved needs no new target).
void updateLightView(LightView& view, const Light& light, float boundingRadius, int resolution,
                     bool maps);
// The single-scattering term's view of `light` (render/single_scatter.h):
// the same projection at a resolution of its own, into a target of its own
// with a depth and, `drawn` (ScatterViewPass::run), the surface's position
// and normal (w = the medium tag); without, the depth alone
// (ScatterViewPass::copyDepth).
void updateScatterView(LightView& view, const Light& light, float boundingRadius, int resolution,
                       bool drawn);

// The lights' shadow maps as one depth texture array (a layer per light), the
// form the shaders sample; the light views draw into their layers.
class ShadowMapArray {
  public:
    ShadowMapArray() = default;
    ~ShadowMapArray();
    ShadowMapArray(const ShadowMapArray&) = delete;
    ShadowMapArray& operator=(const ShadowMapArray&) = delete;
    // Makes the array for `layers` maps of resolution² when it has another
    // shape; true then (every layer to draw again).
    bool ensure(int resolution, int layers);
    GLuint id() const { return id_; }
    int resolution() const { return resolution_; }

  private:
    GLuint id_ = 0;
    int resolution_ = 0, layers_ = 0;
};

// Binds `framebuffer` for drawing view `view`: its maps' textures (if any)
// and layer `layer` of `shadows` as depth, viewport set; clears them.
void bindAndClearLightView(GLuint framebuffer, const LightView& view, const ShadowMapArray& shadows,
                           int layer);

// Sets u_lightCount, u_light* and u_shadow* on `program`, binding the
// shadow map array to texture unit `unit`.
void bindLights(const ShaderProgram& program, const std::vector<LightView>& lights, int unit,
                const ShadowMapArray& shadows);

}  // namespace tsis
