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

void MaterialTables::updateAlbedo(const std::vector<glm::vec3>& factor, int resolution,
                                  uint64_t version) {
    if (!albedoTexture_) {  // bound even when unread: a sampler needs a texture
        albedoTexture_ = std::make_unique<FloatTexture>(1, 1);
        const float one[4] = {1, 1, 1, 1};
        albedoTexture_->upload(one);
    }
    textured_ = !factor.empty();
    if (!textured_ || version == albedoVersion_) return;
    TSIS_CHECK_EQ(factor.size(), static_cast<size_t>(resolution) * resolution);
    std::vector<float> rgba(factor.size() * 4, 1.0f);
    for (size_t i = 0; i < factor.size(); ++i)
        for (int c = 0; c < 3; ++c) rgba[i * 4 + c] = factor[i][c];
    if (albedoTexture_->width() != resolution || albedoTexture_->height() != resolution)
        albedoTexture_ = std::make_unique<FloatTexture>(resolution, resolution);
    albedoTexture_->upload(rgba.data());
    albedoVersion_ = version;
}

void MaterialTables::updateNormals(const std::vector<glm::vec3>& normal, int resolution,
                                   uint64_t version) {
    if (!normalTexture_) {  // bound even when unread, as the albedo's
        normalTexture_ = std::make_unique<FloatTexture>(1, 1);
        const float none[4] = {0, 0, 0, 0};
        normalTexture_->upload(none);
    }
    normalMapped_ = !normal.empty();
    if (!normalMapped_ || version == normalVersion_) return;
    TSIS_CHECK_EQ(normal.size(), static_cast<size_t>(resolution) * resolution);
    std::vector<float> rgba(normal.size() * 4, 0.0f);
    for (size_t i = 0; i < normal.size(); ++i)
        for (int c = 0; c < 3; ++c) rgba[i * 4 + c] = normal[i][c];
    if (normalTexture_->width() != resolution || normalTexture_->height() != resolution)
        normalTexture_ = std::make_unique<FloatTexture>(resolution, resolution);
    normalTexture_->upload(rgba.data());
    normalVersion_ = version;
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
