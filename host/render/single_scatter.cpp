#include "render/single_scatter.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

#include "cl/launch.h"
#include "physics/fresnel.h"
#include "render/light_map_info.h"
#include "render/surface_points.h"
#include "util/error.h"
#include "util/hash.h"

namespace tsis {

TsisScatterMedium scatterMedium(const Material& m, ExitTerm exit) {
    const glm::dvec3 st = m.sigmaSPrime + m.sigmaA;
    return {static_cast<float>(m.sigmaSPrime.x),
            static_cast<float>(m.sigmaSPrime.y),
            static_cast<float>(m.sigmaSPrime.z),
            static_cast<float>(m.eta),
            static_cast<float>(st.x),
            static_cast<float>(st.y),
            static_cast<float>(st.z),
            static_cast<float>(M_PI / exitScale(exit, m.eta))};
}

TsisScatterLight scatterLight(const Light& light) {
    return {light.vec.x, light.vec.y, light.vec.z, light.type == Light::Type::Point ? 0 : 1,
            light.rgb.x, light.rgb.y, light.rgb.z, 0.0f};
}

namespace {

// The smallest mean free path 1/max σt′ (mm) of the scene's media.
double mediaMeanFreePath(const FrameContext& ctx) {
    double ell = INFINITY;
    const SceneMedia& sm = *ctx.media;
    for (size_t m = 0; m < sm.etaOfMedium.size(); ++m)
        ell = std::min(ell, smallestMeanFreePath(sm.slotMedium(*ctx.scene, sm.slotOfMedium[m])));
    return ell;
}

}  // namespace

int scatterViewResolution(const FrameContext& ctx) {
    const double texels =
        std::ceil(2.0 * ctx.boundingRadius / mediaMeanFreePath(ctx) * kScatterTexelsPerMfp);
    const int most = std::min(kScatterMaxResolution, ctx.lightResolution);
    return static_cast<int>(
        std::clamp(texels, double(std::min(kScatterMinResolution, most)), double(most)));
}

namespace {

// As the kernel's tsis_scatter_phi and tsis_scatter_stratum, in double.
double phi(double x) {
    return std::abs(x) < 1e-8 ? 1.0 - 0.5 * x : -std::expm1(-x) / x;
}

glm::dvec3 stratum(const glm::dvec3& sigmaT, double a, double b, double sm, double hm, double c,
                   double cosT) {
    const double sz = c != 0.0 ? sm + hm / c : -INFINITY;
    glm::dvec3 sum(0.0);
    double p = a, q = b;
    if (c <= 0.0 && sz > a) {
        const double z = std::min(sz, b);
        for (int i = 0; i < 3; ++i)
            sum[i] += std::exp(-sigmaT[i] * a) * (z - a) * phi(sigmaT[i] * (z - a));
        p = z;
    }
    if (c > 0.0) q = std::min(b, sz);
    if (q > p) {
        const double hp = std::max(0.0, hm - (p - sm) * c);
        for (int i = 0; i < 3; ++i)
            sum[i] += std::exp(-sigmaT[i] * (p + hp / cosT)) * (q - p) *
                      phi(sigmaT[i] * (1.0 - c / cosT) * (q - p));
    }
    return sum;
}

}  // namespace

ScatterEntry depthViewTexel(const DepthView& view, int x, int y) {
    const int res = view.resolution;
    const std::vector<float>& depth = *view.depth;
    auto at = [&](int i, int j) {
        return i >= 0 && j >= 0 && i < res && j < res
                   ? double(depth[static_cast<size_t>(j) * size_t(res) + size_t(i)])
                   : 1.0;
    };
    const glm::dmat4 toWorld = glm::inverse(view.viewProj);
    auto unproject = [&](int i, int j, double z) {
        const glm::dvec4 w = toWorld * glm::dvec4((i + 0.5) / res * 2.0 - 1.0,
                                                  (j + 0.5) / res * 2.0 - 1.0, z * 2.0 - 1.0, 1.0);
        return glm::dvec3(w) / w.w;
    };
    const double z = at(x, y);
    const double xp = at(x + 1, y), xm = at(x - 1, y), yp = at(x, y + 1), ym = at(x, y - 1);
    if (!(z < 1.0 && (xp < 1.0 || xm < 1.0) && (yp < 1.0 || ym < 1.0))) return {};
    const glm::dvec3 p = unproject(x, y, z);
    auto tangent = [&](int dx, int dy, double zp, double zm) {
        const int side = zp < 1.0 && (!(zm < 1.0) || std::abs(zp - z) <= std::abs(z - zm)) ? 1 : -1;
        return double(side) * (unproject(x + side * dx, y + side * dy, side > 0 ? zp : zm) - p);
    };
    return {true, p, glm::normalize(glm::cross(tangent(1, 0, xp, xm), tangent(0, 1, yp, ym)))};
}

ScatterEntry depthViewEntry(const DepthView& view, const glm::dvec3& x) {
    const glm::dvec4 c = view.viewProj * glm::dvec4(x, 1.0);
    const double res = view.resolution;
    const double tx = std::floor((c.x / c.w * 0.5 + 0.5) * res);
    const double ty = std::floor((c.y / c.w * 0.5 + 0.5) * res);
    if (!(tx >= 0 && ty >= 0 && tx < res && ty < res)) return {};
    return depthViewTexel(view, static_cast<int>(tx), static_cast<int>(ty));
}

glm::dvec3 singleScatterHost(const glm::dvec3& xo, const glm::dvec3& normal, const glm::dvec3& eye,
                             const TsisScatterMedium& md, const Light& light, const EntryOf& entry,
                             int strata) {
    glm::dvec3 n = glm::normalize(normal);
    const glm::dvec3 v = glm::normalize(eye - xo);
    double cosO = glm::dot(n, v);
    if (cosO < 0) {
        n = -n;
        cosO = -cosO;
    }
    const double eta = md.eta, invEta = 1.0 / eta;
    auto refractedCos = [invEta](double c) {
        return std::sqrt(std::max(0.0, 1.0 - invEta * invEta * (1.0 - c * c)));
    };
    const glm::dvec3 wt = glm::normalize(-v * invEta + n * (invEta * cosO - refractedCos(cosO)));
    const glm::dvec3 sigmaS(md.ss_r, md.ss_g, md.ss_b), sigmaT(md.st_r, md.st_g, md.st_b);
    const double sigma = std::min({sigmaT.x, sigmaT.y, sigmaT.z});
    const double kept = 1.0 - std::exp(-double(TSIS_SCATTER_DEPTH));
    glm::dvec3 sum(0.0);
    double a = 0.0;
    for (int k = 0; k < strata; ++k) {
        const double b = -std::log(1.0 - (k + 1.0) / strata * kept) / sigma;
        const double sm = -std::log(1.0 - (k + 0.5) / strata * kept) / sigma;
        const double ak = a;
        a = b;
        const glm::dvec3 x = xo + sm * wt;
        ScatterEntry in = entry(x);
        if (!in.lit) continue;
        // As the kernel: from the straight line's entry, the tangent plane's
        // refracted solution moved onto the surface, TSIS_SCATTER_ENTRY_STEPS
        // times; none where it falls past what the light sees.
        glm::dvec3 e, l, ni;
        double cosI = 0, cosT = 1, h2 = 0;
        for (int it = 0;; ++it) {
            e = glm::dvec3(light.rgb);
            if (light.type == Light::Type::Point) {
                const glm::dvec3 d = glm::dvec3(light.vec) - in.point;
                e /= glm::dot(d, d);
                l = glm::normalize(d);
            } else {
                l = -glm::normalize(glm::dvec3(light.vec));
            }
            ni = glm::normalize(in.normal);
            cosI = glm::dot(ni, l);
            cosT = refractedCos(cosI);
            h2 = glm::dot(in.point - x, ni);
            if (!(h2 > 0)) {
                if (it > 0) cosI = 0;
                h2 = 0;
                break;
            }
            if (!(cosI > 0) || it == TSIS_SCATTER_ENTRY_STEPS) break;
            const glm::dvec3 refracted = -l * invEta + ni * (invEta * cosI - cosT);
            in = entry(x - refracted * (h2 / cosT));
            if (!in.lit) {
                cosI = 0;
                break;
            }
        }
        if (!(cosI > 0)) continue;
        sum += stratum(sigmaT, ak, b, sm, h2, glm::dot(wt, ni), cosT) *
               (fresnelTransmittance(eta, cosI) * cosI / cosT) * e;
    }
    return sum * sigmaS * (invEta * invEta / (4.0 * M_PI));
}

SingleScatter::SingleScatter(ClRuntime& cl)
    : cl_(cl),
      drawn_(cl.kernel("single_scatter.cl", "tsis_single_scatter")),
      fromDepth_(
          cl.kernel("single_scatter.cl", "tsis_single_scatter", "-DTSIS_SCATTER_FROM_DEPTH")),
      interpolation_(cl) {}

void SingleScatter::addPass(FrameGraph& graph, const FrameContext& ctx, const RasterHandles& gl,
                            FrameGraphId<RadiosityImage> radiosity) {
    graph.addPass(
        "single_scatter",
        [&](FrameGraph::Builder& b) {
            b.read(ctx.points);
            b.read(gl.gbuffer);
            b.read(gl.scatterViews);
            b.read(radiosity);
            b.write(radiosity);
        },
        [this, &ctx, gl, radiosity](FrameGraph::Resources& res) {
            const SurfacePoints& points = res.read(ctx.points);
            const GlLights& scatter = res.read(gl.scatterViews);
            const GlTarget& gbuffer = res.read(gl.gbuffer);
            std::vector<float>& rgba = res.write(radiosity).rgba;
            const size_t count = static_cast<size_t>(points.count);
            if (count == 0) return;
            cl::CommandQueue& queue = cl_.queue();
            // The points' shading normals (the G-buffer's), with the points.
            if (gbuffer.version != normalsOf_) {
                const std::vector<float> all = gbuffer.target->readRGBA(1);
                std::vector<float> normals(count * 4, 0.0f);
                for (size_t k = 0; k < count; ++k)
                    std::copy_n(&all[static_cast<size_t>(points.pixel[k]) * 4], 3, &normals[k * 4]);
                queue.enqueueWriteBuffer(normals_.reserve(cl_.context(), count * 16), CL_TRUE, 0,
                                         count * 16, normals.data());
                normalsOf_ = gbuffer.version;
            }
            // The scatter views, with the views: a drawn one's positions
            // then normals, one from the shadow map its depth alone.
            const std::vector<LightView>& views = *scatter.views;
            if (scatter.version != viewsOf_ || views_.size() != views.size()) {
                views_.resize(views.size());
                for (size_t l = 0; l < views.size(); ++l) {
                    const RenderTarget& target = *views[l].target;
                    std::vector<float> view;
                    if (scatter.depthOnly) {
                        view = target.readDepth();
                    } else {
                        const size_t texels = size_t(target.width()) * size_t(target.height());
                        view.resize(texels * 8);
                        target.readRGBA(0, view.data());
                        target.readRGBA(1, view.data() + texels * 4);
                    }
                    const size_t bytes = view.size() * sizeof(float);
                    queue.enqueueWriteBuffer(views_[l].reserve(cl_.context(), bytes), CL_TRUE, 0,
                                             bytes, view.data());
                }
                viewsOf_ = scatter.version;
            }
            // The points evaluated, the rest interpolated: a plan per view of
            // the surface (the points are the G-buffer's covered pixels).
            const SparseGrid grid = sparseGridFor(pixelMm(ctx.scene->camera, ctx.height),
                                                  kScatterGridMfp * mediaMeanFreePath(ctx), 0);
            const uint64_t planKey =
                Hasher(gbuffer.version).add(grid.stride).add(grid.maxCornerMm).digest();
            if (planKey != planKey_) {
                plan_ = planSparsePixels(points.pixel, points.host, ctx.width, ctx.height,
                                         grid.stride, grid.maxCornerMm);
                interpolation_.upload(plan_);
                planKey_ = planKey;
            }
            const int evaluated = static_cast<int>(plan_.evaluate.size());
            // Each medium's coefficients (tag − 1 indexes them).
            const SceneMedia& sm = *ctx.media;
            std::vector<TsisScatterMedium> media;
            for (size_t m = 0; m < sm.etaOfMedium.size(); ++m)
                media.push_back(scatterMedium(sm.slotMedium(*ctx.scene, sm.slotOfMedium[m]),
                                              ctx.options->exit));
            const size_t mediaBytes = media.size() * sizeof(TsisScatterMedium);
            cl::Buffer& mediaBuffer = media_.reserve(cl_.context(), mediaBytes);
            queue.enqueueWriteBuffer(mediaBuffer, CL_TRUE, 0, mediaBytes, media.data());
            cl::Buffer& out = out_.reserve(cl_.context(), count * 16);
            const cl_float4 eye = {{ctx.eye.x, ctx.eye.y, ctx.eye.z, 0.0f}};
            for (size_t l = 0; l < views.size(); ++l) {
                const glm::mat4 toWorld = glm::inverse(views[l].viewProj);
                cl_float16 to;
                std::copy_n(glm::value_ptr(toWorld), 16, to.s);
                cl::Kernel& kernel = scatter.depthOnly ? fromDepth_ : drawn_;
                setKernelArgs(kernel, points.xyz, normals_.buffer, interpolation_.order(),
                              evaluated, eye, mediaBuffer, static_cast<int>(media.size()),
                              lightMapInfo(views[l], views[l].resolution),
                              scatterLight(views[l].light), views_[l].buffer, to,
                              kSingleScatterStrata, l > 0 ? 1 : 0, out);
                // TSIS_SCATTER_LANES points an item; small groups, so both
                // cores get a share of a few thousand points.
                enqueue1D(
                    queue, kernel,
                    static_cast<size_t>(evaluated + TSIS_SCATTER_LANES - 1) / TSIS_SCATTER_LANES,
                    16, nullptr);
            }
            interpolation_.run(out);
            std::vector<float> b1(count * 4);
            queue.enqueueReadBuffer(out, CL_TRUE, 0, count * 16, b1.data());
            for (size_t k = 0; k < count; ++k)
                for (int c = 0; c < 3; ++c)
                    rgba[static_cast<size_t>(points.pixel[k]) * 4 + static_cast<size_t>(c)] +=
                        b1[k * 4 + static_cast<size_t>(c)];
            res.stats().set("single_scatter_strata", kSingleScatterStrata);
            res.stats().set("single_scatter_stride", grid.stride);
            res.stats().set("single_scatter_evaluated", evaluated);
        });
}

}  // namespace tsis
