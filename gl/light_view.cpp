#include "gl/light_view.h"

#include "scene/projection.h"
#include "util/error.h"

namespace tsis {

namespace {

void setProjection(LightView& lv, const Light& light, float radius, int resolution) {
    lv.light = light;
    const LightProjection lp = lightProjection(light, radius, resolution);
    lv.viewProj = lp.viewProj;
    lv.tanHalf = lp.tanHalf;
    lv.texelAreaMm = lp.texelAreaMm;
    lv.texelMm = lp.texelMm;
    lv.resolution = resolution;
}

// `lv`'s target as `maps` RGBA32F maps of resolution², made when it has
// another shape.
void ensureMaps(LightView& lv, int resolution, int maps, bool depth) {
    if (!lv.target || lv.target->width() != resolution || lv.target->colorCount() != maps)
        lv.target = std::make_unique<RenderTarget>(
            resolution, resolution, std::vector<GLenum>(size_t(maps), GL_RGBA32F), depth);
}

}  // namespace

LightView makeLightView(const Light& light, float radius, int resolution, bool maps) {
    LightView lv;
    updateLightView(lv, light, radius, resolution, maps);
    return lv;
}

void updateLightView(LightView& lv, const Light& light, float radius, int resolution, bool maps) {
    setProjection(lv, light, radius, resolution);
    if (maps)
        ensureMaps(lv, resolution, 2, false);
    else
        lv.target.reset();
}

void updateScatterView(LightView& lv, const Light& light, float radius, int resolution,
                       bool drawn) {
    setProjection(lv, light, radius, resolution);
    ensureMaps(lv, resolution, drawn ? 2 : 0, true);
}

ShadowMapArray::~ShadowMapArray() {
    if (id_) glDeleteTextures(1, &id_);
}

bool ShadowMapArray::ensure(int resolution, int layers) {
    if (id_ && resolution == resolution_ && layers == layers_) return false;
    if (id_) glDeleteTextures(1, &id_);
    glGenTextures(1, &id_);
    glBindTexture(GL_TEXTURE_2D_ARRAY, id_);
    glTexStorage3D(GL_TEXTURE_2D_ARRAY, 1, GL_DEPTH_COMPONENT32F, resolution, resolution, layers);
    setShadowSampling(GL_TEXTURE_2D_ARRAY);
    resolution_ = resolution;
    layers_ = layers;
    return true;
}

void bindAndClearLightView(GLuint framebuffer, const LightView& view, const ShadowMapArray& shadows,
                           int layer) {
    if (view.target) {
        view.target->bindAndClear(framebuffer);  // its maps (it has no depth)
    } else {
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        // A framebuffer may have held a view with maps before.
        for (GLenum i = 0; i < 3; ++i)
            glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + i, GL_TEXTURE_2D, 0, 0);
        glDrawBuffer(GL_NONE);
        glViewport(0, 0, view.resolution, view.resolution);
    }
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, shadows.id(), 0, layer);
    const float one = 1.0f;
    glClearBufferfv(GL_DEPTH, 0, &one);
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
