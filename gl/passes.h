// The GL passes of a frame (docs/design.md §1). Each owns its program and its render
// target and is reused across frames; a target is re-made only when its size
// changes. What each reads and writes is declared where the frame graph
// schedules it (host/render/renderer.cpp).
#pragma once

#include <glm/vec3.hpp>
#include <memory>
#include <vector>

#include "gl/gpu_mesh.h"
#include "gl/light_view.h"
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
    void run(const GpuMesh& mesh, std::vector<LightView>& lights, float eta);
    // The shadow maps of the last run, for the passes that light.
    const ShadowMapArray& shadows() const { return shadows_; }

  private:
    ShaderProgram program_, depthProgram_;
    ShadowMapArray shadows_;
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
             const ShadowMapArray& shadows, float eta, GLuint envIrradiance = 0);
    const RenderTarget& target() const { return *target_; }

  private:
    ShaderProgram program_;
    std::unique_ptr<RenderTarget> target_;
    GLuint emptyVao_ = 0;
};

// Pass C: camera G-buffer: position (w = coverage), normal and, with
// `irradiance` (for the camera-view methods), E at each pixel's surface point
// (attachments 0, 1, 2). Each variant is compiled on first use.
class GBufferPass {
  public:
    void run(const GpuMesh& mesh, const std::vector<LightView>& lights,
             const ShadowMapArray& shadows, float eta, const glm::mat4& viewProj, int width,
             int height, bool irradiance);
    const RenderTarget& target() const { return *variants_[current_].target; }

  private:
    struct Variant {
        std::unique_ptr<ShaderProgram> program;
        std::unique_ptr<RenderTarget> target;
    };
    Variant variants_[2];  // without, with irradiance
    int current_ = 0;
};

// Composite: radiance L = Ft/π·B (× the exit term's scale), then tone map + specular + sRGB.
class CompositePass {
  public:
    CompositePass();
    // radiosity: width*height RGBA floats, GL row order. Returns nothing; read
    // radiance() after it, then call toneMap().
    // `exitScale`: the exit term's factor over Ft/π (render_options.h exitScale).
    void radiance(const float* radiosityRGBA, const RenderTarget& gbuffer, const glm::vec3& eye,
                  float eta, float exitScale);
    void toneMap(const RenderTarget& gbuffer, const std::vector<LightView>& lights,
                 const ShadowMapArray& shadows, const glm::vec3& eye, float eta, float key,
                 float lavg, float specular, float shininess);
    const RenderTarget& radianceTarget() const { return *radianceTarget_; }
    const RenderTarget& colorTarget() const { return *colorTarget_; }

  private:
    ShaderProgram radianceProgram_, toneMapProgram_;
    std::unique_ptr<FloatTexture> radiosity_;
    std::unique_ptr<RenderTarget> radianceTarget_, colorTarget_;
    GLuint emptyVao_ = 0;
};

}  // namespace tsis
