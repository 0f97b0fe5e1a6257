#include "render/raster_passes.h"

#include <algorithm>
#include <cmath>
#include <glm/matrix.hpp>

#include "image/image_io.h"
#include "mesh/lod.h"
#include "mesh/uv_texels.h"
#include "physics/ggx.h"
#include "render/env_reflection.h"
#include "render/frame_keys.h"
#include "render/single_scatter.h"
#include "tsis_shared.h"
#include "util/hash.h"
#include "util/timer.h"

namespace tsis {

float logAverageLuminance(const std::vector<float>& rgba) {
    double sum = 0;
    size_t n = 0;
    for (size_t i = 0; i + 3 < rgba.size(); i += 4) {
        if (rgba[i + 3] <= 0) continue;
        double y = TSIS_LUMINANCE(rgba[i], rgba[i + 1], rgba[i + 2]);
        sum += std::log(1e-12 + std::max(0.0, y));
        ++n;
    }
    return n ? static_cast<float>(std::exp(sum / static_cast<double>(n))) : 1.0f;
}

float exposureScale(const RenderOptions& o, float lavg) {
    return o.autoExposure ? o.key / std::max(lavg, 1e-30f) : std::exp2(o.exposure);
}

namespace {

// Bilinear lookups (the reflection's tables), wrapping in s where `wrapS`
// (a lat-long map's longitude).
void filterLinear(const FloatTexture& t, bool wrapS) {
    glBindTexture(GL_TEXTURE_2D, t.id());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrapS ? GL_REPEAT : GL_CLAMP_TO_EDGE);
}

// Each medium's lobe roughness (its file's or --roughness) and the distinct
// ones in the order of first use: the prefiltered environment's layers.
struct MediumRoughness {
    std::vector<float> ofMedium, layers;
    std::vector<int> layerOf;  // per medium
};
MediumRoughness mediumRoughness(const FrameContext& ctx) {
    MediumRoughness r;
    const std::vector<ObjectMaterial>& files = ctx.scene->objectMaterials;
    for (size_t m = 0; m < ctx.media->etaOfMedium.size(); ++m) {
        const uint32_t id = ctx.media->fileMaterialOfMedium(m);
        const double file = id < files.size() ? files[id].roughness : -1.0;
        const auto v = static_cast<float>(surfaceRoughness(ctx.options->roughness, file));
        auto it = std::find(r.layers.begin(), r.layers.end(), v);
        if (it == r.layers.end()) it = r.layers.insert(r.layers.end(), v);
        r.ofMedium.push_back(v);
        r.layerOf.push_back(static_cast<int>(it - r.layers.begin()));
    }
    return r;
}

// The views (of `count` lights) whose key changed, keyOf(i) against keys[i]:
// each updated (update(i)) and its key kept, so that a frame that moves one
// light of several redraws that one.
template <typename KeyOf, typename Update>
std::vector<size_t> changedViews(size_t count, std::vector<uint64_t>& keys, const KeyOf& keyOf,
                                 const Update& update) {
    keys.resize(count, 0);
    std::vector<size_t> changed;
    for (size_t i = 0; i < count; ++i) {
        const uint64_t key = keyOf(i);
        if (key == keys[i]) continue;
        update(i);
        keys[i] = key;
        changed.push_back(i);
    }
    return changed;
}

// The camera's passes may cull back faces: the mesh is closed and outward and
// the eye outside its bounding sphere (so outside the mesh).
bool cullsBackFaces(const FrameContext& ctx, const GpuMesh& mesh) {
    return mesh.closedOutward() && glm::length(ctx.eye) > ctx.boundingRadius;
}

}  // namespace

void RasterPasses::setGlWorker(GlWorker* worker) {
    lightPass_.setWorker(worker);
    scatterPass_.setWorker(worker);
    // The samples' G-buffer (aa × the size) goes to the worker for any mesh:
    // it then overlaps the frame's G-buffer and the CL work of a camera move
    // (default scene 28.4 -> 27.3 ms, 5 rounds interleaved; cow -0.3), where
    // a light view of a small mesh on it cost more than it saved.
    sampleGbufferPass_.setWorker(worker, 0);
}

// What the composite's samples' G-buffer shows: the mesh, the camera, the
// size and --aa.
uint64_t RasterPasses::samplesKey(const FrameContext& ctx) const {
    Hasher key;
    key.add(meshHash_).add(ctx.width).add(ctx.height).add(ctx.options->aa);
    key.add(ctx.viewProj);
    return key.digest();
}

void RasterPasses::startSamples(const FrameContext& ctx, const GpuMesh& mesh,
                                const GlLights& lights) {
    const int aa = ctx.options->aa;
    sampleGbufferPass_.setEye(ctx.eye);
    sampleGbufferPass_.start(mesh, *lights.views, *lights.shadows, materials_, ctx.viewProj,
                             ctx.width * aa, ctx.height * aa, 0, 0, cullsBackFaces(ctx, mesh));
}

void RasterPasses::uploadMesh(const Mesh& mesh, uint64_t hash) {
    if (gpuMesh_ && hash == meshHash_) return;
    gpuMesh_ = std::make_unique<GpuMesh>(mesh);
    meshHash_ = hash;
}

const GpuMesh* RasterPasses::depthMesh(const Mesh& mesh, int budget, FrameStats& stats) {
    const bool coarser = budget > 0 && mesh.triangles.size() > 2 * size_t(budget);
    if (lodKey_ != std::make_pair(meshHash_, budget)) {
        lodMesh_.reset();
        lodMm_ = 0;
        lodTriangles_ = 0;
        if (coarser) {
            const MeshLod lod = clusterLod(mesh, lodCellForBudget(mesh, size_t(budget)));
            lodMesh_ = std::make_unique<GpuMesh>(lod.mesh, GpuMesh::PositionsOnly{});
            lodMm_ = lod.deviationMm;
            lodTriangles_ = lod.mesh.triangles.size();
        }
        lodKey_ = {meshHash_, budget};
    }
    stats.set("light_lod_triangles", static_cast<double>(lodTriangles_));
    stats.set("light_lod_mm", lodMm_);
    return lodMesh_.get();
}

RasterHandles RasterPasses::addPasses(FrameGraph& graph, const FrameContext& ctx, uint64_t meshHash,
                                      uint64_t lighting, FrameGraphId<LightMapsCl> lightMapsCl,
                                      FrameGraphId<CameraBuffersCl> gbufferCl) {
    RasterHandles h;
    h.mesh = graph.create<const GpuMesh*>("mesh", nullptr);
    h.lights = graph.create<GlLights>("light_views");
    h.geometryAtlas = graph.create<GlTarget>("geometry_atlas");
    h.fluxAtlas = graph.create<GlTarget>("flux_atlas");
    h.residualFluxAtlas = graph.create<GlTarget>("residual_flux_atlas");
    h.gbuffer = graph.create<GlTarget>("gbuffer");
    // η, the exit scale and the lobe of every medium (render/scene_media.h).
    std::vector<MediumSurface> media;
    const MediumRoughness roughness = mediumRoughness(ctx);
    for (size_t m = 0; m < ctx.media->etaOfMedium.size(); ++m) {
        const float eta = ctx.media->etaOfMedium[m];
        media.push_back({eta, static_cast<float>(exitScale(ctx.options->exit, eta)),
                         static_cast<float>(ggxAlpha(roughness.ofMedium[m])),
                         roughness.layerOf[m]});
    }
    Hasher etas;
    for (const MediumSurface& m : media) etas.add(m.eta);
    const uint64_t eta = etas.digest();
    h.samples = graph.create<GlTarget>("composite_samples");

    graph.addPass(
        "upload_mesh", [&](FrameGraph::Builder& b) { b.write(h.mesh); },
        [this, &ctx, meshHash, h, media](FrameGraph::Resources& res) {
            materials_.updateMedia(media);
            materials_.updateAlbedo(ctx.albedo->factor, ctx.atlasResolution, ctx.albedo->key);
            materials_.updateSurface(ctx.surface->normal, ctx.surface->roughness,
                                     ctx.atlasResolution, ctx.surface->key);
            uploadMesh(ctx.scene->mesh, meshHash);
            res.write(h.mesh) = gpuMesh_.get();
        });
    graph.addPass(
        "gl_light_view",
        [&](FrameGraph::Builder& b) {
            b.read(h.mesh);
            b.write(h.lights);
        },
        [this, &graph, &ctx, lighting, lightMapsCl, eta, h](FrameGraph::Resources& res) {
            // Flux and position maps only when a light-view method reads them.
            const bool maps = graph.isRead(lightMapsCl);
            // Each view is redrawn only when its own key changed.
            const std::vector<Light>& lights = ctx.scene->lights;
            // A big mesh's depth-only views from its coarser copy.
            const int lod = ctx.options->lightLodTriangles;
            const GpuMesh* depth = maps ? nullptr : depthMesh(ctx.scene->mesh, lod, res.stats());
            const uint64_t shading =
                Hasher(eta).add(ctx.albedo->key).add(ctx.surface->key).digest();
            lights_.resize(lights.size());
            const std::vector<size_t> changed = changedViews(
                lights.size(), viewKeys_,
                [&](size_t i) {
                    return lightViewKey(lights[i], meshHash_, ctx.lightResolution, maps, shading,
                                        lod);
                },
                [&](size_t i) {
                    updateLightView(lights_[i], lights[i], ctx.boundingRadius, ctx.lightResolution,
                                    maps);
                });
            size_t onWorker = 0;
            if (!changed.empty()) {
                onWorker = lightPass_.run(*res.read(h.mesh), lights_, materials_, changed, depth);
                glFinish();
                ++lightsVersion_;
            }
            lightViewKey_ = lighting;
            res.stats().set("light_views_drawn", static_cast<double>(changed.size()));
            res.stats().set("light_views_on_worker", static_cast<double>(onWorker));
            res.stats().set("light_views_cull",
                            (depth ? depth : res.read(h.mesh))->closedOutward() ? 1.0 : 0.0);
            res.write(h.lights) = {&lights_, &lightPass_.shadows(), lightsVersion_};
        });
    if (addsSingleScatter(*ctx.options)) {
        h.scatterViews = graph.create<GlLights>("scatter_views");
        graph.addPass(
            "gl_scatter_views",
            [&](FrameGraph::Builder& b) {
                b.read(h.mesh);
                b.read(h.lights);
                b.write(h.scatterViews);
            },
            [this, &ctx, h](FrameGraph::Resources& res) {
                // From the shadow maps where they hold what a draw would:
                // one medium, no normal map, the mesh's own depth, and only
                // faces towards the light (a closed, outward mesh).
                const bool derived = ctx.media->etaOfMedium.size() == 1 &&
                                     ctx.surface->normal.empty() && !lodMesh_ &&
                                     res.read(h.mesh)->closedOutward();
                // As the light views: each redrawn when its own key changed.
                const std::vector<Light>& lights = ctx.scene->lights;
                const int resolution = scatterViewResolution(ctx);
                const uint64_t source =
                    Hasher(ctx.surface->key).add(derived ? ctx.lightResolution : 0).digest();
                scatterViews_.resize(lights.size());
                const std::vector<size_t> changed = changedViews(
                    lights.size(), scatterKeys_,
                    [&](size_t i) {
                        return lightViewKey(lights[i], meshHash_, resolution, true, source, 0);
                    },
                    [&](size_t i) {
                        updateScatterView(scatterViews_[i], lights[i], ctx.boundingRadius,
                                          resolution, !derived);
                    });
                if (!changed.empty()) {
                    if (derived)
                        scatterPass_.copyDepth(*res.read(h.lights).shadows, scatterViews_, changed);
                    else
                        scatterPass_.run(*res.read(h.mesh), scatterViews_, materials_, changed);
                    glFinish();
                    ++scatterVersion_;
                }
                res.stats().set("scatter_view_resolution", resolution);
                res.stats().set("scatter_views_derived", derived ? 1 : 0);
                res.write(h.scatterViews) = {&scatterViews_, nullptr, scatterVersion_, derived};
            });
    }
    // The geometry atlas depends on the mesh and resolution only: made once.
    graph.addPass(
        "gl_geometry_atlas",
        [&](FrameGraph::Builder& b) {
            b.read(h.mesh);
            b.write(h.geometryAtlas);
        },
        [this, &ctx, h](FrameGraph::Resources& res) {
            if (geometryKey_ != std::make_pair(meshHash_, ctx.atlasResolution)) {
                // Each chart's texels sum to its area at this resolution.
                gpuMesh_->setAreaRatios(texelAreaRatios(ctx.scene->mesh, ctx.atlasResolution));
                geometryAtlasPass_.run(*gpuMesh_, ctx.atlasResolution);
                glFinish();
                geometryKey_ = {meshHash_, ctx.atlasResolution};
                ++geometryVersion_;
            }
            res.write(h.geometryAtlas) = {&geometryAtlasPass_.target(), geometryVersion_};
        });
    // The flux atlas (the lights' E and the environment's residual) and, for
    // the texture-space run that adds the residual to a light-view method
    // (Renderer::render), the same pass without the lights: by linearity the
    // two runs' sum sees the whole atlas.
    auto fluxPass = [&](const char* name, FrameGraphId<GlTarget> out, FluxAtlasPass& pass,
                        uint64_t& key, uint64_t& version, bool withLights) {
        graph.addPass(
            name,
            [&](FrameGraph::Builder& b) {
                b.read(h.geometryAtlas);
                b.read(h.lights);
                b.write(out);
            },
            [this, &ctx, lighting, h, out, &pass, &key, &version,
             withLights](FrameGraph::Resources& res) {
                if (key != lighting) {
                    static const std::vector<LightView> none;
                    const GlLights& lights = res.read(h.lights);
                    const RenderTarget& geometry = *res.read(h.geometryAtlas).target;
                    pass.run(geometry, withLights ? *lights.views : none, *lights.shadows,
                             materials_, environmentTexture(ctx, geometry, res.stats()));
                    glFinish();
                    key = lighting;
                    ++version;
                }
                res.write(out) = {&pass.target(), version};
            });
    };
    fluxPass("gl_flux_atlas", h.fluxAtlas, fluxAtlasPass_, fluxKey_, fluxVersion_, true);
    if (ctx.scene->env)
        fluxPass("gl_residual_flux_atlas", h.residualFluxAtlas, residualFluxPass_, residualKey_,
                 residualVersion_, false);
    graph.addPass(
        "gl_gbuffer",
        [&](FrameGraph::Builder& b) {
            b.read(h.mesh);
            b.read(h.lights);
            // The environment's residual per atlas texel, for the irradiance.
            if (ctx.scene->env) b.read(h.geometryAtlas);
            b.write(h.gbuffer);
            b.write(ctx.pointUvs);
        },
        [this, &graph, &ctx, eta, gbufferCl, lighting, h](FrameGraph::Resources& res) {
            // Redrawn only when what it shows changed: a frame that only moves
            // the light keeps it (irradiance, for image-space methods, moves
            // with the lighting).
            const bool irradiance = graph.isRead(gbufferCl);
            const unsigned outputs = (irradiance ? GBufferPass::kIrradiance : 0u) |
                                     (graph.isRead(ctx.pointUvs) ? GBufferPass::kUv : 0u);
            Hasher key;
            key.add(meshHash_).add(ctx.width).add(ctx.height).add(outputs).add(ctx.albedo->key);
            key.add(ctx.surface->key);
            key.add(ctx.viewProj);
            if (irradiance) key.add(lighting).add(eta);
            // The composite's samples' G-buffer, when it is to be drawn too,
            // on the worker's thread meanwhile (gl_composite_samples waits).
            const GlLights& lights = res.read(h.lights);
            const GpuMesh& mesh = *res.read(h.mesh);
            const uint64_t samples = samplesKey(ctx);
            if (sampleGbufferPass_.onWorker(mesh, cullsBackFaces(ctx, mesh)) &&
                ctx.options->aa > 1 && graph.isRead(h.samples) && samples != samplesKey_) {
                startSamples(ctx, mesh, lights);
                samplesStarted_ = samples;
            }
            if (key.digest() != gbufferKey_) {
                const GLuint env =
                    irradiance && ctx.scene->env
                        ? environmentTexture(ctx, *res.read(h.geometryAtlas).target, res.stats())
                        : 0;
                gbufferPass_.setEye(ctx.eye);
                gbufferPass_.run(mesh, *lights.views, *lights.shadows, materials_, ctx.viewProj,
                                 ctx.width, ctx.height, outputs, env, cullsBackFaces(ctx, mesh));
                glFinish();
                gbufferKey_ = key.digest();
                ++gbufferVersion_;
            }
            res.write(h.gbuffer) = {&gbufferPass_.target(), gbufferVersion_};
        });
    // The composite's geometry at --aa × the size: rasterised again (cheap),
    // while B stays at the frame's pixels (the methods' cost).
    graph.addPass(
        "gl_composite_samples",
        [&](FrameGraph::Builder& b) {
            b.read(h.mesh);
            b.read(h.lights);
            b.read(h.gbuffer);
            b.write(h.samples);
        },
        [this, &ctx, h](FrameGraph::Resources& res) {
            res.stats().set("samples_on_worker", 0.0);
            const int aa = ctx.options->aa;
            if (aa == 1) {
                res.write(h.samples) = res.read(h.gbuffer);
                return;
            }
            const uint64_t key = samplesKey(ctx);
            if (key != samplesKey_) {
                // Started by gl_gbuffer on the worker's thread, or drawn now.
                const bool started = samplesStarted_ == key;
                res.stats().set("samples_on_worker", started ? 1.0 : 0.0);
                if (!started) startSamples(ctx, *res.read(h.mesh), res.read(h.lights));
                sampleGbufferPass_.finish();
                glFinish();
                samplesStarted_ = 0;
                samplesKey_ = key;
                ++samplesVersion_;
            }
            res.write(h.samples) = {&sampleGbufferPass_.target(), samplesVersion_};
        });
    return h;
}

GLuint RasterPasses::environmentTexture(const FrameContext& ctx, const RenderTarget& geometry,
                                        FrameStats& stats) {
    const Scene& scene = *ctx.scene;
    if (!scene.env) return 0;
    // The transfer: once per mesh, atlas resolution and η (rays per texel).
    const uint64_t key =
        Hasher(geometryKey_.first).add(geometryKey_.second).add(scene.material.eta).digest();
    Timer t;
    if (key != envTransfer_.key())
        envTransfer_.update(key, scene.mesh, geometry.width(), scene.material.eta,
                            geometry.readRGBA(0), geometry.readRGBA(1));
    stats.set("env_transfer_ms", t.ms());
    stats.set("env_transfer_texels", static_cast<double>(envTransfer_.tracedTexels()));
    // Each frame whose lighting changed: the turned map's harmonics, one dot
    // a texel (once a lighting, though the flux atlas and the G-buffer read it).
    const uint64_t lighting = Hasher(key)
                                  .add(scene.env.map->hash)
                                  .add(scene.env.intensity)
                                  .add(scene.env.rotateDegrees)
                                  .digest();
    if (envTexture_ && lighting == envTextureKey_) return envTexture_->id();
    envTextureKey_ = lighting;
    Timer e;
    const std::vector<float> irradiance = envTransfer_.irradiance(scene.env);
    if (!envTexture_ || envTexture_->width() != geometry.width())
        envTexture_ = std::make_unique<FloatTexture>(geometry.width(), geometry.height());
    envTexture_->upload(irradiance.data());
    stats.set("env_irradiance_ms", e.ms());
    return envTexture_->id();
}

EnvReflectionTextures RasterPasses::environmentReflection(const FrameContext& ctx,
                                                          FrameStats& stats) {
    const Environment& env = ctx.scene->env;
    const RenderOptions& o = *ctx.options;
    if (!env || !o.specular) return {};
    Timer t;
    // One band of rows per distinct roughness, stacked (layer 0 on top), then
    // with a roughness map the ladder's steps; the albedo table likewise.
    const MediumRoughness roughness = mediumRoughness(ctx);
    const bool ladder = !ctx.surface->roughness.empty();
    std::vector<float> layerRoughness = roughness.layers;
    const std::vector<float>& etas = ctx.media->etaOfMedium;
    std::vector<float> rowEta = etas, rowRoughness = roughness.ofMedium;
    if (ladder) {
        for (int k = 0; k < kRoughnessLadderSteps; ++k)
            layerRoughness.push_back(static_cast<float>(ladderRoughness(k)));
        for (float eta : etas)
            for (int k = 0; k < kRoughnessLadderSteps; ++k) {
                rowEta.push_back(eta);
                rowRoughness.push_back(static_cast<float>(ladderRoughness(k)));
            }
    }
    Hasher mapHash(env.map->hash);
    for (float r : layerRoughness) mapHash.add(r);
    const uint64_t mapKey = mapHash.digest();
    const int w = kReflectionMapWidth;
    const auto layers = static_cast<int>(layerRoughness.size());
    if (!envPrefiltered_ || mapKey != envPrefilteredKey_) {
        if (!envPrefiltered_ || envPrefiltered_->height() != layers * w / 2) {
            envPrefiltered_ = std::make_unique<FloatTexture>(w, layers * w / 2);
            filterLinear(*envPrefiltered_, true);
        }
        if (envBandsOf_ != env.map->hash) envBands_.clear(), envBandsOf_ = env.map->hash;
        std::vector<float> bands;
        for (float r : layerRoughness) {
            auto band = envBands_.find(r);
            if (band == envBands_.end())
                band = envBands_.emplace(r, prefilterReflection(*env.map, r, w)).first;
            bands.insert(bands.end(), band->second.begin(), band->second.end());
        }
        envPrefiltered_->upload(bands.data());
        envPrefilteredKey_ = mapKey;
    }
    Hasher albedoKey;
    for (float r : rowRoughness) albedoKey.add(r);
    for (float eta : rowEta) albedoKey.add(eta);
    if (!envAlbedo_ || albedoKey.digest() != envAlbedoKey_) {
        const int rows = static_cast<int>(rowEta.size());
        if (!envAlbedo_ || envAlbedo_->height() != rows) {
            envAlbedo_ = std::make_unique<FloatTexture>(kReflectionAlbedoEntries, rows);
            filterLinear(*envAlbedo_, false);
        }
        envAlbedo_->upload(reflectionAlbedoTable(rowEta, rowRoughness).data());
        envAlbedoKey_ = albedoKey.digest();
    }
    stats.set("env_reflection_ms", t.ms());
    EnvReflectionTextures out{envPrefiltered_->id(), envAlbedo_->id(), layers,
                              glm::transpose(glm::mat3(env.toWorld())),
                              static_cast<float>(env.intensity)};
    if (ladder) {
        out.ladderSteps = kRoughnessLadderSteps;
        out.ladderLayer = static_cast<int>(roughness.layers.size());
        out.ladderRow = static_cast<int>(etas.size());
        out.ladderMin = static_cast<float>(kMinRoughness);
    }
    return out;
}

DisplayBackground RasterPasses::displayBackground(const FrameContext& ctx) {
    DisplayBackground b;
    const Environment& env = ctx.scene->env;
    b.mode = static_cast<int>(ctx.options->background);
    if (ctx.options->background != Background::Env || !env) return b;
    if (!envBackground_ || env.map->hash != envBackgroundKey_) {
        int w = 0, h = 0;
        const std::vector<float> rgba = wholeMapRgba(*env.map, kBackgroundMapWidth, w, h);
        envBackground_ = std::make_unique<FloatTexture>(w, h);
        filterLinear(*envBackground_, true);
        envBackground_->upload(rgba.data());
        envBackgroundKey_ = env.map->hash;
    }
    b.envMap = envBackground_->id();
    b.inverseViewProj = glm::inverse(ctx.viewProj);
    b.worldToMap = glm::transpose(glm::mat3(env.toWorld()));
    b.scale = static_cast<float>(env.intensity);
    return b;
}

FrameGraphId<RadiosityImage> RasterPasses::addRadiosityLookup(FrameGraph& graph,
                                                              const FrameContext& ctx,
                                                              const RasterHandles& gl,
                                                              const AtlasRadiosity& copy) {
    const FrameGraphId<RadiosityImage> image = graph.create<RadiosityImage>("radiosity");
    graph.addPass(
        "gl_radiosity_lookup",
        [&](FrameGraph::Builder& b) {
            b.read(gl.gbuffer);
            b.read(ctx.pointUvs);
            b.write(image);
        },
        [this, &copy, gl, image](FrameGraph::Resources& res) {
            Timer upload;
            radiosityLookupPass_.setAtlas(copy.positions->data(), copy.positionsKey,
                                          copy.radiosity->data(), copy.radiosityKey,
                                          copy.resolution);
            res.stats().set("radiosity_atlas_upload_ms", upload.ms());
            const RenderTarget& gbuffer = *res.read(gl.gbuffer).target;
            const RadiosityLookupPass::Counts n =
                radiosityLookupPass_.run(gbuffer, gbuffer.colorCount() - 1, copy.maxMm);
            glFinish();
            RadiosityImage& out = res.write(image);
            out.texture = radiosityLookupPass_.texture();
            out.covered = n.covered;
            res.stats().set("pyramid_from_atlas", 1.0);
            res.stats().set("pyramid_filled_off_atlas", static_cast<double>(n.offAtlas));
        });
    return image;
}

FrameGraphId<FrameImage> RasterPasses::addComposite(FrameGraph& graph, const FrameContext& ctx,
                                                    const RasterHandles& gl,
                                                    FrameGraphId<RadiosityImage> radiosity) {
    const FrameGraphId<FrameImage> image = graph.create<FrameImage>("image");
    graph.addPass(
        "composite",
        [&](FrameGraph::Builder& b) {
            b.read(radiosity);
            b.read(gl.gbuffer);
            b.read(gl.samples);
            b.read(gl.lights);
            b.write(image);
        },
        [this, &ctx, gl, radiosity, image](FrameGraph::Resources& res) {
            const RenderOptions& o = *ctx.options;
            const GlLights& lights = res.read(gl.lights);
            FrameImage& out = res.write(image);
            const GlTarget& gbuffer = res.read(gl.gbuffer);
            // The frame's radiance as floats only for the AOVs; the
            // log-average from the GPU's sums, before the tone curve only
            // where it sets the exposure. Else the display straight from
            // the radiance pass.
            const bool direct = !o.keepAovs && !o.autoExposure;
            if (direct) out.exposureScale = exposureScale(o, out.lavg);
            const RadiosityImage& b = res.read(radiosity);
            compositePass_.setDisplay(static_cast<int>(o.tone), displayBackground(ctx));
            compositePass_.setFxaa(o.aaMethod == AaMethod::Fxaa);
            compositePass_.radiance(b.texture ? nullptr : b.rgba.data(), b.texture, *gbuffer.target,
                                    gbuffer.version, *res.read(gl.samples).target, o.aa,
                                    *lights.views, *lights.shadows, ctx.eye, materials_, o.specular,
                                    environmentReflection(ctx, res.stats()),
                                    direct ? std::optional(out.exposureScale) : std::nullopt);
            if (!direct) {
                compositePass_.resolve();
                if (o.keepAovs) out.radiance = compositePass_.frameRadiance();
                if (o.autoExposure) out.lavg = compositePass_.logAverageLuminance();
                out.exposureScale = exposureScale(o, out.lavg);
                compositePass_.toneMap(out.exposureScale);
            }
            if (!o.autoExposure) out.lavg = compositePass_.logAverageLuminance();
            if (o.aaMethod == AaMethod::Fxaa) compositePass_.fxaa();
            const std::vector<uint8_t> rgba = compositePass_.colorTarget().readRGBA8(0);
            out.rgb8 = fromGlRgba(rgba, ctx.width, ctx.height, 3);
            if (o.background == Background::Transparent)
                out.alpha8 = fromGlRgba(rgba, ctx.width, ctx.height, 1, 3);
        });
    return image;
}

}  // namespace tsis
