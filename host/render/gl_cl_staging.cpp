#include "render/gl_cl_staging.h"

#include <algorithm>
#include <cstring>

#include "util/error.h"

namespace tsis {

namespace {

constexpr size_t kTexelBytes = 4 * sizeof(float);

// What a float vector moves, for the stage's bytes.
long long bytesOf(const std::vector<float>& v) {
    return static_cast<long long>(v.size()) * static_cast<long long>(sizeof(float));
}

// Blocking: the host vector dies when the pass returns.
void upload(cl::CommandQueue& queue, cl::Buffer& buffer, const std::vector<float>& data) {
    if (!data.empty())
        queue.enqueueWriteBuffer(buffer, CL_TRUE, 0, data.size() * sizeof(float), data.data());
}

}  // namespace

void GlClStaging::declare(FrameGraph& graph, FrameContext& ctx) {
    ctx.fluxAtlas = graph.create<AtlasCl>("flux_atlas_cl");
    ctx.residualFluxAtlas = graph.create<AtlasCl>("residual_flux_atlas_cl");
    ctx.positionAtlas = graph.create<AtlasCl>("position_atlas_cl");
    ctx.normalAtlas = graph.create<AtlasCl>("normal_atlas_cl");
    ctx.points = graph.create<SurfacePoints>("points_cl");
    ctx.pointUvs = graph.create<Marker>("point_uvs");
    ctx.gbuffer = graph.create<CameraBuffersCl>("gbuffer_cl");
    ctx.lightMaps = graph.create<LightMapsCl>("light_maps_cl");
    ctx.radiosity = graph.create<RadiosityCl>("radiosity_cl", RadiosityCl{&radiosity_});
}

void GlClStaging::addAtlasUpload(FrameGraph& graph, const FrameContext& ctx, const char* name,
                                 FrameGraphId<GlTarget> source, int attachment,
                                 GrowingBuffer& buffer, uint64_t& uploaded,
                                 FrameGraphId<AtlasCl> out) {
    graph.addPass(
        name,
        [&](FrameGraph::Builder& b) {
            b.read(source);
            b.write(out);
        },
        [&ctx, source, attachment, &buffer, &uploaded, out](FrameGraph::Resources& res) {
            const GlTarget& gl = res.read(source);
            if (gl.version != uploaded) {
                // Read straight into the CL buffer, mapped: on a CPU device
                // its memory, with no vector of floats between.
                const size_t bytes =
                    size_t(gl.target->width()) * size_t(gl.target->height()) * 4 * sizeof(float);
                cl::Buffer& b = buffer.reserve(ctx.cl->context(), bytes);
                cl::CommandQueue& q = ctx.cl->queue();
                void* mapped =
                    q.enqueueMapBuffer(b, CL_TRUE, CL_MAP_WRITE_INVALIDATE_REGION, 0, bytes);
                gl.target->readRGBA(attachment, static_cast<float*>(mapped));
                q.enqueueUnmapMemObject(b, mapped);
                uploaded = gl.version;
                res.addBytes(static_cast<long long>(bytes));
            } else {
                res.addBytes(0);
            }
            res.write(out) = {buffer.buffer, gl.version};
        });
}

void GlClStaging::addUploads(FrameGraph& graph, const FrameContext& ctx, const RasterHandles& gl) {
    // The flux atlas crosses whenever the lighting changed; the geometry
    // (position; normal, w = texel area) only with the mesh or resolution.
    addAtlasUpload(graph, ctx, "gl_to_cl_flux_atlas", gl.fluxAtlas, 0, fluxAtlas_, fluxUploaded_,
                   ctx.fluxAtlas);
    if (ctx.scene->env)
        addAtlasUpload(graph, ctx, "gl_to_cl_residual_flux_atlas", gl.residualFluxAtlas, 0,
                       residualFluxAtlas_, residualUploaded_, ctx.residualFluxAtlas);
    addAtlasUpload(graph, ctx, "gl_to_cl_position_atlas", gl.geometryAtlas, 0, positionAtlas_,
                   positionUploaded_, ctx.positionAtlas);
    addAtlasUpload(graph, ctx, "gl_to_cl_normal_atlas", gl.geometryAtlas, 1, normalAtlas_,
                   normalUploaded_, ctx.normalAtlas);
    // Only covered pixels cross, packed (xyz per point).
    graph.addPass(
        "gl_to_cl_points",
        [&](FrameGraph::Builder& b) {
            b.read(gl.gbuffer);
            b.write(ctx.points);
        },
        [this, &graph, &ctx, gl](FrameGraph::Resources& res) {
            const GlTarget& gbuffer = res.read(gl.gbuffer);
            SurfacePoints& p = res.write(ctx.points);
            if (gbuffer.version == pointsOf_) {
                p = cachedPoints_;
                return;
            }
            static const std::vector<float> kNone;
            const RenderTarget& target = *gbuffer.target;
            const size_t texels = static_cast<size_t>(target.width()) * target.height();
            gbufferPositions_.resize(texels * 4);
            target.readRGBA(0, gbufferPositions_.data());
            const std::vector<float>& position = gbufferPositions_;
            // The atlas coordinates, when drawn: the G-buffer's last attachment.
            const bool uvs = graph.isRead(ctx.pointUvs);
            if (uvs) {
                gbufferUvs_.resize(texels * 2);
                target.readRG(target.colorCount() - 1, gbufferUvs_.data());
            }
            const std::vector<float>& uv = uvs ? gbufferUvs_ : kNone;
            // With an albedo atlas, the normal's w holds each pixel's texel + 1.
            const AlbedoAtlas& albedo = *ctx.albedo;
            if (!albedo.empty()) {
                gbufferNormals_.resize(texels * 4);
                target.readRGBA(1, gbufferNormals_.data());
            }
            const std::vector<float>& normal = albedo.empty() ? kNone : gbufferNormals_;
            for (int i = 0; i < ctx.width * ctx.height; ++i)
                if (position[static_cast<size_t>(i) * 4 + 3] > 0) {
                    p.pixel.push_back(i);
                    p.host.insert(p.host.end(), position.begin() + i * 4,
                                  position.begin() + i * 4 + 4);
                    if (!uv.empty())
                        p.uvs.insert(p.uvs.end(), uv.begin() + i * 2, uv.begin() + i * 2 + 2);
                    if (albedo.empty()) continue;
                    const float texel = normal[static_cast<size_t>(i) * 4 + 3] - 1.0f;
                    const size_t at = texel >= 0 ? static_cast<size_t>(texel) : SIZE_MAX;
                    const glm::vec3 f = albedo.atTexel(at);
                    p.exitAlbedo.insert(p.exitAlbedo.end(), {f.x, f.y, f.z});
                    if (!albedo.slot.empty())
                        p.slot.push_back(albedo.slotAtTexel(
                            at, ctx.media->slotOfTag(position[static_cast<size_t>(i) * 4 + 3])));
                }
            p.count = static_cast<int>(p.pixel.size());
            p.xyz = points_.reserve(ctx.cl->context(), p.host.size() * sizeof(float));
            upload(ctx.cl->queue(), p.xyz, p.host);
            if (!p.uvs.empty()) {
                p.uv = pointUvs_.reserve(ctx.cl->context(), p.uvs.size() * sizeof(float));
                upload(ctx.cl->queue(), p.uv, p.uvs);
            }
            res.addBytes(bytesOf(p.host) + bytesOf(p.uvs));
            cachedPoints_ = p;
            pointsOf_ = gbuffer.version;
        });
    // Full-resolution camera buffers, for methods that work in image space.
    graph.addPass(
        "gl_to_cl_gbuffer",
        [&](FrameGraph::Builder& b) {
            b.read(gl.gbuffer);
            b.write(ctx.gbuffer);
        },
        [this, &ctx, gl](FrameGraph::Resources& res) {
            const GlTarget& gbuffer = res.read(gl.gbuffer);
            const size_t bytes = static_cast<size_t>(ctx.width) * ctx.height * kTexelBytes;
            CameraBuffersCl& out = res.write(ctx.gbuffer);
            cl::Buffer* dst[3] = {&out.position, &out.normal, &out.irradiance};
            const bool changed = gbuffer.version != gbufferUploaded_;
            for (int i = 0; i < 3; ++i) {
                *dst[i] = gbuffer_[i].reserve(ctx.cl->context(), bytes);
                if (!changed) continue;
                upload(ctx.cl->queue(), *dst[i], gbuffer.target->readRGBA(i));
                res.addBytes(static_cast<long long>(bytes));
            }
            gbufferUploaded_ = gbuffer.version;
        });
    graph.addPass(
        "gl_to_cl_light_maps",
        [&](FrameGraph::Builder& b) {
            b.read(gl.lights);
            b.write(ctx.lightMaps);
        },
        [this, &ctx, gl](FrameGraph::Resources& res) {
            const GlLights& lights = res.read(gl.lights);
            const size_t bytes =
                static_cast<size_t>(ctx.lightResolution) * ctx.lightResolution * kTexelBytes;
            const bool changed = lights.version != lightsUploaded_;
            LightMapsCl& out = res.write(ctx.lightMaps);
            out.views = lights.views;
            lightMaps_.resize(2 * lights.views->size());
            res.addBytes(0);
            for (size_t l = 0; l < lights.views->size(); ++l)
                for (int i = 0; i < 2; ++i) {
                    GrowingBuffer& b = lightMaps_[2 * l + static_cast<size_t>(i)];
                    if (changed) {
                        upload(ctx.cl->queue(), b.reserve(ctx.cl->context(), bytes),
                               (*lights.views)[l].target->readRGBA(i));
                        res.addBytes(static_cast<long long>(bytes));
                    }
                    (i == 0 ? out.flux : out.position).push_back(b.buffer);
                }
            lightsUploaded_ = lights.version;
        });
}

FrameGraphId<RadiosityCl> GlClStaging::declareRadiosity(FrameGraph& graph, size_t slot) {
    while (slotRadiosity_.size() < slot)
        slotRadiosity_.push_back(std::make_unique<GrowingBuffer>());
    return graph.create<RadiosityCl>(concat("radiosity_cl_", slot),
                                     RadiosityCl{slotRadiosity_[slot - 1].get()});
}

std::vector<FrameGraphId<SurfacePoints>> GlClStaging::addSlotPoints(FrameGraph& graph,
                                                                    const FrameContext& ctx) {
    const size_t slots = ctx.media->slots();
    if (slots == 1) return {ctx.points};
    std::vector<FrameGraphId<SurfacePoints>> out;
    for (size_t k = 0; k < slots; ++k)
        out.push_back(graph.create<SurfacePoints>(concat("points_cl_", k)));
    while (slotXyz_.size() < slots) slotXyz_.push_back(std::make_unique<GrowingBuffer>());
    while (slotUv_.size() < slots) slotUv_.push_back(std::make_unique<GrowingBuffer>());
    graph.addPass(
        "split_points",
        [&](FrameGraph::Builder& b) {
            b.read(ctx.points);
            for (const auto& h : out) b.write(h);
        },
        [this, &ctx, out, slots](FrameGraph::Resources& res) {
            const SurfacePoints& all = res.read(ctx.points);
            // Split again only for a new G-buffer (the points' version) or
            // another assignment of media (or texels, render/albedo_atlas.h)
            // to slots.
            if (slotPointsOf_ != pointsOf_ || slotOfMedium_ != ctx.media->slotOfMedium ||
                slotAlbedo_ != ctx.albedo->key || slotPoints_.size() != slots) {
                slotPoints_.assign(slots, SurfacePoints());
                for (size_t i = 0; i < static_cast<size_t>(all.count); ++i) {
                    const uint32_t slot =
                        all.slot.empty() ? ctx.media->slotOfTag(all.host[i * 4 + 3]) : all.slot[i];
                    SurfacePoints& p = slotPoints_[std::min<size_t>(slot, slots - 1)];
                    p.pixel.push_back(all.pixel[i]);
                    p.host.insert(p.host.end(), all.host.begin() + static_cast<long>(i * 4),
                                  all.host.begin() + static_cast<long>(i * 4 + 4));
                    if (!all.exitAlbedo.empty())
                        p.exitAlbedo.insert(p.exitAlbedo.end(),
                                            all.exitAlbedo.begin() + static_cast<long>(i * 3),
                                            all.exitAlbedo.begin() + static_cast<long>(i * 3 + 3));
                    if (!all.uvs.empty())
                        p.uvs.insert(p.uvs.end(), all.uvs.begin() + static_cast<long>(i * 2),
                                     all.uvs.begin() + static_cast<long>(i * 2 + 2));
                }
                long long bytes = 0;
                for (size_t k = 0; k < slots; ++k) {
                    SurfacePoints& p = slotPoints_[k];
                    p.count = static_cast<int>(p.pixel.size());
                    p.xyz = slotXyz_[k]->reserve(
                        ctx.cl->context(), std::max<size_t>(p.host.size(), 4) * sizeof(float));
                    upload(ctx.cl->queue(), p.xyz, p.host);
                    if (!p.uvs.empty()) {
                        p.uv = slotUv_[k]->reserve(ctx.cl->context(), p.uvs.size() * sizeof(float));
                        upload(ctx.cl->queue(), p.uv, p.uvs);
                    }
                    bytes += bytesOf(p.host) + bytesOf(p.uvs);
                }
                res.addBytes(bytes);
                slotPointsOf_ = pointsOf_;
                slotOfMedium_ = ctx.media->slotOfMedium;
                slotAlbedo_ = ctx.albedo->key;
            }
            for (size_t k = 0; k < slots; ++k) res.write(out[k]) = slotPoints_[k];
        });
    return out;
}

FrameGraphId<RadiosityImage> GlClStaging::addReadback(FrameGraph& graph,
                                                      const std::vector<FrameContext>& runs,
                                                      const std::vector<FrameContext>& residual) {
    TSIS_CHECK(residual.empty() || residual.size() == runs.size());
    const FrameGraphId<RadiosityImage> image =
        graph.create<RadiosityImage>("radiosity", RadiosityImage{std::move(spareRadiosity_)});
    graph.addPass(
        "read_radiosity",
        [&](FrameGraph::Builder& b) {
            for (const FrameContext& run : runs) b.read(run.points);
            for (const FrameContext& run : runs) b.read(run.radiosity);
            for (const FrameContext& run : residual) b.read(run.radiosity);
            b.write(image);
        },
        [&runs, &residual, image](FrameGraph::Resources& res) {
            const FrameContext& ctx = runs.front();
            std::vector<float>& rgba = res.write(image).rgba;
            rgba.assign(static_cast<size_t>(ctx.width) * ctx.height * 4, 0.0f);
            // Each run's B of its points (plus the residual's).
            for (size_t k = 0; k < runs.size(); ++k) {
                const SurfacePoints& points = res.read(runs[k].points);
                const size_t count = static_cast<size_t>(points.count);
                auto read = [&](const FrameContext& run) {
                    std::vector<float> b(count * 4);
                    if (count > 0)
                        ctx.cl->queue().enqueueReadBuffer(res.read(run.radiosity).storage->buffer,
                                                          CL_TRUE, 0, count * 4 * sizeof(float),
                                                          b.data());
                    res.addBytes(bytesOf(b));
                    return b;
                };
                std::vector<float> b = read(runs[k]);
                if (!residual.empty()) {
                    const std::vector<float> r = read(residual[k]);
                    for (size_t i = 0; i < r.size(); ++i) b[i] += r[i];
                }
                for (size_t i = 0; i < count; ++i) {
                    float* out = &rgba[static_cast<size_t>(points.pixel[i]) * 4];
                    for (int c = 0; c < 3; ++c)
                        out[c] = points.exitAlbedo.empty()
                                     ? b[i * 4 + c]
                                     : b[i * 4 + c] * points.exitAlbedo[i * 3 + c];
                    out[3] = 1.0f;
                }
            }
        });
    return image;
}

}  // namespace tsis
