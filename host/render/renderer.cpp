#include "render/renderer.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>

#include "physics/dipole.h"
#include "render/energy_target.h"
#include "render/frame_keys.h"
#include "util/error.h"
#include "util/timer.h"

namespace tsis {

namespace {

// GL RGBA (row 0 = bottom) → ImageF with `channels` of them, row 0 = top.
ImageF toImage(const std::vector<float>& rgba, int w, int h, int channels, int first = 0) {
    return ImageF{w, h, channels, fromGlRgba(rgba, w, h, channels, first)};
}

FrameContext frameContext(const Scene& scene, uint64_t meshKey, const RenderOptions& opt,
                          ClRuntime& cl, FrameStats& stats) {
    FrameContext ctx;
    ctx.scene = &scene;
    ctx.meshKey = meshKey;
    ctx.material = &scene.material;
    ctx.options = &opt;
    ctx.cl = &cl;
    ctx.stats = &stats;
    ctx.boundingRadius = boundingRadius(scene.mesh);
    ctx.atlasResolution = opt.atlasResolution;
    ctx.width = opt.width;
    ctx.height = opt.height;
    ctx.lightResolution = opt.lightResolution;
    ctx.viewProj = cameraViewProj(scene.camera, static_cast<float>(opt.width) / opt.height,
                                  ctx.boundingRadius);
    ctx.eye = scene.camera.eye;
    return ctx;
}

// The context of the method's run for `material`: its profile, scaled by
// --energy (the object's V/S).
FrameContext materialContext(const FrameContext& base, const Material& material) {
    FrameContext ctx = base;
    ctx.material = &material;
    const Mesh& mesh = base.scene->mesh;
    if (base.options->energy == EnergyTarget::Object)
        ctx.profileScale = energyScale(material, base.options->profile,
                                       mesh.enclosedVolume() / mesh.surfaceArea());
    return ctx;
}

// The AOVs of RenderOptions::keepAovs, from the frame's resources.
void collectAovs(FrameGraph& graph, const RasterHandles& gl, FrameGraphId<RadiosityImage> radiosity,
                 FrameGraphId<FrameImage> image, const FrameContext& ctx, FrameResult& result) {
    const int w = ctx.width, h = ctx.height, res = ctx.atlasResolution;
    result.radiosity = toImage(graph.get(radiosity).rgba, w, h, 3);
    // Transparent: the alpha channel too (the fraction of the pixel covered).
    result.radiance = toImage(graph.get(image).radiance, w, h,
                              ctx.options->background == Background::Transparent ? 4 : 3);
    const RenderTarget& gbuffer = *graph.get(gl.gbuffer).target;
    const std::vector<float> position = gbuffer.readRGBA(0);
    result.position = toImage(position, w, h, 3);
    result.coverage = toImage(position, w, h, 1, 3);  // w: the medium tag, 0 where uncovered
    result.medium = result.coverage;                  // the tag 1 + medium, 0 where uncovered
    for (float& m : result.medium.pixels) m -= 1.0f;
    for (float& c : result.coverage.pixels) c = c > 0 ? 1.0f : 0.0f;
    result.normal = toImage(gbuffer.readRGBA(1), w, h, 3);
    // The flux atlas, when this frame's method used it.
    if (const RenderTarget* flux = graph.get(gl.fluxAtlas).target)
        result.fluxAtlas = toImage(flux->readRGBA(0), res, res, 3);
}

void recordFrame(FrameStats& stats, const RenderOptions& opt, const Scene& scene,
                 const FrameGraph& graph, int coveredPixels) {
    stats.totalRdEvaluations();
    stats.set("method", opt.method);
    stats.set("width", opt.width);
    stats.set("height", opt.height);
    stats.set("atlas_resolution", opt.atlasResolution);
    stats.set("light_resolution", opt.lightResolution);
    stats.set("samples", opt.samples);
    stats.set("covered_pixels", coveredPixels);
    stats.set("triangles", static_cast<double>(scene.mesh.triangles.size()));
    Json passes = Json::array();
    for (const std::string& p : graph.executed()) passes.push_back(p);
    stats.set("passes", passes);
    stats.set("graph", graph.describe());
}

// The worker where a shared context is made (every Mesa platform here): the
// frame does without one where not, and with TSIS_GL_WORKER=0 (measuring).
std::unique_ptr<GlWorker> makeGlWorker(const GlContext& gl) {
    const char* env = std::getenv("TSIS_GL_WORKER");
    if (env && std::string(env) == "0") return nullptr;
    try {
        return std::make_unique<GlWorker>(gl);
    } catch (const Error&) {
        return nullptr;
    }
}

// The process whose threads started OpenCL and GL (the first renderer's):
// PoCL's and Mesa's worker threads are not copied by fork(), so a child
// waits on them forever, with its parent's renderers or a new one.
std::atomic<pid_t> gStartedIn{0};

pid_t startedIn() {
    pid_t expected = 0;
    const pid_t self = ::getpid();
    if (gStartedIn.compare_exchange_strong(expected, self)) return self;
    if (expected != self)
        fail("no renderer in a child forked after one was made (in process ", expected,
             "): OpenCL and GL cannot start again without their threads, which fork() does not "
             "copy; fork before making any renderer, or use multiprocessing's 'spawn' start "
             "method");
    return self;
}

}  // namespace

Renderer::Renderer(const std::string& clDevice, const std::string& gl)
    : pid_(startedIn()),
      gl_(parseGlChoice(gl)),
      glWorker_(makeGlWorker(gl_)),
      cl_(clDevice),
      sharing_(chooseGlClSharing({gl_.platform(), gl_.vendor(), gl_.renderer()},
                                 clSharingSide(cl_.device()))) {
    raster_.setGlWorker(glWorker_.get());
}

bool Renderer::forkedAway() const {
    return ::getpid() != pid_;
}

void Renderer::forgetAfterAbort() {
    // A task the worker still draws may use the frame's resources.
    if (glWorker_) {
        try {
            glWorker_->wait();
        } catch (const std::exception&) {  // the frame's error, already on its way
        }
    }
    cl_.queue().finish();
    // A pass may have stopped between making a result and recording its key.
    raster_.invalidateLighting();
    methods_.clear();
    singleScatter_.reset();
    lastView_ = 0;
}

bool Renderer::backgroundFitReady() const {
    return transport_ && transport_->backgroundFitReady();
}

bool Renderer::prepareCameraMoves(const Scene& scene, const RenderOptions& options) {
    // With AOVs kept the camera moves read the copy on the CL side, which
    // makes it as fast as the GL side's lookup does not: nothing to gain.
    if (options.method != "pyramid" || options.pyramidCache != PyramidCache::Camera ||
        options.progressive || options.keepAovs)
        return false;
    // The same view and lighting with the copy always read: it is made (or
    // found current) for this lighting; the frame itself is not shown.
    RenderOptions copy = options;
    copy.pyramidCache = PyramidCache::Texture;
    render(scene, copy);
    // With the object's transport, once more: that frame reads the copy on
    // the GL side, so the copy with the correction in it is made here too
    // (10–12 ms), not in the first camera move.
    if (addsTransport(options)) render(scene, copy);
    return true;
}

// The passes free their GL objects in this renderer's context, whichever
// renderer of the thread drew last.
Renderer::~Renderer() {
    try {
        gl_.makeCurrent();
    } catch (const Error&) {  // a lost context: nothing to free it in
    }
}

Method& Renderer::method(const std::string& name, size_t slot, const char* role) {
    // One instance per material slot and role: each keeps the tables of its
    // own profile.
    const std::string key = concat(name, role, "#", slot);
    auto it = methods_.find(key);
    if (it == methods_.end()) it = methods_.emplace(key, makeMethod(name, cl_)).first;
    return *it->second;
}

const AlbedoAtlas& Renderer::albedoAtlas(const Scene& scene, const SceneMedia& media,
                                         const RenderOptions& opt, uint64_t meshKey) {
    Hasher h(meshKey);
    hashMaterials(h, scene);
    const uint64_t key = h.add(opt.atlasResolution).add(opt.profile).digest();
    if (key != albedoOf_) {
        albedo_ = bakeAlbedoAtlas(scene, media, opt.atlasResolution, opt.profile);
        albedoOf_ = key;
    }
    return albedo_;
}

const SurfaceAtlas& Renderer::surfaceAtlas(const Scene& scene, const Media& media,
                                           const RenderOptions& opt, uint64_t meshKey) {
    const bool fileRoughness = opt.roughness < 0;
    Hasher h(meshKey);
    h.add(opt.atlasResolution).add(fileRoughness);
    for (const ObjectMaterial& o : scene.objectMaterials) {
        h.add(o.normalScale).add(o.roughness).add(o.roughnessChannel);
        for (const auto& map : {o.normalMap, o.roughnessMap})
            if (map) h.add(map->name).add(map->image.width).add(map->image.height);
    }
    if (h.digest() != surfaceOf_) {
        surface_ = bakeSurfaceAtlas(scene, media, opt.atlasResolution, fileRoughness);
        surfaceOf_ = h.digest();
    }
    return surface_;
}

const SceneMedia& Renderer::media(const Scene& scene, uint64_t meshKey) {
    // The weld once per mesh; the slots again only when a material changed
    // (not every frame: SceneMedia holds a per-vertex table).
    Hasher h(meshKey);
    hashMaterials(h, scene);
    const uint64_t key = h.digest();
    if (!media_ || key != mediaOf_) {
        media_ = std::make_unique<SceneMedia>(sceneMedia(scene, findMedia(scene.mesh)));
        mediaOf_ = key;
    }
    return *media_;
}

int autoLightResolution(const Scene& scene) {
    // Shadow edges in B are blurred over the shortest diffusion length 1/σtr;
    // on objects many of those across, the 1024² maps' texels show (measured:
    // ChineseDragon-10kv, ketchup 50 mm, 2.3% against the reference at 1024²,
    // 1.1% at 2048²).
    double sigmaTr = 0;
    auto widen = [&](const Material& m) {
        const glm::dvec3 tr = Dipole(m).sigmaTr();
        sigmaTr = std::max({sigmaTr, tr.x, tr.y, tr.z});
    };
    widen(scene.material);
    for (const ObjectMaterial& o : scene.objectMaterials) widen(o.medium);
    const double across = 2.0 * boundingRadius(scene.mesh) * sigmaTr;
    return across > 100.0 ? 2048 : 1024;
}

int autoAtlasResolution(const Scene& scene, double surfaceAreaMm2) {
    double mfp = std::numeric_limits<double>::infinity();
    bool maps = false;
    auto shorten = [&](const Material& m) {
        const glm::dvec3 t = m.sigmaSPrime + m.sigmaA;
        mfp = std::min(mfp, 1.0 / std::max({t.x, t.y, t.z}));
    };
    shorten(scene.material);
    for (const ObjectMaterial& o : scene.objectMaterials) {
        shorten(o.medium);
        for (const MfpStep& s : o.mfpSteps) shorten(s.medium);
        maps = maps || o.texture || o.normalMap || o.roughnessMap || o.mfpMap;
    }
    if (maps) return kAtlasPackResolution;
    // Measured against the reference (docs/guide/performance.md): 1/8 keeps
    // every 10 mm marble scene of the table within 1 %, and sends bunny00
    // and cow in skin1 at 30 mm (1/6–1/7: 0.5 → 1.3 %) to 512².
    constexpr int kSmall = 256;
    return std::sqrt(surfaceAreaMm2) / kSmall <= mfp / 8.0 ? kSmall : kAtlasPackResolution;
}

double Renderer::surfaceArea(const Mesh& mesh, uint64_t meshKey) {
    if (meshKey != areaOf_) {
        area_ = mesh.surfaceArea();
        areaOf_ = meshKey;
    }
    return area_;
}

const AtlasRadiosity* Renderer::atlasRadiosity(const Scene& scene, const RenderOptions& opt,
                                               const FrameContext& ctx, bool residual) {
    const SceneMedia& sm = *ctx.media;
    if (sm.slots() != 1 || residual || opt.progressive || addsSingleScatter(opt) || opt.keepAovs ||
        !ctx.albedo->empty() || !raster_.lightingCurrent(ctx.lighting))
        return nullptr;
    const AtlasRadiosity* copy =
        method(opt.method, 0).atlasRadiosity(materialContext(ctx, sm.slotMedium(scene, 0)));
    // With the object's transport, the copy with its correction (when the
    // last frame made it for this lighting).
    if (!copy || !addsTransport(opt)) return copy;
    return transport_ ? transport_->corrected(*copy, ctx.lighting) : nullptr;
}

std::vector<uint8_t> FrameResult::displayPixels(int& channels) const {
    channels = alpha8.empty() ? 3 : 4;
    if (alpha8.empty()) return rgb8;
    std::vector<uint8_t> rgba(alpha8.size() * 4);
    for (size_t i = 0; i < alpha8.size(); ++i) {
        for (size_t c = 0; c < 3; ++c) rgba[i * 4 + c] = rgb8[i * 3 + c];
        rgba[i * 4 + 3] = alpha8[i];
    }
    return rgba;
}

FrameResult Renderer::render(const Scene& scene, const RenderOptions& requested, Cancel* cancel) {
    if (forkedAway())
        fail("this renderer was made in process ", pid_, " and cannot render in its forked child ",
             ::getpid(),
             ": OpenCL's and GL's threads are not copied by fork(); fork before making any "
             "renderer, or use multiprocessing's 'spawn' start method");
    // The one check of the frame's user input; past here a bad value is a bug.
    validateRenderOptions(requested);
    validateMaterial(scene.material);
    for (const ObjectMaterial& o : scene.objectMaterials) validateMaterial(o.medium);
    RenderOptions opt = requested;
    // The key of every per-mesh cache (its area below, the media, the atlases).
    const uint64_t mesh = meshHash(scene.mesh);
    if (opt.lightResolution == 0) opt.lightResolution = autoLightResolution(scene);
    if (opt.atlasResolution == 0)
        opt.atlasResolution = autoAtlasResolution(scene, surfaceArea(scene.mesh, mesh));
    if (opt.aaMethod == AaMethod::Fxaa) opt.aa = 1;  // the pass over the display instead
    gl_.makeCurrent();  // another renderer on this thread may have drawn since
    if (scene.lights.empty()) fail("the scene has no light; add one with --light");
    if (opt.background == Background::Env && !scene.env)
        fail("--background env shows the --env map: give --env FILE");
    if (static_cast<int>(scene.lights.size()) > kMaxLights)
        fail("too many lights: ", scene.lights.size(), " (at most ", kMaxLights, ")");
    // The composite's samples are one render target (docs/design.md "The composite").
    if (const int most = gl_.maxTextureSize(); std::max(opt.width, opt.height) * opt.aa > most)
        fail("--aa ", opt.aa, " at ", opt.width, "×", opt.height, " needs ", opt.width * opt.aa,
             "×", opt.height * opt.aa, " composite samples, past GL's largest target ", most,
             "; lower --aa");
    Timer total;
    CpuTimer totalCpu;
    FrameResult result;
    FrameStats& stats = result.stats;
    FrameContext ctx = frameContext(scene, mesh, opt, cl_, stats);
    ctx.cancel = cancel;

    // A frame that moves only the camera (or changes σ, N, the method…) reuses
    // the light maps and the flux atlas: same lighting key.
    const SceneMedia& sm = media(scene, mesh);
    ctx.media = &sm;
    ctx.albedo = &albedoAtlas(scene, sm, opt, mesh);
    ctx.surface = &surfaceAtlas(scene, sm.media, opt, mesh);
    const uint64_t lighting =
        Hasher(lightingKey(scene, opt, mesh)).add(ctx.albedo->key).add(ctx.surface->key).digest();
    if (!opt.reuseLighting) raster_.invalidateLighting();
    ctx.lighting = lighting;
    const uint64_t view = Hasher().add(ctx.viewProj).add(opt.width).add(opt.height).digest();
    ctx.cameraMoved = view != lastView_;
    lastView_ = view;
    stats.set("lighting_reused", raster_.lightingCurrent(lighting) ? 1.0 : 0.0);
    const uint64_t accumulation = opt.progressive ? accumulationKey(scene, opt, lighting) : 0;
    if (opt.progressive) ctx.sampleSet = accumulator_.framesFor(accumulation);

    // The pipeline: GL rasterises, the hand-off moves what CL reads, the
    // method computes B, B comes back (and is averaged), GL composites.
    FrameGraph graph;
    staging_.declare(graph, ctx);
    const RasterHandles gl =
        raster_.addPasses(graph, ctx, mesh, lighting, ctx.lightMaps, ctx.gbuffer);
    staging_.addUploads(graph, ctx, gl);
    // The method, once per material (docs/design.md §2 "Materials"); the
    // passes hold their context by reference until the graph has run.
    // A method that reads only the lights' views gets the environment's
    // residual from a texture-space run (pyramid) over the residual's flux
    // alone, through the part of Rd it misses (docs/design.md §12).
    std::vector<FrameContext> runs, residual;
    runs.reserve(sm.slots());
    const std::vector<FrameGraphId<SurfacePoints>> points = staging_.addSlotPoints(graph, ctx);
    const std::optional<RdPart> missed =
        scene.env ? method(opt.method, 0).missesResidual(opt) : std::nullopt;
    if (missed) residual.reserve(sm.slots());
    // A frame that only moved the camera may read B from the method's copy
    // over the atlas on the GL side (docs/design.md §6): no run at all.
    const AtlasRadiosity* copy = atlasRadiosity(scene, opt, ctx, missed.has_value());
    stats.set("radiosity_lookup_gl", copy ? 1.0 : 0.0);
    if (copy && addsTransport(opt))
        stats.set("transport_copy_made", transport_->madeCorrectedCopy() ? 1.0 : 0.0);
    for (size_t k = 0; k < sm.slots() && !copy; ++k) {
        runs.push_back(materialContext(ctx, sm.slotMedium(scene, k)));
        runs[k].points = points[k];
        if (k > 0) runs[k].radiosity = staging_.declareRadiosity(graph, k);
        method(opt.method, k).addPasses(graph, runs[k]);
        if (!missed) continue;
        residual.push_back(runs[k]);
        residual[k].fluxAtlas = ctx.residualFluxAtlas;
        residual[k].rdPart = *missed;
        residual[k].radiosity = staging_.declareRadiosity(graph, sm.slots() + k);
        method("pyramid", k, "residual").addPasses(graph, residual[k]);
    }
    const FrameGraphId<RadiosityImage> radiosity =
        copy ? raster_.addRadiosityLookup(graph, ctx, gl, *copy)
             : staging_.addReadback(graph, runs, residual);
    // L⁽¹⁾ once for every method but volumetric, whose walk scatters once too.
    if (addsSingleScatter(opt)) {
        if (!singleScatter_) singleScatter_ = std::make_unique<SingleScatter>(cl_);
        singleScatter_->addPass(graph, ctx, gl, radiosity);
    }
    // The object's own transport, likewise for every method but volumetric
    // (on the GL side's lookup, in the copy it reads).
    if (addsTransport(opt) && !copy) {
        if (!transport_) transport_ = std::make_unique<ObjectTransport>(cl_);
        transport_->setBackgroundFits(backgroundFits_ && !opt.progressive);
        std::vector<KeyedProfile> profiles;
        for (size_t k = 0; k < sm.slots(); ++k)
            profiles.push_back(materialContext(ctx, sm.slotMedium(scene, k)).profile());
        transport_->addPass(graph, ctx, std::move(profiles), radiosity);
    }
    if (opt.progressive)
        graph.addPass(
            "accumulate",
            [&](FrameGraph::Builder& b) {
                b.read(radiosity);
                b.write(radiosity);
            },
            [this, radiosity, accumulation](FrameGraph::Resources& res) {
                std::vector<float>& rgba = res.write(radiosity).rgba;
                rgba = accumulator_.add(accumulation, rgba);
                res.stats().set("accumulated_frames",
                                static_cast<double>(accumulator_.framesFor(accumulation)));
            });
    const FrameGraphId<FrameImage> image = raster_.addComposite(graph, ctx, gl, radiosity);
    graph.setCancel(cancel);
    try {
        graph.execute(stats, image);
    } catch (...) {
        forgetAfterAbort();
        throw;
    }

    result.width = opt.width;
    result.height = opt.height;
    result.rgb8 = std::move(graph.get(image).rgb8);
    result.alpha8 = std::move(graph.get(image).alpha8);
    result.lavg = graph.get(image).lavg;
    if (opt.keepAovs) collectAovs(graph, gl, radiosity, image, ctx, result);
    stats.addStage("total", total.ms(), -1, totalCpu.ms());
    stats.set("device", cl_.deviceName());
    stats.set("gl_renderer", gl_.renderer());
    stats.set("gl_platform", gl_.platform());
    stats.set("gl_cl_sharing", sharing_.reason);
    recordFrame(stats, opt, scene, graph,
                copy ? graph.get(radiosity).covered : graph.get(ctx.points).count);
    if (!copy) staging_.recycle(graph.get(radiosity));
    return result;
}

}  // namespace tsis
