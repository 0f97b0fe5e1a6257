#include "gl/material_tables.h"

#include <algorithm>

#include "util/error.h"

namespace tsis {

void MaterialTables::updateMedia(const std::vector<MediumSurface>& media) {
    TSIS_CHECK(!media.empty());
    if (mediaTexture_ && media == media_) return;
    const int n = static_cast<int>(media.size());
    const int w = std::min(n, kMediumTableWidth),
              h = (n + kMediumTableWidth - 1) / kMediumTableWidth;
    std::vector<float> rgba(static_cast<size_t>(w) * h * 4, 0.0f);
    for (size_t m = 0; m < media.size(); ++m) {
        rgba[m * 4] = media[m].eta;
        rgba[m * 4 + 1] = media[m].exitScale;
        rgba[m * 4 + 2] = media[m].alpha;
        rgba[m * 4 + 3] = static_cast<float>(media[m].envLayer);
    }
    if (!mediaTexture_ || mediaTexture_->width() != w || mediaTexture_->height() != h)
        mediaTexture_ = std::make_unique<FloatTexture>(w, h);
    mediaTexture_->upload(rgba.data());
    media_ = media;
}

namespace {

// A table of one RGBA per atlas texel (`count` of them, texel(i) each), or
// while there is none the 1×1 texture of `fill` (a sampler needs a texture
// even where it is not read). Returns whether there is a table.
template <typename Texel>
bool updateTexelTable(std::unique_ptr<FloatTexture>& texture, uint64_t& uploaded, size_t count,
                      const Texel& texel, int resolution, uint64_t version, float fill) {
    if (!texture) {
        texture = std::make_unique<FloatTexture>(1, 1);
        const float none[4] = {fill, fill, fill, fill};
        texture->upload(none);
    }
    if (count == 0 || version == uploaded) return count != 0;
    TSIS_CHECK_EQ(count, static_cast<size_t>(resolution) * resolution);
    std::vector<float> rgba(count * 4);
    for (size_t i = 0; i < count; ++i) {
        const glm::vec4 v = texel(i);
        for (int c = 0; c < 4; ++c) rgba[i * 4 + c] = v[c];
    }
    if (texture->width() != resolution || texture->height() != resolution)
        texture = std::make_unique<FloatTexture>(resolution, resolution);
    texture->upload(rgba.data());
    uploaded = version;
    return true;
}

}  // namespace

void MaterialTables::updateAlbedo(const std::vector<glm::vec3>& factor, int resolution,
                                  uint64_t version) {
    textured_ = updateTexelTable(
        albedoTexture_, albedoVersion_, factor.size(),
        [&](size_t i) { return glm::vec4(factor[i], 1.0f); }, resolution, version, 1.0f);
}

void MaterialTables::updateSurface(const std::vector<glm::vec3>& normal,
                                   const std::vector<float>& roughness, int resolution,
                                   uint64_t version) {
    const size_t count = std::max(normal.size(), roughness.size());
    const bool any = updateTexelTable(
        surfaceTexture_, surfaceVersion_, count,
        [&](size_t i) {
            return glm::vec4(normal.empty() ? glm::vec3(0.0f) : normal[i],
                             roughness.empty() ? 0.0f : roughness[i]);
        },
        resolution, version, 0.0f);
    normalMapped_ = any && !normal.empty();
    roughnessMapped_ = any && !roughness.empty();
}

void MaterialTables::bind(const ShaderProgram& program, int unit, int normalUnit) const {
    TSIS_CHECK(mediaTexture_ && albedoTexture_ && surfaceTexture_);
    program.set("u_media", unit);
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
    glBindTexture(GL_TEXTURE_2D, mediaTexture_->id());
    program.set("u_albedo", unit + 1);
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit + 1));
    glBindTexture(GL_TEXTURE_2D, albedoTexture_->id());
    program.set("u_textured", textured_ ? 1 : 0);
    program.set("u_surfaceMaps", normalUnit);
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(normalUnit));
    glBindTexture(GL_TEXTURE_2D, surfaceTexture_->id());
    program.set("u_normalMapped", normalMapped_ ? 1 : 0);
    program.set("u_roughnessMapped", roughnessMapped_ ? 1 : 0);
}

}  // namespace tsis
