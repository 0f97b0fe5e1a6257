#include "gl/passes.h"

#include <algorithm>
#include <cmath>
#include <glm/matrix.hpp>

#include "gl/gl_context.h"
#include "util/error.h"
#include "util/hash.h"

namespace tsis {

namespace {

// Texture units: 0–3, 5, 8, 9 and 10 for a pass's own inputs, 4 for the
// shadow map array, 6, 7 and 11 for the material tables.
constexpr int kShadowUnit = 4;
constexpr int kMediaUnit = 6;
constexpr int kShadingNormalUnit = 11;
constexpr int kBackgroundUnit = 12;
// The supersampled pixels' slots a row (CompositePass::edgePixels_).
constexpr int kEdgeColumns = 64;

void bindTexture(const ShaderProgram& p, const char* name, int unit, GLuint tex,
                 GLenum target = GL_TEXTURE_2D) {
    p.set(name, unit);
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
    glBindTexture(target, tex);
}

// A sampler that reads depth as a value (a RenderTarget's depth and the
// shadow maps compare, as a shadow map does), texel by texel.
GLuint rawDepthSampler() {
    GLuint sampler = 0;
    glGenSamplers(1, &sampler);
    glSamplerParameteri(sampler, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(sampler, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return sampler;
}

// (Re)creates a target when missing or of another size.
void ensureTarget(std::unique_ptr<RenderTarget>& t, int w, int h, std::vector<GLenum> formats,
                  bool depth) {
    if (!t || t->width() != w || t->height() != h)
        t = std::make_unique<RenderTarget>(w, h, std::move(formats), depth);
}

// A full-screen triangle at depth 1 against the G-buffer depth the bound
// target holds: GL_GREATER draws where the surface is, GL_EQUAL where it is
// not. llvmpipe runs both sides of a shader's branches, so a pass that only
// tested coverage would shade every pixel; the depth test drops the others'
// blocks before the shader.
void drawFullScreenWhere(GLenum depthFunc) {
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glDepthRange(1.0, 1.0);
    glDepthFunc(depthFunc);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDepthRange(0.0, 1.0);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);
}

// `mesh` with the depth test, back faces culled when `cull`, through
// `vertexArray` (GpuMesh::draw); both tests off after.
void drawDepthTested(const GpuMesh& mesh, bool cull, GLuint vertexArray = 0) {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    if (cull)
        glEnable(GL_CULL_FACE);
    else
        glDisable(GL_CULL_FACE);
    mesh.draw(vertexArray);
    glDisable(GL_CULL_FACE);
    glDisable(GL_DEPTH_TEST);
}

// Copies `from`'s depth into `to`'s (same size).
void copyDepth(const RenderTarget& from, const RenderTarget& to) {
    glCopyImageSubData(from.depth(), GL_TEXTURE_2D, 0, 0, 0, 0, to.depth(), GL_TEXTURE_2D, 0, 0, 0,
                       0, from.width(), from.height(), 1);
}

// Draws each of `views`: every other one that mayMove(i) allows on
// `worker`'s thread (there(i)), in parallel with the others here (here(i)),
// then waits for the worker; null: all here. llvmpipe sets up each thread's
// triangles alone, so two views take little more than one. Returns how many
// the worker drew.
template <typename MayMove, typename There, typename Here>
size_t drawSplit(GlWorker* worker, const std::vector<size_t>& views, const MayMove& mayMove,
                 const There& there, const Here& here, const char* what) {
    std::vector<size_t> mine, theirs;
    for (size_t k = 0; k < views.size(); ++k)
        (worker && k % 2 == 1 && mayMove(views[k]) ? theirs : mine).push_back(views[k]);
    const bool split = worker && !theirs.empty();
    if (split)
        worker->start([&there, &theirs, what] {
            for (size_t i : theirs) there(i);
            checkGl(what);
        });
    try {
        for (size_t i : mine) here(i);
    } catch (...) {
        if (split) worker->wait();  // it reads the caller's views
        throw;
    }
    if (split) worker->wait();
    checkGl(what);
    return theirs.size();
}

}  // namespace

LightViewPass::LightViewPass()
    : program_("mesh.vert", "light_view.frag"), depthProgram_("mesh.vert", "depth.frag") {
    glGenFramebuffers(1, &framebuffer_);
}

LightViewPass::~LightViewPass() {
    if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
}

void LightViewPass::run(const GpuMesh& mesh, std::vector<LightView>& lights,
                        const MaterialTables& media) {
    std::vector<size_t> all(lights.size());
    for (size_t i = 0; i < all.size(); ++i) all[i] = i;
    run(mesh, lights, media, all);
}

void LightViewPass::drawDepth(const GpuMesh& mesh, const LightView& view, int layer,
                              const ShaderProgram& program, GLuint framebuffer,
                              GLuint vertexArray) const {
    bindAndClearLightView(framebuffer, view, shadows_, layer);
    program.use();
    program.set("u_viewProj", view.viewProj);
    // A closed, outward mesh: its back faces are never the nearest (a third
    // less of llvmpipe's per-triangle work).
    drawDepthTested(mesh, mesh.closedOutward(), vertexArray);
}

size_t LightViewPass::run(const GpuMesh& mesh, std::vector<LightView>& lights,
                          const MaterialTables& media, const std::vector<size_t>& changed,
                          const GpuMesh* depthMesh) {
    if (lights.empty()) return 0;
    // Each view draws its depth straight into its layer; a new array (size or
    // count) has every layer to draw.
    std::vector<size_t> views = changed;
    if (shadows_.ensure(lights[0].resolution, static_cast<int>(lights.size()))) {
        views.resize(lights.size());
        for (size_t i = 0; i < views.size(); ++i) views[i] = i;
    }
    // Every other depth-only view to the worker's thread.
    const GpuMesh& depthDrawn = depthMesh ? *depthMesh : mesh;
    GlWorker* worker = side_.workerFor(depthDrawn.trianglesSetUp(depthDrawn.closedOutward()));
    return drawSplit(
        worker, views, [&](size_t i) { return lights[i].target == nullptr; },
        [&](size_t i) {
            drawDepth(depthDrawn, lights[i], static_cast<int>(i), side_.program(),
                      side_.framebuffer(), side_.vertexArray());
        },
        [&](size_t i) {
            if (!lights[i].target) {
                drawDepth(depthDrawn, lights[i], static_cast<int>(i), depthProgram_, framebuffer_,
                          0);
                return;
            }
            bindAndClearLightView(framebuffer_, lights[i], shadows_, static_cast<int>(i));
            program_.use();
            bindLights(program_, lights, kShadowUnit, shadows_);
            // The array is drawn into, not read: no texture of it bound.
            glActiveTexture(GL_TEXTURE0 + kShadowUnit);
            glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
            media.bind(program_, kMediaUnit, kShadingNormalUnit);
            program_.set("u_viewProj", lights[i].viewProj);
            program_.set("u_light", static_cast<int>(i));
            program_.set("u_tanHalf", lights[i].tanHalf);
            program_.set("u_texelAreaMm", lights[i].texelAreaMm);
            program_.set("u_resolution", glm::vec2(lights[i].resolution));
            drawDepthTested(mesh, mesh.closedOutward());
        },
        "LightViewPass");
}

ScatterViewPass::ScatterViewPass() : program_("mesh.vert", "scatter_view.frag") {
    glGenFramebuffers(1, &readFramebuffer_);
}

ScatterViewPass::~ScatterViewPass() {
    if (readFramebuffer_) glDeleteFramebuffers(1, &readFramebuffer_);
}

void ScatterViewPass::copyDepth(const ShadowMapArray& shadows, const std::vector<LightView>& views,
                                const std::vector<size_t>& changed) {
    for (size_t i : changed) {
        const LightView& view = views[i];
        view.target->bind();  // the blit writes every texel: no clear
        glBindFramebuffer(GL_READ_FRAMEBUFFER, readFramebuffer_);
        glFramebufferTextureLayer(GL_READ_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, shadows.id(), 0,
                                  static_cast<GLint>(i));
        const int from = shadows.resolution(), to = view.resolution;
        glBlitFramebuffer(0, 0, from, from, 0, 0, to, to, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    }
    checkGl("ScatterViewPass::copyDepth");
}

void ScatterViewPass::draw(const GpuMesh& mesh, const LightView& view, const MaterialTables& media,
                           const ShaderProgram& program, GLuint framebuffer,
                           GLuint vertexArray) const {
    view.target->bindAndClear(framebuffer);
    program.use();
    media.bind(program, kMediaUnit, kShadingNormalUnit);
    program.set("u_viewProj", view.viewProj);
    drawDepthTested(mesh, mesh.closedOutward(), vertexArray);
}

void ScatterViewPass::run(const GpuMesh& mesh, const std::vector<LightView>& views,
                          const MaterialTables& media, const std::vector<size_t>& changed) {
    // Every other view on the worker: these small views are all set-up.
    drawSplit(
        side_.workerFor(mesh.trianglesSetUp(mesh.closedOutward())), changed,
        [](size_t) { return true; },
        [&](size_t i) {
            draw(mesh, views[i], media, side_.program(), side_.framebuffer(), side_.vertexArray());
        },
        [&](size_t i) { draw(mesh, views[i], media, program_, 0, 0); }, "ScatterViewPass");
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

FluxAtlasPass::FluxAtlasPass()
    : programs_("fullscreen.vert", "flux_atlas.frag", {"TSIS_ENV", "TSIS_TEXTURED"}) {
    glGenVertexArrays(1, &emptyVao_);
}

void FluxAtlasPass::run(const RenderTarget& geometry, const std::vector<LightView>& lights,
                        const ShadowMapArray& shadows, const MaterialTables& media,
                        GLuint envIrradiance) {
    ensureTarget(target_, geometry.width(), geometry.height(), {GL_RGBA32F}, false);
    target_->bind();  // every texel drawn (0 where uncovered): no clear
    const ShaderProgram& program =
        programs_.get((envIrradiance != 0 ? 1u : 0u) | (media.textured() ? 2u : 0u));
    program.use();
    bindLights(program, lights, kShadowUnit, shadows);
    media.bind(program, kMediaUnit, kShadingNormalUnit);
    bindTexture(program, "u_position", 0, geometry.color(0));
    bindTexture(program, "u_normal", 1, geometry.color(1));
    bindTexture(program, "u_envIrradiance", 2, envIrradiance);
    glDisable(GL_DEPTH_TEST);
    glBindVertexArray(emptyVao_);
    // Full-screen: a depth test against the covered texels (as the composite
    // does) measured slower here, most blocks holding some.
    glDrawArrays(GL_TRIANGLES, 0, 3);
    checkGl("FluxAtlasPass");
}

void GBufferPass::start(const GpuMesh& mesh, const std::vector<LightView>& lights,
                        const ShadowMapArray& shadows, const MaterialTables& media,
                        const glm::mat4& viewProj, int width, int height, unsigned outputs,
                        GLuint envIrradiance, bool cull) {
    TSIS_CHECK_LT(outputs, 4u);
    finish();
    current_ = static_cast<int>(outputs);
    // The target's textures are made here, in the caller's context.
    std::vector<GLenum> formats(2, GL_RGBA32F);
    if (outputs & kIrradiance) formats.push_back(GL_RGBA32F);
    if (outputs & kUv) formats.push_back(GL_RG32F);
    ensureTarget(targets_[current_], width, height, formats, true);
    const Draw d{&mesh, &lights, &shadows, &media, viewProj, outputs, envIrradiance, cull, eye_};
    GlWorker* worker = side_.workerFor(mesh.trianglesSetUp(cull));
    if (!worker) {
        draw(d, programs_.get(outputs), 0, 0);
        return;
    }
    worker->start(
        [this, d] { draw(d, side_.program(d.outputs), side_.framebuffer(), side_.vertexArray()); });
    started_ = true;
}

void GBufferPass::finish() {
    if (!started_) return;
    started_ = false;
    side_.worker()->wait();
}

void GBufferPass::draw(const Draw& d, const ShaderProgram& program, GLuint framebuffer,
                       GLuint vertexArray) {
    RenderTarget& target = *targets_[current_];
    if (clearColor_)
        target.bindAndClear(framebuffer);
    else
        target.bindAndClearDepth(framebuffer);
    program.use();
    bindLights(program, *d.lights, kShadowUnit, *d.shadows);
    d.media->bind(program, kMediaUnit, kShadingNormalUnit);
    program.set("u_viewProj", d.viewProj);
    program.set("u_eye", d.eye);
    if (d.outputs & kIrradiance) {
        bindTexture(program, "u_envIrradiance", 0, d.envIrradiance);
        program.set("u_hasEnv", d.envIrradiance != 0 ? 1 : 0);
    }
    drawDepthTested(*d.mesh, d.cull, vertexArray);
    checkGl("GBufferPass");
}

CompositePass::CompositePass()
    : centrePrograms_("fullscreen.vert", "radiance.frag",
                      {"TSIS_SPECULAR", "TSIS_ENV_REFLECT", "TSIS_FIND_EDGES", "TSIS_DISPLAY"}),
      samplePrograms_("fullscreen.vert", "radiance.frag", {"TSIS_SPECULAR", "TSIS_ENV_REFLECT"},
                      "#define TSIS_COMPOSITE_SAMPLES 1\n"),
      resolveProgram_("fullscreen.vert", "resolve.frag"),
      resolveEdgesProgram_("fullscreen.vert", "resolve.frag", "#define TSIS_RESOLVE_EDGES 1\n"),
      toneMapProgram_("fullscreen.vert", "resolve.frag", "#define TSIS_TONE_MAP 1\n"),
      toneMapEdgesProgram_("fullscreen.vert", "resolve.frag",
                           "#define TSIS_TONE_MAP 1\n#define TSIS_RESOLVE_EDGES 1\n"),
      backgroundProgram_("fullscreen.vert", "resolve.frag",
                         "#define TSIS_TONE_MAP 1\n#define TSIS_BACKGROUND 1\n"),
      reduceProgram_("fullscreen.vert", "reduce.frag"),
      fxaaProgram_("fullscreen.vert", "fxaa.frag") {
    glGenVertexArrays(1, &emptyVao_);
    depthSampler_ = rawDepthSampler();
    // The display read between texels (fxaa.frag).
    glGenSamplers(1, &linearSampler_);
    glSamplerParameteri(linearSampler_, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glSamplerParameteri(linearSampler_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glSamplerParameteri(linearSampler_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(linearSampler_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    // The G-buffer's neighbours at constant offsets (radiance.frag's edge marks).
    glGenSamplers(1, &clampSampler_);
    glSamplerParameteri(clampSampler_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(clampSampler_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glSamplerParameteri(clampSampler_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(clampSampler_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

CompositePass::~CompositePass() {
    if (depthSampler_) glDeleteSamplers(1, &depthSampler_);
    if (linearSampler_) glDeleteSamplers(1, &linearSampler_);
    if (clampSampler_) glDeleteSamplers(1, &clampSampler_);
}

// The centre pass' marks read back and listed: the covered pixels it marked
// (r), and the uncovered ones with a covered pixel (g) in their 3×3
// neighbourhood — the same test the centre pass makes, on the host, instead
// of a full-screen pass over the uncovered pixels.
void CompositePass::updateEdgePoints(uint64_t key, const RenderTarget& target, int index) {
    const int w = target.width(), h = target.height();
    const std::vector<unsigned char> marks = target.readRGBA8(index);
    const size_t width = static_cast<size_t>(w);
    // Coverage dilated along each row, then the 3×3 test as three rows' look-ups.
    std::vector<unsigned char> rowNear(width * static_cast<size_t>(h), 0);
    for (int y = 0; y < h; ++y) {
        const unsigned char* m = &marks[static_cast<size_t>(y) * width * 4];
        unsigned char* near = &rowNear[static_cast<size_t>(y) * width];
        for (int x = 0; x < w; ++x)
            if (m[x * 4 + 1]) near[std::max(0, x - 1)] = near[x] = near[std::min(w - 1, x + 1)] = 1;
    }
    // The list as a texture of slots, pixel e's at (e mod kEdgeColumns, e div
    // kEdgeColumns), rows in steps of 8 (fewer re-made targets); the slots
    // past the list repeat its last pixel (shaded, never read).
    std::vector<glm::vec2> points;
    for (int y = 0; y < h; ++y) {
        const unsigned char* m = &marks[static_cast<size_t>(y) * width * 4];
        const unsigned char* above = &rowNear[static_cast<size_t>(std::max(0, y - 1)) * width];
        const unsigned char* row = &rowNear[static_cast<size_t>(y) * width];
        const unsigned char* below = &rowNear[static_cast<size_t>(std::min(h - 1, y + 1)) * width];
        for (int x = 0; x < w; ++x)
            if (m[x * 4 + 1] ? m[x * 4] != 0 : (above[x] | row[x] | below[x]) != 0)
                points.emplace_back(x, y);
    }
    edgeCount_ = static_cast<GLsizei>(points.size());
    edgesKey_ = key;
    const int rows = std::max(1, (edgeCount_ + kEdgeColumns * 8 - 1) / (kEdgeColumns * 8)) * 8;
    std::vector<float> slots(size_t(kEdgeColumns) * size_t(rows) * 4, 0.0f);
    for (size_t e = 0; !points.empty() && e < slots.size() / 4; ++e) {
        const glm::vec2 p = points[std::min(e, points.size() - 1)];
        slots[e * 4] = p.x;
        slots[e * 4 + 1] = p.y;
    }
    if (!edgePixels_ || edgePixels_->height() != rows)
        edgePixels_ = std::make_unique<FloatTexture>(kEdgeColumns, rows);
    edgePixels_->upload(slots.data());
}

void CompositePass::radiance(const float* radiosityRGBA, GLuint radiosityTexture,
                             const RenderTarget& frameGbuffer, uint64_t gbufferVersion,
                             const RenderTarget& sampleGbuffer, int aa,
                             const std::vector<LightView>& lights, const ShadowMapArray& shadows,
                             const glm::vec3& eye, const MaterialTables& materials, bool specular,
                             const EnvReflectionTextures& env, std::optional<float> displayScale) {
    const int w = frameGbuffer.width(), h = frameGbuffer.height();
    TSIS_CHECK_EQ(sampleGbuffer.width(), w * aa);
    TSIS_CHECK_EQ(sampleGbuffer.height(), h * aa);
    aa_ = aa;
    if (radiosityRGBA) {
        if (!radiosity_ || radiosity_->width() != w || radiosity_->height() != h)
            radiosity_ = std::make_unique<FloatTexture>(w, h);
        radiosity_->upload(radiosityRGBA);
        radiosityTexture = radiosity_->id();
    }
    glBindVertexArray(emptyVao_);
    // The pixels' centres, and which pixels to supersample.
    // The pixels to supersample follow the G-buffer (the camera), not the
    // lights: marked, read back and listed only when it changed.
    const uint64_t edgesKey = Hasher(gbufferVersion).add(w).add(h).add(aa).add(fxaa_).digest();
    coverageKey_ = edgesKey;
    const bool marks = aa > 1 || fxaa_;  // the edge pixels listed
    const bool findEdges = marks && (!edgePixels_ || edgesKey != edgesKey_);
    // Only the covered pixels shaded (the G-buffer's depth, < 1 there), and
    // only they read: the radiance is not cleared, the marks only when read.
    // Straight to the display, the centres write its colour and log
    // luminance (the tone map's pass over a frame of radiance saved).
    const bool direct = displayScale.has_value();
    std::unique_ptr<RenderTarget>& target = direct ? directTarget_ : centreTarget_;
    const int markIndex = direct ? 2 : 1;
    ensureTarget(target, w, h,
                 direct ? std::vector<GLenum>{GL_RGBA8, GL_RG32F, GL_RGBA8}
                        : std::vector<GLenum>{GL_RGBA32F, GL_RGBA8},
                 true);
    target->bind();
    copyDepth(frameGbuffer, *target);
    if (findEdges) {
        const float zero[4] = {0, 0, 0, 0};
        glClearBufferfv(GL_COLOR, markIndex, zero);
    }
    const unsigned features = (specular ? 1u : 0u) | (env.prefiltered != 0 ? 2u : 0u);
    const ShaderProgram& centre =
        centrePrograms_.get(features | (findEdges ? 4u : 0u) | (direct ? 8u : 0u));
    const ShaderProgram& samples = samplePrograms_.get(features);
    for (const ShaderProgram* p : {&centre, &samples}) {
        p->use();
        bindLights(*p, lights, kShadowUnit, shadows);
        materials.bind(*p, kMediaUnit, kShadingNormalUnit);
        p->set("u_eye", eye);
        p->set("u_envLayers", env.layers);
        p->set("u_ladderSteps", env.ladderSteps);
        p->set("u_ladderLayer", env.ladderLayer);
        p->set("u_ladderRow", env.ladderRow);
        p->set("u_ladderMin", env.ladderMin);
        p->set("u_worldToMap", env.worldToMap);
        p->set("u_envScale", env.scale);
        bindTexture(*p, "u_envPrefiltered", 8, env.prefiltered);
        bindTexture(*p, "u_envAlbedo", 9, env.albedo);
    }
    if (direct) {
        setToneMapScale(*displayScale, w, h);
        copyStaticBackground(*target, directBackgroundKey_);
    }
    centre.use();
    if (direct) setDisplayUniforms(centre, *displayScale, w, h);
    bindTexture(centre, "u_radiosity", 0, radiosityTexture);
    bindTexture(centre, "u_framePosition", 1, frameGbuffer.color(0));
    glBindSampler(1, clampSampler_);
    bindTexture(centre, "u_normal", 2, frameGbuffer.color(1));
    bindBackgroundMap();
    drawFullScreenWhere(GL_GREATER);
    glBindSampler(1, 0);
    if (findEdges) updateEdgePoints(edgesKey, *target, markIndex);
    if (aa > 1) {
        // Only the marked pixels' samples are drawn, and only they are read.
        // The marked pixels' samples, packed: edge e's aa × aa block at its
        // slot in edgePixels_ (llvmpipe shades full 4×4 blocks, where a
        // point per pixel filled a quarter of each).
        if (edgeCount_ > 0) {
            ensureTarget(sampleTarget_, kEdgeColumns * aa, edgePixels_->height() * aa, {GL_RGBA32F},
                         false);
            sampleTarget_->bind();
            samples.use();
            samples.set("u_aa", aa);
            bindTexture(samples, "u_radiosity", 0, radiosityTexture);
            bindTexture(samples, "u_framePosition", 1, frameGbuffer.color(0));
            bindTexture(samples, "u_normal", 2, sampleGbuffer.color(1));
            bindTexture(samples, "u_position", 3, sampleGbuffer.color(0));
            // Coverage from the samples' depth (their colour is not cleared).
            bindTexture(samples, "u_sampleDepth", 5, sampleGbuffer.depth());
            glBindSampler(5, depthSampler_);
            bindTexture(samples, "u_edgePixels", 10, edgePixels_->id());
            glBindVertexArray(emptyVao_);
            glDrawArrays(GL_TRIANGLES, 0, 3);
            glBindSampler(5, 0);
        }
    }
    if (direct) {
        // The background and the supersampled pixels into the display and
        // the log luminance, the marks left as they are.
        target->bind();
        const GLenum drawn[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_NONE};
        glDrawBuffers(3, drawn);
        drawAroundCentres(*target, &backgroundProgram_, toneMapEdgesProgram_);
        const GLenum all[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
        glDrawBuffers(3, all);
        logLuminance_ = display_ = target.get();
    }
    checkGl("CompositePass::radiance");
}

void CompositePass::setDisplayUniforms(const ShaderProgram& p, float scale, int width,
                                       int height) const {
    p.use();
    p.set("u_scale", scale);
    p.set("u_tone", tone_);
    p.set("u_frameSize", glm::vec2(width, height));
    p.set("u_background", background_.mode);
    p.set("u_inverseViewProj", background_.inverseViewProj);
    p.set("u_backgroundToMap", background_.worldToMap);
    p.set("u_backgroundScale", background_.scale);
    p.set("u_envBackground", kBackgroundUnit);
}

void CompositePass::bindBackgroundMap() const {
    // Just before a draw that reads it: a target made since (ensureTarget)
    // binds its textures on the active unit.
    glActiveTexture(GL_TEXTURE0 + kBackgroundUnit);
    glBindTexture(GL_TEXTURE_2D, background_.envMap);
    glActiveTexture(GL_TEXTURE0);
}

void CompositePass::setToneMapScale(float scale, int width, int height) {
    for (const ShaderProgram* p : {&toneMapProgram_, &toneMapEdgesProgram_, &backgroundProgram_})
        setDisplayUniforms(*p, scale, width, height);
}

void CompositePass::copyStaticBackground(RenderTarget& target, uint64_t& backgroundKey) {
    const uint64_t key = Hasher(coverageKey_).add(background_.mode).digest();
    if (background_.mode == 2 || key == backgroundKey) return;
    // The shader's pass over every uncovered pixel (three sRGB powers each)
    // cost llvmpipe ~3.5 ms at 512² in each frame whose coverage changed (the
    // camera moved); a copy of the frame's 1 MiB and a clear cost ~0.1.
    const int w = target.width(), h = target.height();
    const uint64_t cacheKey = Hasher(w).add(h).add(background_.mode).digest();
    if (!backgroundCache_ || cacheKey != backgroundCacheKey_) {
        // A new target's texture binds on the active unit: unit 0, which the
        // centres bind again, not the environment's tables just bound.
        glActiveTexture(GL_TEXTURE0);
        ensureTarget(backgroundCache_, w, h, {GL_RGBA8}, false);
        backgroundCache_->bind();
        backgroundProgram_.use();
        glBindVertexArray(emptyVao_);
        bindBackgroundMap();
        glDrawArrays(GL_TRIANGLES, 0, 3);
        backgroundCacheKey_ = cacheKey;
        target.bind();
    }
    glCopyImageSubData(backgroundCache_->color(0), GL_TEXTURE_2D, 0, 0, 0, 0, target.color(0),
                       GL_TEXTURE_2D, 0, 0, 0, 0, w, h, 1);
    const float zero[4] = {0, 0, 0, 0};
    glClearBufferfv(GL_COLOR, 1, zero);
    backgroundKey = key;
}

void CompositePass::drawAroundCentres(RenderTarget& target, const ShaderProgram* background,
                                      const ShaderProgram& edges) {
    const int w = target.width(), h = target.height();
    glBindVertexArray(emptyVao_);
    bindBackgroundMap();
    // The environment's background follows the camera and the exposure: drawn
    // every frame (the others were copied before the centres).
    if (background && background_.mode == 2) {
        background->use();
        drawFullScreenWhere(GL_EQUAL);
    }
    // At 1× no pixel is marked and the samples are never read. Packed, one
    // fragment a supersampled pixel, each stored at its pixel of `target`'s
    // colour and log luminance (resolve.frag); the packed target's own
    // colour is not read.
    if (aa_ > 1 && edgeCount_ > 0) {
        drawPackedEdges(edges, [&] {
            edges.set("u_aa", aa_);
            edges.set("u_frameSize", glm::vec2(w, h));
            bindTexture(edges, "u_samples", 1, sampleTarget_->color(0));
            glBindImageTexture(0, target.color(0), 0, GL_FALSE, 0, GL_WRITE_ONLY, target.format(0));
            glBindImageTexture(1, target.color(1), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG32F);
            edges.set("u_outColor", 0);
            edges.set("u_outLogLuminance", 1);
        });
        target.bind();
    }
}

void CompositePass::drawPackedEdges(const ShaderProgram& program,
                                    const std::function<void()>& bindInputs) {
    // Made before the inputs are bound: a new target's textures bind on the
    // active unit.
    ensureTarget(edgesPacked_, kEdgeColumns, edgePixels_->height(), {GL_RGBA8}, false);
    edgesPacked_->bind();
    program.use();
    bindTexture(program, "u_edgePixels", 10, edgePixels_->id());
    bindInputs();
    glBindVertexArray(emptyVao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT |
                    GL_PIXEL_BUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}

void CompositePass::resolveInto(const ShaderProgram& centres, const ShaderProgram* background,
                                const ShaderProgram& edges, std::unique_ptr<RenderTarget>& target,
                                std::vector<GLenum> formats) {
    const int w = centreTarget_->width(), h = centreTarget_->height();
    ensureTarget(target, w, h, std::move(formats), true);
    // With a background every pixel is drawn: no clear.
    if (background)
        target->bind();
    else
        target->bindAndClear();
    copyDepth(*centreTarget_, *target);  // the G-buffer's
    if (background) copyStaticBackground(*target, backgroundKey_);
    centres.use();
    bindTexture(centres, "u_centre", 0, centreTarget_->color(0));
    glBindVertexArray(emptyVao_);
    drawFullScreenWhere(GL_GREATER);
    drawAroundCentres(*target, background, edges);
    logLuminance_ = target.get();
}

void CompositePass::resolve() {
    resolveInto(resolveProgram_, nullptr, resolveEdgesProgram_, frameTarget_,
                {GL_RGBA32F, GL_RG32F});
    checkGl("CompositePass::resolve");
}

std::vector<float> CompositePass::frameRadiance() const {
    TSIS_CHECK(frameTarget_ != nullptr);
    return frameTarget_->readRGBA(0);
}

void CompositePass::toneMap(float scale) {
    setToneMapScale(scale, centreTarget_->width(), centreTarget_->height());
    resolveInto(toneMapProgram_, &backgroundProgram_, toneMapEdgesProgram_, colorTarget_,
                {GL_RGBA8, GL_RG32F});
    display_ = colorTarget_.get();
    checkGl("CompositePass::toneMap");
}

void CompositePass::fxaa() {
    TSIS_CHECK(display_ != nullptr && fxaa_);
    const int w = display_->width(), h = display_->height();
    ensureTarget(fxaaTarget_, w, h, {GL_RGBA8}, false);
    glCopyImageSubData(display_->color(0), GL_TEXTURE_2D, 0, 0, 0, 0, fxaaTarget_->color(0),
                       GL_TEXTURE_2D, 0, 0, 0, 0, w, h, 1);
    // Only the edge pixels (the centres' marks, as --aa's samples): a
    // full-screen pass costs llvmpipe ~10 ms at 512² (every 4×4 block runs
    // the search as far as its farthest pixel). Filtered packed, each edge
    // pixel stored into the copy (fxaa.frag).
    if (edgeCount_ > 0) {
        drawPackedEdges(fxaaProgram_, [&] {
            bindTexture(fxaaProgram_, "u_display", 0, display_->color(0));
            glBindSampler(0, linearSampler_);
            glBindImageTexture(0, fxaaTarget_->color(0), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
            fxaaProgram_.set("u_out", 0);
        });
        glBindSampler(0, 0);
    }
    display_ = fxaaTarget_.get();
    checkGl("CompositePass::fxaa");
}

float CompositePass::logAverageLuminance() {
    TSIS_CHECK(logLuminance_ != nullptr);
    // Blocks of 4² a pass until at most 64² sums are left (8 KiB at 512²):
    // llvmpipe shades a target's 64² tiles in parallel, so one pass into a
    // single tile of 16² blocks ran on one thread (1.3 ms at 512², 0.6 in
    // two passes).
    constexpr int kBlock = 4, kMostLeft = 64;
    int w = logLuminance_->width(), h = logLuminance_->height();
    GLuint from = logLuminance_->color(1);
    const RenderTarget* last = nullptr;
    reduceProgram_.use();
    reduceProgram_.set("u_block", kBlock);
    glBindVertexArray(emptyVao_);
    for (size_t level = 0; level == 0 || std::max(w, h) > kMostLeft; ++level) {
        w = (w + kBlock - 1) / kBlock;
        h = (h + kBlock - 1) / kBlock;
        if (sumTargets_.size() <= level) sumTargets_.emplace_back();
        ensureTarget(sumTargets_[level], w, h, {GL_RG32F}, false);
        sumTargets_[level]->bind();
        bindTexture(reduceProgram_, "u_logLuminance", 0, from);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        last = sumTargets_[level].get();
        from = last->color(0);
    }
    checkGl("CompositePass::logAverageLuminance");
    const std::vector<float> sums = last->readRG(0);
    double sum = 0, count = 0;
    for (size_t i = 0; i + 1 < sums.size(); i += 2) {
        sum += sums[i];
        count += sums[i + 1];
    }
    return count > 0 ? static_cast<float>(std::exp(sum / count)) : 1.0f;
}

RadiosityLookupPass::RadiosityLookupPass()
    : lookup_("fullscreen.vert", "radiosity_lookup.frag"),
      fill_("fullscreen.vert", "radiosity_lookup.frag", "#define TSIS_FILL 1\n") {
    glGenVertexArrays(1, &emptyVao_);
    glGenBuffers(1, &counter_);
    glBindBuffer(GL_ATOMIC_COUNTER_BUFFER, counter_);
    glBufferData(GL_ATOMIC_COUNTER_BUFFER, sizeof(GLuint), nullptr, GL_DYNAMIC_READ);
    glBindBuffer(GL_ATOMIC_COUNTER_BUFFER, 0);
    glGenQueries(1, &query_);
}

RadiosityLookupPass::~RadiosityLookupPass() {
    if (query_) glDeleteQueries(1, &query_);
    if (counter_) glDeleteBuffers(1, &counter_);
    if (emptyVao_) glDeleteVertexArrays(1, &emptyVao_);
}

void RadiosityLookupPass::setAtlas(const float* positions, uint64_t positionsKey,
                                   const float* radiosity, uint64_t radiosityKey, int resolution) {
    auto update = [&](std::unique_ptr<FloatTexture>& t, uint64_t& key, const float* data,
                      uint64_t newKey) {
        if (t && t->width() == resolution && key == newKey) return;
        if (!t || t->width() != resolution)
            t = std::make_unique<FloatTexture>(resolution, resolution);
        t->upload(data);
        key = newKey;
    };
    update(xyz_, xyzKey_, positions, positionsKey);
    update(b_, bKey_, radiosity, radiosityKey);
}

RadiosityLookupPass::Counts RadiosityLookupPass::run(const RenderTarget& frameGbuffer,
                                                     int uvAttachment, float maxMm) {
    TSIS_CHECK(xyz_ != nullptr && b_ != nullptr);
    ensureTarget(target_, frameGbuffer.width(), frameGbuffer.height(), {GL_RGBA32F}, true);
    target_->bind();
    copyDepth(frameGbuffer, *target_);
    const GLuint zero = 0;
    glBindBuffer(GL_ATOMIC_COUNTER_BUFFER, counter_);
    glBufferSubData(GL_ATOMIC_COUNTER_BUFFER, 0, sizeof zero, &zero);
    glBindBufferBase(GL_ATOMIC_COUNTER_BUFFER, 0, counter_);
    glBindVertexArray(emptyVao_);
    for (const ShaderProgram* p : {&lookup_, &fill_}) {
        p->use();
        bindTexture(*p, "u_position", 0, frameGbuffer.color(0));
        bindTexture(*p, "u_uv", 1, frameGbuffer.color(uvAttachment));
        bindTexture(*p, "u_atlasXyz", 2, xyz_->id());
        bindTexture(*p, "u_atlasB", 3, b_->id());
        p->set("u_maxMm2", maxMm * maxMm);
    }
    lookup_.use();
    glBeginQuery(GL_SAMPLES_PASSED, query_);
    drawFullScreenWhere(GL_GREATER);
    glEndQuery(GL_SAMPLES_PASSED);
    GLuint offAtlas = 0, covered = 0;
    glGetQueryObjectuiv(query_, GL_QUERY_RESULT, &covered);
    glGetBufferSubData(GL_ATOMIC_COUNTER_BUFFER, 0, sizeof offAtlas, &offAtlas);
    glBindBufferBase(GL_ATOMIC_COUNTER_BUFFER, 0, 0);
    glBindBuffer(GL_ATOMIC_COUNTER_BUFFER, 0);
    // The few pixels with no texel of their surface around, from their
    // neighbours: the pass reads the lookup's output it draws into, made
    // visible by the barrier (and never a texel it writes: the shader's rule).
    if (offAtlas > 0) {
        glTextureBarrier();
        fill_.use();
        bindTexture(fill_, "u_b", 4, target_->color(0));
        drawFullScreenWhere(GL_GREATER);
        bindTexture(fill_, "u_b", 4, 0);
    }
    checkGl("RadiosityLookupPass");
    return {static_cast<int>(covered), static_cast<int>(offAtlas)};
}

}  // namespace tsis
