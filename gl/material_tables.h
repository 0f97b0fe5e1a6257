// What the GL passes read of the materials (docs/design.md §2 "Materials"):
//  * per medium, by a point's medium tag (mesh/media.h): η for the Fresnel
//    terms at entry and exit and the exit term's scale (render_options.h
//    exitScale), so that objects of several materials are each lit and
//    composited with their own;
//  * per medium, the single-scattering albedo α′ = σs′/σt′ per channel of the
//    composite's half-space single scattering (--transport object; 0: none);
//  * per atlas texel, when the scene has one: the albedo factor
//    (render/albedo_atlas.h) that scales the light entering there.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <vector>

#include "gl/render_target.h"
#include "gl/shader.h"

namespace tsis {

class MaterialTables {
  public:
    // One (η, exit scale) per medium, and one single-scattering albedo each
    // (or none: `scatterAlbedo` empty); uploaded only when they changed.
    void updateMedia(const std::vector<glm::vec2>& etaAndExit,
                     const std::vector<glm::vec3>& scatterAlbedo = {});
    // The albedo factor per atlas texel (res², GL row order), or none
    // (`factor` empty); uploaded when `version` changed.
    void updateAlbedo(const std::vector<glm::vec3>& factor, int resolution, uint64_t version);
    // Binds the tables to texture units `unit`, `unit` + 1 (common.glsl:
    // u_media, u_albedo, u_textured).
    void bind(const ShaderProgram& program, int unit) const;
    // Whether the scene has an albedo factor (a program's TSIS_TEXTURED).
    bool textured() const { return textured_; }
    // Whether the composite adds single scattering (a program's TSIS_SINGLE_SCATTER).
    bool singleScatter() const { return !scatter_.empty(); }

  private:
    std::vector<glm::vec2> media_;
    std::vector<glm::vec3> scatter_;
    std::unique_ptr<FloatTexture> mediaTexture_, albedoTexture_;
    bool textured_ = false;
    uint64_t albedoVersion_ = 0;
};

// Media per texture row (common.glsl mediumOf reads the same layout); the
// scattering albedos are the rows below the (η, exit) rows, as many again.
constexpr int kMediumTableWidth = 4096;

}  // namespace tsis
