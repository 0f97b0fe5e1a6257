// What the GL passes read of the materials (docs/design.md §2 "Materials"):
//  * per medium, by a point's medium tag (mesh/media.h): η for the Fresnel
//    terms at entry and exit, the exit term's scale (render_options.h
//    exitScale) and the surface's GGX α with the layer of the environment
//    prefiltered at it, so that objects of several materials are each lit
//    and composited with their own;
//  * per atlas texel, when the scene has one: the albedo factor
//    (render/albedo_atlas.h) that scales the light entering there, and the
//    shading normal of the normal maps and the roughness of the roughness
//    maps (render/surface_atlas.h).
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <memory>
#include <vector>

#include "gl/render_target.h"
#include "gl/shader.h"

namespace tsis {

// What the composite reads of one medium's surface.
struct MediumSurface {
    float eta = 1.3f;
    float exitScale = 1.0f;
    float alpha = 0.09f;  // the GGX lobe's α = R²
    int envLayer = 0;     // its roughness' layer of the prefiltered environment
    bool operator==(const MediumSurface& o) const {
        return eta == o.eta && exitScale == o.exitScale && alpha == o.alpha &&
               envLayer == o.envLayer;
    }
};

class MaterialTables {
  public:
    // One entry per medium; uploaded only when they changed.
    void updateMedia(const std::vector<MediumSurface>& media);
    // The albedo factor per atlas texel (res², GL row order), or none
    // (`factor` empty); uploaded when `version` changed.
    void updateAlbedo(const std::vector<glm::vec3>& factor, int resolution, uint64_t version);
    // The shading normal (xyz; (0, 0, 0): the geometry's) and roughness (w;
    // 0: the medium's) per atlas texel (res², GL row order), either or both
    // none (empty); uploaded when `version` changed.
    void updateSurface(const std::vector<glm::vec3>& normal, const std::vector<float>& roughness,
                       int resolution, uint64_t version);
    // Binds the tables to texture units `unit`, `unit` + 1 and `normalUnit`
    // (common.glsl: u_media, u_albedo, u_textured, u_surfaceMaps,
    // u_normalMapped, u_roughnessMapped).
    void bind(const ShaderProgram& program, int unit, int normalUnit) const;
    // Whether the scene has an albedo factor (a program's TSIS_TEXTURED).
    bool textured() const { return textured_; }

  private:
    std::vector<MediumSurface> media_;
    std::unique_ptr<FloatTexture> mediaTexture_, albedoTexture_, surfaceTexture_;
    bool textured_ = false, normalMapped_ = false, roughnessMapped_ = false;
    uint64_t albedoVersion_ = 0, surfaceVersion_ = 0;
};

// Media per texture row (common.glsl mediumOf reads the same layout).
constexpr int kMediumTableWidth = 4096;

}  // namespace tsis
