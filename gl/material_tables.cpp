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

// A table of one vec3 per atlas texel as an RGBA texture (a = `fill`, as
// the 1×1 texture of `fill` made while there is none: a sampler needs a
// texture even where it is not read). Returns whether `values` has any.
bool updateTexelTable(std::unique_ptr<FloatTexture>& texture, uint64_t& uploaded,
                      const std::vector<glm::vec3>& values, int resolution, uint64_t version,
                      float fill) {
    if (!texture) {
        texture = std::make_unique<FloatTexture>(1, 1);
        const float none[4] = {fill, fill, fill, fill};
        texture->upload(none);
    }
    if (values.empty() || version == uploaded) return !values.empty();
    TSIS_CHECK_EQ(values.size(), static_cast<size_t>(resolution) * resolution);
    std::vector<float> rgba(values.size() * 4, fill);
    for (size_t i = 0; i < values.size(); ++i)
        for (int c = 0; c < 3; ++c) rgba[i * 4 + c] = values[i][c];
    if (texture->width() != resolution || texture->height() != resolution)
        texture = std::make_unique<FloatTexture>(resolution, resolution);
    texture->upload(rgba.data());
    uploaded = version;
    return true;
}

}  // namespace

void MaterialTables::updateAlbedo(const std::vector<glm::vec3>& factor, int resolution,
                                  uint64_t version) {
    textured_ = updateTexelTable(albedoTexture_, albedoVersion_, factor, resolution, version, 1.0f);
}

void MaterialTables::updateNormals(const std::vector<glm::vec3>& normal, int resolution,
                                   uint64_t version) {
    normalMapped_ =
        updateTexelTable(normalTexture_, normalVersion_, normal, resolution, version, 0.0f);
}

void MaterialTables::bind(const ShaderProgram& program, int unit, int normalUnit) const {
    TSIS_CHECK(mediaTexture_ && albedoTexture_ && normalTexture_);
    program.set("u_media", unit);
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
    glBindTexture(GL_TEXTURE_2D, mediaTexture_->id());
    program.set("u_albedo", unit + 1);
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit + 1));
    glBindTexture(GL_TEXTURE_2D, albedoTexture_->id());
    program.set("u_textured", textured_ ? 1 : 0);
    program.set("u_shadingNormal", normalUnit);
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(normalUnit));
    glBindTexture(GL_TEXTURE_2D, normalTexture_->id());
    program.set("u_normalMapped", normalMapped_ ? 1 : 0);
}

}  // namespace tsis
