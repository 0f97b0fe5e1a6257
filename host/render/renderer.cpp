#include "render/renderer.h"

#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "physics/dipole.h"
#include "tsis_shared.h"
#include "util/error.h"
#include "util/timer.h"

namespace tsis {

namespace {

template <typename T>
void hashBytes(uint64_t& h, const T* data, size_t count) {
    const auto* p = reinterpret_cast<const unsigned char*>(data);
    for (size_t i = 0; i < count * sizeof(T); ++i) {
        h ^= p[i];
        h *= 1099511628211ull;
    }
}

float boundingRadius(const Mesh& mesh) {
    float r2 = 0;
    for (const glm::vec3& p : mesh.positions) r2 = std::max(r2, glm::dot(p, p));
    return std::sqrt(r2);
}

// GL RGBA (row 0 = bottom) → ImageF with `channels` of them, row 0 = top.
ImageF toImage(const std::vector<float>& rgba, int w, int h, int channels, int first = 0) {
    ImageF img;
    img.width = w;
    img.height = h;
    img.channels = channels;
    img.pixels.resize(static_cast<size_t>(w) * h * channels);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < channels; ++c)
                img.pixels[(static_cast<size_t>(h - 1 - y) * w + x) * channels + c] =
                    rgba[(static_cast<size_t>(y) * w + x) * 4 + first + c];
    return img;
}

template <typename T>
void hashValue(uint64_t& h, const T& value) {
    hashBytes(h, &value, 1);
}

// Everything the light maps and the flux atlas depend on: the mesh, the
// lights, η (Fresnel at entry) and the two resolutions. Field by field (no
// struct padding).
uint64_t lightingKey(const Scene& scene, const RenderOptions& o, uint64_t meshHash) {
    uint64_t h = 1469598103934665603ull;
    hashValue(h, meshHash);
    hashValue(h, scene.material.eta);
    for (const Light& l : scene.lights) {
        hashValue(h, l.type);
        hashValue(h, l.vec);
        hashValue(h, l.rgb);
        hashValue(h, l.shadows);
    }
    hashValue(h, o.lightResolution);
    hashValue(h, o.atlasResolution);
    return h;
}

// Everything that changes the radiosity a frame computes, except the sample
// set: frames with equal keys may be averaged. A new option that changes the
// radiosity belongs here too.
uint64_t accumulationKey(const Scene& scene, const RenderOptions& o, uint64_t lighting) {
    uint64_t h = lighting;
    hashValue(h, scene.material.sigmaSPrime);
    hashValue(h, scene.material.sigmaA);
    const Camera& c = scene.camera;
    for (const glm::vec3& v : {c.eye, c.target, c.up}) hashValue(h, v);
    hashValue(h, c.fovYDegrees);
    hashBytes(h, o.method.data(), o.method.size());
    hashBytes(h, o.rdPart.data(), o.rdPart.size());
    for (int v : {o.width, o.height, o.samples, o.ltsmRings, o.ltsmPerRing, o.misDistanceSamples,
                  o.pyramidStride, o.spp})
        hashValue(h, v);
    for (double v :
         {o.rpBound, o.rpK, o.spacingMm, double(o.epsilon), double(o.pyramidEpsilon), o.tsmRadius})
        hashValue(h, v);
    hashValue(h, o.seed);
    return h;
}

}  // namespace

uint64_t meshHash(const Mesh& mesh) {
    uint64_t h = 1469598103934665603ull;
    hashBytes(h, mesh.positions.data(), mesh.positions.size());
    hashBytes(h, mesh.normals.data(), mesh.normals.size());
    hashBytes(h, mesh.uvs.data(), mesh.uvs.size());
    hashBytes(h, mesh.triangles.data(), mesh.triangles.size());
    return h;
}

float logAverageLuminance(const std::vector<float>& rgba) {
    double sum = 0;
    size_t n = 0;
    for (size_t i = 0; i + 3 < rgba.size(); i += 4) {
        if (rgba[i + 3] <= 0) continue;
        double y = TSIS_LUMA_R * rgba[i] + TSIS_LUMA_G * rgba[i + 1] + TSIS_LUMA_B * rgba[i + 2];
        sum += std::log(1e-12 + std::max(0.0, y));
        ++n;
    }
    return n ? static_cast<float>(std::exp(sum / static_cast<double>(n))) : 1.0f;
}

Renderer::Renderer(const std::string& clDevice) : gl_(), cl_(clDevice) {}

Renderer::~Renderer() = default;

void Renderer::uploadMeshIfChanged(const Mesh& mesh, uint64_t h) {
    if (gpuMesh_ && h == meshHash_) return;
    gpuMesh_ = std::make_unique<GpuMesh>(mesh);
    meshHash_ = h;
}

Method& Renderer::method(const std::string& name) {
    auto it = methods_.find(name);
    if (it == methods_.end()) it = methods_.emplace(name, makeMethod(name, cl_)).first;
    return *it->second;
}

int autoLightResolution(const Scene& scene) {
    // Shadow edges in B are blurred over the shortest diffusion length 1/σtr;
    // on objects many of those across, the 1024² maps' texels show (measured:
    // ChineseDragon-10kv, ketchup 50 mm, 2.3% against the reference at 1024²,
    // 1.1% at 2048²).
    const glm::dvec3 tr = Dipole(scene.material).sigmaTr();
    const double across = 2.0 * boundingRadius(scene.mesh) * std::max({tr.x, tr.y, tr.z});
    return across > 100.0 ? 2048 : 1024;
}

FrameResult Renderer::render(const Scene& scene, const RenderOptions& requested) {
    RenderOptions opt = requested;
    if (opt.lightResolution == 0) opt.lightResolution = autoLightResolution(scene);
    Timer total;
    FrameResult result;
    FrameStats& stats = result.stats;
    const int w = opt.width, h = opt.height, res = opt.atlasResolution;
    const float eta = static_cast<float>(scene.material.eta);
    if (scene.lights.empty()) fail("the scene has no light; add one with --light");
    if (static_cast<int>(scene.lights.size()) > kMaxLights)
        fail("too many lights: ", scene.lights.size(), " (at most ", kMaxLights, ")");
    Method& m = method(opt.method);

    FrameContext ctx;
    ctx.scene = &scene;
    ctx.options = &opt;
    ctx.cl = &cl_;
    ctx.stats = &stats;
    ctx.boundingRadius = boundingRadius(scene.mesh);
    ctx.atlasResolution = res;
    ctx.lights = &lights_;
    ctx.width = w;
    ctx.height = h;
    ctx.lightResolution = opt.lightResolution;
    const uint64_t mesh = meshHash(scene.mesh);
    // A frame that moves only the camera (or changes σ, N, the method…) reuses
    // the light maps and the flux atlas: same lighting key.
    const uint64_t lighting = lightingKey(scene, opt, mesh);
    if (!opt.reuseLighting) lightViewKey_ = fluxKey_ = fluxUploadKey_ = lightMapsUploadKey_ = 0;
    const bool sameLighting = lighting == lightViewKey_;
    stats.set("lighting_reused", sameLighting ? 1.0 : 0.0);
    const uint64_t key = opt.progressive ? accumulationKey(scene, opt, lighting) : 0;
    if (opt.progressive) ctx.sampleSet = accumulator_.framesFor(key);

    const Camera& cam = scene.camera;
    const float camDist = glm::length(cam.eye - cam.target);
    const float nearP =
        std::max({glm::length(cam.eye) - ctx.boundingRadius * 1.5f, camDist * 1e-3f, 1e-4f});
    const float farP = glm::length(cam.eye) + ctx.boundingRadius * 1.5f;
    const glm::mat4 viewProj =
        glm::perspective(glm::radians(cam.fovYDegrees), static_cast<float>(w) / h, nearP, farP) *
        glm::lookAt(cam.eye, cam.target, cam.up);
    ctx.viewProj = viewProj;
    ctx.eye = cam.eye;

    std::vector<float> gbufferPosition, radianceRGBA;
    std::vector<int> pointPixel;  // GL pixel index of each covered point

    FrameGraph graph;
    graph.addPass({"upload_mesh", {}, {"mesh"}, [&] { uploadMeshIfChanged(scene.mesh, mesh); }});
    graph.addPass({"gl_light_view", {"mesh"}, {"light_maps"}, [&] {
                       // Flux and position maps only when a light-view method reads them.
                       const bool maps = graph.isRead("light_maps_cl");
                       if (sameLighting && (lightMapsMade_ || !maps)) return;
                       // Nothing made from the old maps is current any more.
                       lightViewKey_ = fluxKey_ = fluxUploadKey_ = lightMapsUploadKey_ = 0;
                       lights_.clear();
                       for (const Light& l : scene.lights)
                           lights_.push_back(
                               makeLightView(l, ctx.boundingRadius, opt.lightResolution, maps));
                       lightMapsMade_ = maps;
                       lightPass_.run(*gpuMesh_, lights_, eta);
                       glFinish();
                       lightViewKey_ = lighting;
                   }});
    // The geometry atlas depends on the mesh and resolution only: made once.
    graph.addPass({"gl_geometry_atlas", {"mesh"}, {"geometry_atlas"}, [&] {
                       if (geometryKey_ == std::make_pair(meshHash_, res)) return;
                       geometryAtlasPass_.run(*gpuMesh_, res);
                       glFinish();
                       geometryKey_ = {meshHash_, res};
                       geometryVersion_++;
                   }});
    graph.addPass({"gl_flux_atlas", {"geometry_atlas", "light_maps"}, {"atlas"}, [&] {
                       if (fluxKey_ == lighting) return;
                       fluxAtlasPass_.run(geometryAtlasPass_.target(), lights_,
                                          lightPass_.shadows(), eta);
                       glFinish();
                       fluxKey_ = lighting;
                   }});
    graph.addPass({"gl_gbuffer", {"mesh", "light_maps"}, {"gbuffer"}, [&] {
                       gbufferPass_.run(*gpuMesh_, lights_, lightPass_.shadows(), eta, viewProj, w,
                                        h, graph.isRead("gbuffer_cl"));
                       glFinish();
                   }});
    // Staged hand-off: read back from GL, write to CL (no cl_khr_gl_sharing on
    // OSMesa + PoCL). The flux atlas crosses every frame at full float
    // precision; the position atlas only when the mesh or resolution changed.
    graph.addPass({"gl_to_cl_atlas",
                   {"atlas"},
                   {"flux_atlas_cl", "position_atlas_cl"},
                   [&] {
                       Timer t;
                       size_t bytes = static_cast<size_t>(res) * res * 16;
                       long long moved = 0;
                       std::vector<float> flux;
                       if (fluxUploadKey_ != lighting || opt.keepAovs)
                           flux = fluxAtlasPass_.target().readRGBA(0);
                       if (fluxUploadKey_ != lighting) {
                           fluxAtlas_.reserve(cl_.context(), bytes);
                           cl_.queue().enqueueWriteBuffer(fluxAtlas_.buffer, CL_FALSE, 0, bytes,
                                                          flux.data());
                           moved += static_cast<long long>(bytes);
                       }
                       if (positionVersion_ != geometryVersion_) {
                           positionAtlas_.reserve(cl_.context(), bytes);
                           std::vector<float> pos = geometryAtlasPass_.target().readRGBA(0);
                           cl_.queue().enqueueWriteBuffer(positionAtlas_.buffer, CL_TRUE, 0, bytes,
                                                          pos.data());
                           positionVersion_ = geometryVersion_;
                           moved += static_cast<long long>(bytes);
                       }
                       cl_.queue().finish();
                       fluxUploadKey_ = lighting;
                       ctx.fluxKey = opt.reuseLighting ? lighting : 0;
                       ctx.fluxAtlas = fluxAtlas_.buffer;
                       ctx.positionAtlas = positionAtlas_.buffer;
                       ctx.geometryVersion = geometryVersion_;
                       stats.addStage("gl_to_cl_atlas", t.ms(), moved);
                       if (opt.keepAovs) result.fluxAtlas = toImage(flux, res, res, 3);
                   },
                   true});
    // The geometry atlas' normals (w = texel area) for methods that need areas:
    // again only when the mesh or resolution changed.
    graph.addPass({"gl_to_cl_normal_atlas",
                   {"geometry_atlas"},
                   {"normal_atlas_cl"},
                   [&] {
                       Timer t;
                       long long moved = 0;
                       if (normalVersion_ != geometryVersion_) {
                           const size_t bytes = static_cast<size_t>(res) * res * 16;
                           normalAtlas_.reserve(cl_.context(), bytes);
                           std::vector<float> normals = geometryAtlasPass_.target().readRGBA(1);
                           cl_.queue().enqueueWriteBuffer(normalAtlas_.buffer, CL_TRUE, 0, bytes,
                                                          normals.data());
                           normalVersion_ = geometryVersion_;
                           moved = static_cast<long long>(bytes);
                       }
                       ctx.normalAtlas = normalAtlas_.buffer;
                       stats.addStage("gl_to_cl_normal_atlas", t.ms(), moved);
                   },
                   true});
    // Only covered pixels cross, packed (xyz per point).
    graph.addPass({"gl_to_cl_points",
                   {"gbuffer"},
                   {"points_cl"},
                   [&] {
                       Timer t;
                       gbufferPosition = gbufferPass_.target().readRGBA(0);
                       std::vector<float> packed;
                       pointPixel.clear();
                       for (int i = 0; i < w * h; ++i)
                           if (gbufferPosition[static_cast<size_t>(i) * 4 + 3] > 0) {
                               pointPixel.push_back(i);
                               packed.insert(packed.end(), gbufferPosition.begin() + i * 4,
                                             gbufferPosition.begin() + i * 4 + 4);
                           }
                       ctx.pointCount = static_cast<int>(pointPixel.size());
                       ctx.pointPixel = pointPixel;
                       ctx.pointsHost = packed;
                       size_t bytes = packed.size() * sizeof(float);
                       points_.reserve(cl_.context(), bytes);
                       radiosity_.reserve(cl_.context(), bytes);
                       if (bytes)
                           cl_.queue().enqueueWriteBuffer(points_.buffer, CL_TRUE, 0, bytes,
                                                          packed.data());
                       ctx.points = points_.buffer;
                       ctx.radiosity = radiosity_.buffer;
                       stats.addStage("gl_to_cl_points", t.ms(), static_cast<long long>(bytes));
                   },
                   true});

    // Full-resolution camera buffers, for methods that work in image space.
    graph.addPass({"gl_to_cl_gbuffer",
                   {"gbuffer"},
                   {"gbuffer_cl"},
                   [&] {
                       Timer t;
                       size_t bytes = static_cast<size_t>(w) * h * 16;
                       long long total = 0;
                       cl::Buffer* dst[3] = {&ctx.gbufferPosition, &ctx.gbufferNormal,
                                             &ctx.gbufferIrradiance};
                       for (int i = 0; i < 3; ++i) {
                           gbufferCl_[i].reserve(cl_.context(), bytes);
                           std::vector<float> data = gbufferPass_.target().readRGBA(i);
                           cl_.queue().enqueueWriteBuffer(gbufferCl_[i].buffer, CL_TRUE, 0, bytes,
                                                          data.data());
                           *dst[i] = gbufferCl_[i].buffer;
                           total += static_cast<long long>(bytes);
                       }
                       stats.addStage("gl_to_cl_gbuffer", t.ms(), total);
                   },
                   true});
    graph.addPass(
        {"gl_to_cl_light_maps",
         {"light_maps"},
         {"light_maps_cl"},
         [&] {
             Timer t;
             size_t bytes = static_cast<size_t>(opt.lightResolution) * opt.lightResolution * 16;
             long long total = 0;
             const bool upload = lightMapsUploadKey_ != lighting;
             lightCl_.resize(2 * lights_.size());
             ctx.lightFlux.clear();
             ctx.lightPosition.clear();
             for (size_t l = 0; l < lights_.size(); ++l)
                 for (int i = 0; i < 2; ++i) {
                     GrowingBuffer& b = lightCl_[2 * l + static_cast<size_t>(i)];
                     if (upload) {
                         b.reserve(cl_.context(), bytes);
                         std::vector<float> data = lights_[l].target->readRGBA(i);
                         cl_.queue().enqueueWriteBuffer(b.buffer, CL_TRUE, 0, bytes, data.data());
                         total += static_cast<long long>(bytes);
                     }
                     (i == 0 ? ctx.lightFlux : ctx.lightPosition).push_back(b.buffer);
                 }
             lightMapsUploadKey_ = lighting;
             stats.addStage("gl_to_cl_light_maps", t.ms(), total);
         },
         true});

    m.addPasses(graph, ctx);

    std::vector<float> radiosityRGBA(static_cast<size_t>(w) * h * 4, 0.0f);
    graph.addPass(
        {"cl_to_gl",
         {"radiosity_cl"},
         {"radiosity"},
         [&] {
             Timer t;
             std::vector<float> packed(static_cast<size_t>(ctx.pointCount) * 4);
             if (!packed.empty())
                 cl_.queue().enqueueReadBuffer(ctx.radiosity, CL_TRUE, 0,
                                               packed.size() * sizeof(float), packed.data());
             for (size_t k = 0; k < pointPixel.size(); ++k) {
                 size_t i = static_cast<size_t>(pointPixel[k]) * 4;
                 std::memcpy(&radiosityRGBA[i], &packed[k * 4], 3 * sizeof(float));
                 radiosityRGBA[i + 3] = 1.0f;
             }
             stats.addStage("cl_to_gl", t.ms(),
                            static_cast<long long>(packed.size() * sizeof(float)));
             if (opt.progressive) {
                 Timer ta;
                 radiosityRGBA = accumulator_.add(key, radiosityRGBA);
                 stats.addStage("accumulate", ta.ms());
                 stats.set("accumulated_frames", static_cast<double>(accumulator_.framesFor(key)));
             }
         },
         true});
    graph.addPass({"composite", {"radiosity", "gbuffer", "light_maps"}, {"image"}, [&] {
                       compositePass_.radiance(radiosityRGBA.data(), gbufferPass_.target(), cam.eye,
                                               eta);
                       radianceRGBA = compositePass_.radianceTarget().readRGBA(0);
                       result.lavg = logAverageLuminance(radianceRGBA);
                       compositePass_.toneMap(gbufferPass_.target(), lights_, lightPass_.shadows(),
                                              cam.eye, eta, opt.key, result.lavg,
                                              opt.specular ? opt.specularKs : 0.0f, opt.shininess);
                       std::vector<unsigned char> rgba = compositePass_.colorTarget().readRGBA8(0);
                       result.rgb8.resize(static_cast<size_t>(w) * h * 3);
                       for (int y = 0; y < h; ++y)
                           for (int x = 0; x < w; ++x)
                               for (int c = 0; c < 3; ++c)
                                   result.rgb8[(static_cast<size_t>(h - 1 - y) * w + x) * 3 + c] =
                                       rgba[(static_cast<size_t>(y) * w + x) * 4 + c];
                   }});
    graph.execute({"image"}, stats);

    result.width = w;
    result.height = h;
    if (opt.keepAovs) {
        result.radiosity = toImage(radiosityRGBA, w, h, 3);
        result.radiance = toImage(radianceRGBA, w, h, 3);
        result.position = toImage(gbufferPosition, w, h, 3);
        std::vector<float> normals = gbufferPass_.target().readRGBA(1);
        result.normal = toImage(normals, w, h, 3);
        result.coverage = toImage(gbufferPosition, w, h, 1, 3);
    }
    stats.addStage("total", total.ms());
    stats.totalRdEvaluations();
    stats.set("method", opt.method);
    stats.set("device", cl_.deviceName());
    stats.set("gl_renderer", gl_.renderer());
    stats.set("width", w);
    stats.set("height", h);
    stats.set("atlas_resolution", res);
    stats.set("light_resolution", opt.lightResolution);
    stats.set("samples", opt.samples);
    stats.set("covered_pixels", ctx.pointCount);
    stats.set("triangles", static_cast<double>(scene.mesh.triangles.size()));
    Json passes = Json::array();
    for (const std::string& p : graph.executed()) passes.push(p);
    stats.set("passes", passes);
    return result;
}

}  // namespace tsis
