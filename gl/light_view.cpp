#include "gl/light_view.h"

#include "scene/projection.h"
#include "util/error.h"

namespace tsis {

LightView makeLightView(const Light& light, float radius, int resolution, bool maps, bool normals) {
    LightView lv;
    updateLightView(lv, light, radius, resolution, maps, normals);
    return lv;
}

void updateLightView(LightView& lv, const Light& light, float radius, int resolution, bool maps,
                     bool normals) {
    lv.light = light;
    const LightProjection lp = lightProjection(light, radius, resolution);
    lv.viewProj = lp.viewProj;
    lv.tanHalf = lp.tanHalf;
    lv.texelAreaMm = lp.texelAreaMm;
    lv.texelMm = lp.texelMm;
    const int colours = maps ? (normals ? 3 : 2) : 0;
    if (!lv.target || lv.target->width() != resolution || lv.target->colorCount() != colours)
        lv.target = std::make_unique<RenderTarget>(
            resolution, resolution, std::vector<GLenum>(size_t(colours), GL_RGBA32F), true);
}

ShadowMapArray::~ShadowMapArray() {
    if (id_) glDeleteTextures(1, &id_);
}

void ShadowMapArray::update(const std::vector<LightView>& lights,
                            const std::vector<size_t>& changed) {
    if (lights.empty()) return;
    int res = lights[0].target->width();
    int layers = static_cast<int>(lights.size());
    bool all = false;
    if (!id_ || res != resolution_ || layers != layers_) {
        if (id_) glDeleteTextures(1, &id_);
        glGenTextures(1, &id_);
        glBindTexture(GL_TEXTURE_2D_ARRAY, id_);
        glTexStorage3D(GL_TEXTURE_2D_ARRAY, 1, GL_DEPTH_COMPONENT32F, res, res, layers);
        setShadowSampling(GL_TEXTURE_2D_ARRAY);
        resolution_ = res;
        layers_ = layers;
        all = true;
    }
    auto copy = [&](size_t i) {
        glCopyImageSubData(lights[i].target->depth(), GL_TEXTURE_2D, 0, 0, 0, 0, id_,
                           GL_TEXTURE_2D_ARRAY, 0, 0, 0, static_cast<int>(i), res, res, 1);
    };
    if (all)
        for (size_t i = 0; i < lights.size(); ++i) copy(i);
    else
        for (size_t i : changed) copy(i);
}

void bindLights(const ShaderProgram& program, const std::vector<LightView>& lights, int unit,
                const ShadowMapArray& shadows) {
    TSIS_CHECK_LE(lights.size(), static_cast<size_t>(kMaxLights));
    program.set("u_lightCount", static_cast<int>(lights.size()));
    program.set("u_shadowMaps", unit);
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
    glBindTexture(GL_TEXTURE_2D_ARRAY, shadows.id());
    for (int i = 0; i < static_cast<int>(lights.size()); ++i) {
        auto at = [i](const char* base) {
            std::string s(base);
            s += '[';
            s += std::to_string(i);
            s += ']';
            return s;
        };
        const LightView& lv = lights[static_cast<size_t>(i)];
        program.set(at("u_lightType").c_str(), lv.light.type == Light::Type::Point ? 0 : 1);
        program.set(at("u_lightVec").c_str(), lv.light.vec);
        program.set(at("u_lightRgb").c_str(), lv.light.rgb);
        program.set(at("u_lightViewProj").c_str(), lv.viewProj);
        program.set(at("u_shadowTexelMm").c_str(), lv.texelMm);
        program.set(at("u_lightShadows").c_str(), lv.light.shadows ? 1 : 0);
    }
}

}  // namespace tsis
