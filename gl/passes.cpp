#include "gl/passes.h"

#include "gl/gl_context.h"

namespace tsis {

namespace {

// Texture units: 0–3 for a pass's own inputs, 4 for the shadow map array.
constexpr int kShadowUnit = 4;

void bindTexture(const ShaderProgram& p, const char* name, int unit, GLuint tex) {
    p.set(name, unit);
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
    glBindTexture(GL_TEXTURE_2D, tex);
}

// (Re)creates a target when missing or of another size.
void ensureTarget(std::unique_ptr<RenderTarget>& t, int w, int h, std::vector<GLenum> formats,
                  bool depth) {
    if (!t || t->width() != w || t->height() != h)
        t = std::make_unique<RenderTarget>(w, h, std::move(formats), depth);
}

}  // namespace

LightViewPass::LightViewPass()
    : program_("mesh.vert", "light_view.frag"), depthProgram_("mesh.vert", "depth.frag") {}

void LightViewPass::run(const GpuMesh& mesh, std::vector<LightView>& lights, float eta) {
    program_.use();
    bindLights(program_, lights, eta, kShadowUnit, shadows_);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    for (size_t i = 0; i < lights.size(); ++i) {
        RenderTarget& t = *lights[i].target;
        t.bindAndClear();
        const bool maps = t.colorCount() > 0;
        const ShaderProgram& p = maps ? program_ : depthProgram_;
        p.use();
        p.set("u_viewProj", lights[i].viewProj);
        if (maps) {
            p.set("u_light", static_cast<int>(i));
            p.set("u_tanHalf", lights[i].tanHalf);
            p.set("u_texelAreaMm", lights[i].texelAreaMm);
            p.set("u_resolution", glm::vec2(t.width(), t.height()));
        }
        mesh.draw();
    }
    glDisable(GL_DEPTH_TEST);
    shadows_.update(lights);
    checkGl("LightViewPass");
}

GeometryAtlasPass::GeometryAtlasPass() : program_("atlas.vert", "atlas.frag") {}

void GeometryAtlasPass::run(const GpuMesh& mesh, int resolution) {
    ensureTarget(target_, resolution, resolution, {GL_RGBA32F, GL_RGBA32F}, false);
    target_->bindAndClear();
    program_.use();
    program_.set("u_texelArea", 1.0f / (static_cast<float>(resolution) * resolution));
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    mesh.drawUnrolled();
    checkGl("GeometryAtlasPass");
}

FluxAtlasPass::FluxAtlasPass() : program_("fullscreen.vert", "flux_atlas.frag") {
    glGenVertexArrays(1, &emptyVao_);
}

void FluxAtlasPass::run(const RenderTarget& geometry, const std::vector<LightView>& lights,
                        const ShadowMapArray& shadows, float eta, GLuint envIrradiance) {
    ensureTarget(target_, geometry.width(), geometry.height(), {GL_RGBA32F}, false);
    target_->bindAndClear();
    program_.use();
    bindLights(program_, lights, eta, kShadowUnit, shadows);
    bindTexture(program_, "u_position", 0, geometry.color(0));
    bindTexture(program_, "u_normal", 1, geometry.color(1));
    bindTexture(program_, "u_envIrradiance", 2, envIrradiance);
    program_.set("u_hasEnv", envIrradiance != 0 ? 1 : 0);
    glDisable(GL_DEPTH_TEST);
    glBindVertexArray(emptyVao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    checkGl("FluxAtlasPass");
}

void GBufferPass::run(const GpuMesh& mesh, const std::vector<LightView>& lights,
                      const ShadowMapArray& shadows, float eta, const glm::mat4& viewProj,
                      int width, int height, bool irradiance) {
    current_ = irradiance ? 1 : 0;
    Variant& v = variants_[current_];
    if (!v.program)
        v.program = std::make_unique<ShaderProgram>(
            "mesh.vert", "gbuffer.frag", irradiance ? "#define TSIS_GBUFFER_IRRADIANCE 1\n" : "");
    std::vector<GLenum> formats(irradiance ? 3 : 2, GL_RGBA32F);
    ensureTarget(v.target, width, height, formats, true);
    v.target->bindAndClear();
    const ShaderProgram& program = *v.program;
    program.use();
    bindLights(program, lights, eta, kShadowUnit, shadows);
    program.set("u_viewProj", viewProj);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    mesh.draw();
    glDisable(GL_DEPTH_TEST);
    checkGl("GBufferPass");
}

CompositePass::CompositePass()
    : radianceProgram_("fullscreen.vert", "radiance.frag"),
      toneMapProgram_("fullscreen.vert", "tonemap.frag") {
    glGenVertexArrays(1, &emptyVao_);
}

void CompositePass::radiance(const float* radiosityRGBA, const RenderTarget& gbuffer,
                             const glm::vec3& eye, float eta, float exitScale) {
    int w = gbuffer.width(), h = gbuffer.height();
    ensureTarget(radianceTarget_, w, h, {GL_RGBA32F}, false);
    if (!radiosity_ || radiosity_->width() != w || radiosity_->height() != h)
        radiosity_ = std::make_unique<FloatTexture>(w, h);
    radiosity_->upload(radiosityRGBA);
    radianceTarget_->bindAndClear();
    radianceProgram_.use();
    radianceProgram_.set("u_eta", eta);
    radianceProgram_.set("u_eye", eye);
    radianceProgram_.set("u_exitScale", exitScale);
    bindTexture(radianceProgram_, "u_radiosity", 0, radiosity_->id());
    bindTexture(radianceProgram_, "u_position", 1, gbuffer.color(0));
    bindTexture(radianceProgram_, "u_normal", 2, gbuffer.color(1));
    glBindVertexArray(emptyVao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    checkGl("CompositePass::radiance");
}

void CompositePass::toneMap(const RenderTarget& gbuffer, const std::vector<LightView>& lights,
                            const ShadowMapArray& shadows, const glm::vec3& eye, float eta,
                            float key, float lavg, float specular, float shininess) {
    int w = gbuffer.width(), h = gbuffer.height();
    ensureTarget(colorTarget_, w, h, {GL_RGBA8}, false);
    colorTarget_->bindAndClear();
    toneMapProgram_.use();
    bindLights(toneMapProgram_, lights, eta, kShadowUnit, shadows);
    toneMapProgram_.set("u_eye", eye);
    toneMapProgram_.set("u_key", key);
    toneMapProgram_.set("u_lavg", lavg);
    toneMapProgram_.set("u_specular", specular);
    toneMapProgram_.set("u_shininess", shininess);
    bindTexture(toneMapProgram_, "u_radiance", 0, radianceTarget_->color(0));
    bindTexture(toneMapProgram_, "u_position", 1, gbuffer.color(0));
    bindTexture(toneMapProgram_, "u_normal", 2, gbuffer.color(1));
    glBindVertexArray(emptyVao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    checkGl("CompositePass::toneMap");
}

}  // namespace tsis
