// Textured and per-triangle albedo (issue 20, docs/design.md §2 "Materials").
// A solid's points scatter light with the profile of their own triangle's
// material (its slot, render/scene_media.h); where the surface shows another
// albedo a than that profile's a_slot (a texture, or a triangle of another
// file material that scatters alike) the light entering and the light
// leaving there are each scaled by √(a / a_slot) — texturing "pre- and
// post-scatter" (as real-time skin renderers do): a texture of constant
// a_slot leaves the image unchanged, and far (several diffusion lengths)
// inside a region of constant albedo a, B = a·E, the closed form of a
// homogeneous material of albedo a. Near the border of two albedos the blur
// is the profile's, not each side's own. Baked once per mesh, materials and
// atlas resolution into a factor per atlas texel (and, where a solid holds
// several materials, the slot of each texel): the flux atlas, the light
// views and the camera's points read it.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "render/render_options.h"
#include "render/scene_media.h"
#include "scene/scene.h"

namespace tsis {

struct AlbedoAtlas {
    int resolution = 0;
    // √(a / a_medium) per texel, res², row 0 at v = 0 (GL order); empty: 1
    // everywhere (every triangle shows its medium's own albedo).
    std::vector<glm::vec3> factor;
    // The material slot of each texel's triangle (SceneMedia), where a solid
    // holds several (SceneMedia::mixed); else empty.
    std::vector<uint32_t> slot;
    uint64_t key = 0;  // changes with whatever changed the factors or slots
    bool empty() const { return factor.empty(); }
    // The factor at a texel index (the G-buffer's normal w − 1), 1 when empty.
    glm::vec3 atTexel(size_t texel) const {
        return factor.empty() || texel >= factor.size() ? glm::vec3(1.0f) : factor[texel];
    }
    glm::vec3 at(const glm::vec2& uv) const;  // nearest texel
    // The slot at a texel index, `fallback` (the medium's) when none.
    uint32_t slotAtTexel(size_t texel, uint32_t fallback) const {
        return texel < slot.size() ? slot[texel] : fallback;
    }
};

// A texture at texture coordinate uv: bilinear, wrapping (glTF's default
// sampler, and OBJ's), image convention (0, 0) = the top-left corner.
glm::dvec3 sampleTexture(const ImageF& image, const glm::vec2& uv);

// The albedo a triangle of file material `id` shows at texture coordinate
// `texcoord` (a texture's texel × its scale, else the material's albedo;
// `defaultAlbedo` for kNoFileMaterial), each channel at most kMaxAlbedo.
glm::dvec3 surfaceAlbedo(const Scene& scene, uint32_t id, const glm::vec2& texcoord,
                         const glm::dvec3& defaultAlbedo);

// The factors of `scene` at `resolution`; empty when every triangle shows its
// medium's albedo. Texels no triangle covers take their covered neighbours'
// (the atlas' gutters, where GL's rasterisation may reach), else 1.
AlbedoAtlas bakeAlbedoAtlas(const Scene& scene, const SceneMedia& media, int resolution,
                            ProfileModel model);

}  // namespace tsis
