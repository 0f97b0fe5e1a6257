// lss, Mertens et al. 2003, as a baseline.
//
// Per covered pixel xo, --samples = M samples on the image plane:
//   * radius r_k (mm) by importance of Rd on the plane: u_k = (k + ξ)/M through
//     the inverse CDF of the equal mixture of the channels' Rd_c(r)·2πr
//     (RadialImportance::inverseTable, up to the object's diameter);
//   * direction k of a golden-angle spiral, rotated by φ;
//   * (ξ, φ) hashed from (pixel, --seed): deterministic for a seed, decorrelated
//     between pixels;
//   * r_k mm become r_k / s_o pixels, s_o = 2·d_o·tan(fov/2)/H the size of a
//     pixel at xo's depth d_o; the sample takes the nearest pixel's position and
//     E (samples off the image or off the object add nothing);
//   * its weight is the surface area that pixel covers, (2·tan(fov/2)/H)²·d³/ρ
//     / max(|n·ω|, kMinCos), over the area a sample stands for, p(r)·s_o².
// Light that reaches the object where the camera does not see it is missed —
// the known blind spot of the method, kept.
#include "render/method_lss.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "cl/launch.h"
#include "util/error.h"
#include "util/timer.h"

namespace tsis {
LssMethod::LssMethod(ClRuntime& cl, int lanes)
    : cl_(cl),
      prepare_(cl.kernel("lss.cl", "tsis_lss_prepare")),
      gather_(cl.kernel("lss.cl", "tsis_lss_gather", "-DTSIS_LSS_LANES=" + std::to_string(lanes))) {
    TSIS_CHECK(lanes == 1 || lanes == 8);
}

TsisCamera LssMethod::camera(const Camera& c, int height) {
    const glm::vec3 f = glm::normalize(c.target - c.eye);
    TsisCamera cam{};
    cam.ex = c.eye.x;
    cam.ey = c.eye.y;
    cam.ez = c.eye.z;
    cam.pixel_angle =
        2.0f * std::tan(0.5f * glm::radians(c.fovYDegrees)) / static_cast<float>(height);
    cam.fx = f.x;
    cam.fy = f.y;
    cam.fz = f.z;
    cam.min_cos = kMinCos;
    return cam;
}

void LssMethod::updateTables(const FrameContext& ctx) {
    const double rMax = ctx.maxDistance();
    Timer t;
    const KeyedProfile rd = ctx.profile();
    if (table_.update(rd, rMax)) {
        std::vector<float> radii = RadialImportance(rd.f, rMax).inverseTable(kRadiusEntries);
        radii_ = cl::Buffer(cl_.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                            radii.size() * sizeof(float), radii.data());
        ctx.stats->addStage("lss_tables", t.ms());
    }
    const int m = ctx.options->samples;
    if (m != dirsCount_) {
        // Golden-angle spiral: any prefix of it covers the circle evenly.
        const double golden = M_PI * (3.0 - std::sqrt(5.0));
        // Padded with zeros to whole vectors of 8 (the kernel reads 8 at a time).
        std::vector<cl_float2> dirs(roundUp(static_cast<size_t>(m), 8), cl_float2{{0.0f, 0.0f}});
        for (int k = 0; k < m; ++k)
            dirs[static_cast<size_t>(k)] = {{static_cast<float>(std::cos(golden * k)),
                                             static_cast<float>(std::sin(golden * k))}};
        dirs_ = cl::Buffer(cl_.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                           dirs.size() * sizeof(cl_float2), dirs.data());
        dirsCount_ = m;
    }
}

void LssMethod::addPasses(FrameGraph& graph, const FrameContext& ctx) {
    const auto surface = graph.create<Marker>("lss_surface");
    graph.addPass(
        "lss_prepare",
        [&](FrameGraph::Builder& b) {
            b.read(ctx.gbuffer);
            b.write(surface);
        },
        [this, &ctx](FrameGraph::Resources& res) {
            updateTables(ctx);
            const size_t pixels = static_cast<size_t>(ctx.width) * ctx.height;
            const CameraBuffersCl& g = res.read(ctx.gbuffer);
            setKernelArgs(prepare_, g.position, g.normal, g.irradiance, static_cast<cl_int>(pixels),
                          camera(ctx.scene->camera, ctx.height),
                          pos_.reserve(cl_.context(), pixels * 16),
                          ea_.reserve(cl_.context(), pixels * 16));
            cl::Event e;
            enqueue1D(cl_.queue(), prepare_, pixels, kLocalSize, &e);
            res.setDeviceMs(eventMilliseconds(e));
        });
    graph.addPass(
        "lss_gather",
        [&](FrameGraph::Builder& b) {
            b.read(surface);
            b.read(ctx.points);
            b.write(ctx.radiosity);
        },
        [this, &ctx](FrameGraph::Resources& res) {
            const SurfacePoints& points = res.read(ctx.points);
            cl::Buffer& out = ctx.radiosityBuffer(res, points.count);
            const int count = points.count;
            const int m = ctx.options->samples;
            res.stats().set("rd_evaluations", static_cast<double>(count) * m);
            if (count == 0) return;
            Timer t;
            const size_t bytes = static_cast<size_t>(count) * sizeof(cl_int);
            cl::Buffer& pixels = pixels_.reserve(cl_.context(), bytes);
            cl_.queue().enqueueWriteBuffer(pixels, CL_TRUE, 0, bytes, points.pixel.data());
            res.stats().addStage("lss_upload", t.ms(), static_cast<long long>(bytes));
            setKernelArgs(gather_, pixels, static_cast<cl_int>(count), pos_.buffer, ea_.buffer,
                          static_cast<cl_int>(ctx.width), static_cast<cl_int>(ctx.height), dirs_,
                          static_cast<cl_int>(m), radii_, static_cast<cl_int>(kRadiusEntries),
                          table_.device(cl_.context()), table_.table().info,
                          camera(ctx.scene->camera, ctx.height),
                          static_cast<cl_uint>(frameSeed(ctx)), out);
            cl::Event e;
            enqueue1D(cl_.queue(), gather_, static_cast<size_t>(count), kLocalSize, &e);
            res.setDeviceMs(eventMilliseconds(e));
        });
}

}  // namespace tsis
