// tsm, Dachsbacher & Stamminger 2003, as a baseline.
//
// Each light's view holds the flux that lands in every texel (docs/design.md §2) and
// the surface position there. For xo, per light:
//   * project xo into the map; the filter radius R (mm) is --tsm-radius / σtr
//     of the widest channel (default 2: the best of 1–4 on the sphere and the
//     torus against the reference), at most the object's bounding radius (a
//     wider disk only adds taps off the object, into which the coarse mip
//     levels they read smear light); R / texel in texels, the texel's size
//     taken at xo's depth along the light's axis;
//   * 21 taps in a fixed pattern around the projection; tap k stands for the
//     texels of its footprint F_k and reads, bilinearly, the mip level of sums
//     whose cells are half the footprint's side (so the bilinear tent spans
//     about the footprint): Φ_k = (mean flux per texel there) · F_k, and x_k
//     the luminance-weighted centroid of that flux;
//   * B(xo) += Φ_k · Rd̄_ring(k)(Δz_k), with Δz_k = |(x_k − xo)·l| the depth
//     offset along the light's direction of travel l, taken in 3D from the
//     stored positions (so light entering the far side of a thin part reaches
//     xo through its thickness), and Rd̄_j(Δz) the mean of Rd(√(ρ² + Δz²)) over
//     ring j's annulus of the plane (annulusMean).
// The ring mean instead of Rd at the tap's own distance: a tap stands for a
// whole footprint, and Rd is far from flat over it — for marble, Rd(0) is 2×
// (red) to 2.8× (blue) its mean over a centre disk of radius 0.56 mm, 5.5–8.9×
// over 1.3 mm, so a point value would overstate the local term that much.
//
// The pattern (their paper: a fixed pattern of 21 samples; these positions and
// weights are ours). Rings at 0, R/8, R/4, R/2, R: widths double outwards as Rd
// falls, so 13 of the 21 taps lie within R/2. A tap sits at its sector's
// area-median radius √((a² + b²)/2); successive rings are turned by half a
// sector so no two taps line up radially.
//   ring  annulus (R)   taps  radius (R)  angles              footprint each (R²)
//   0     0 … 1/8       1     0           —                   π/64      = 0.0491
//   1     1/8 … 1/4     4     0.1976      45° + 90°·i          3π/256    = 0.0368
//   2     1/4 … 1/2     8     0.3953      22.5° + 45°·i        3π/128    = 0.0736
//   3     1/2 … 1       8     0.7906      45°·i                3π/32     = 0.2945
// The footprints tile the disk (they sum to π R²), so a uniformly lit plane
// gets E·∫_{ρ≤R} Rd dA exactly.
#include "render/method_tsm.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "cl/launch.h"
#include "physics/dipole.h"
#include "physics/profile_table.h"
#include "render/light_map_info.h"
#include "render/profiles.h"
#include "util/error.h"
#include "util/timer.h"

namespace tsis {
namespace {

constexpr size_t kLocal2D = 8;
constexpr int kTapsPerRing[TsmMethod::kRings] = {1, 4, 8, 8};
constexpr double kRingTurn[TsmMethod::kRings] = {0.0, 0.5, 0.5, 0.0};  // in sectors

}  // namespace

TsmMethod::TsmMethod(ClRuntime& cl)
    : cl_(cl),
      level0_(cl.kernel("tsm.cl", "tsis_tsm_level0")),
      reduce_(cl.kernel("tsm.cl", "tsis_tsm_reduce")),
      filter_(cl.kernel("tsm.cl", "tsis_tsm_filter")) {
    std::vector<TsisTsmTap> taps = pattern();
    taps_ = cl::Buffer(cl.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                       taps.size() * sizeof(TsisTsmTap), taps.data());
}

std::vector<TsisTsmTap> TsmMethod::pattern() {
    std::vector<TsisTsmTap> taps;
    for (int j = 0; j < kRings; ++j) {
        const double a = kRingEdges[j], b = kRingEdges[j + 1];
        const int n = kTapsPerRing[j];
        const double radius = j == 0 ? 0.0 : std::sqrt(0.5 * (a * a + b * b));
        for (int i = 0; i < n; ++i) {
            const double angle = 2.0 * std::numbers::pi * (i + kRingTurn[j]) / n;
            taps.push_back({static_cast<float>(radius * std::cos(angle)),
                            static_cast<float>(radius * std::sin(angle)),
                            static_cast<float>(std::numbers::pi * (b * b - a * a) / n),
                            static_cast<float>(j)});
        }
    }
    return taps;
}

double TsmMethod::filterRadiusMm(const Material& m, double transportLengths, double limit) {
    const glm::dvec3 sigmaTr = Dipole(m).sigmaTr();
    const double widest = std::min({sigmaTr.x, sigmaTr.y, sigmaTr.z});
    return std::min(transportLengths / widest, limit);
}

glm::dvec3 TsmMethod::annulusMean(const RadialImportance& rd, double a, double b, double z) {
    TSIS_CHECK(a >= 0.0 && b > a);
    const glm::dvec3 inner = rd.mass(std::sqrt(a * a + z * z));
    const glm::dvec3 outer = rd.mass(std::sqrt(b * b + z * z));
    return (outer - inner) / (std::numbers::pi * (b * b - a * a));
}

void TsmMethod::updateTables(const FrameContext& ctx) {
    const double diameter = ctx.maxDistance();
    const double radius = filterRadiusMm(*ctx.material, ctx.options->tsmRadius, ctx.boundingRadius);
    const KeyedProfile rd = ctx.profile();
    const std::string key = exactKey(rd.key + " R z", {radius, diameter});
    if (key == tableKey_) return;
    Timer t;
    // Depth offsets up to the diameter; the mass up to the farthest annulus edge.
    const RadialImportance mass(rd.f, std::hypot(radius, diameter) * 1.001);
    std::vector<float> rgba;
    for (int j = 0; j < kRings; ++j) {
        const double a = kRingEdges[j] * radius, b = kRingEdges[j + 1] * radius;
        ProfileTable table =
            ProfileTable::build([&](double z) { return annulusMean(mass, a, b, z); }, diameter);
        ringInfo_ = table.info;
        rgba.insert(rgba.end(), table.rgba.begin(), table.rgba.end());
    }
    rings_ = cl::Buffer(cl_.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                        rgba.size() * sizeof(float), rgba.data());
    radiusMm_ = radius;
    tableKey_ = key;
    ctx.stats->addStage("tsm_tables", t.ms());
}

double TsmMethod::buildPyramids(const FrameContext& ctx, const LightMapsCl& maps) {
    const int res = ctx.lightResolution;
    const size_t lights = maps.flux.size();
    TSIS_CHECK_EQ(lights, maps.views->size());
    levelsHost_.clear();
    int cells = 0;
    for (int w = res, h = res;; w = (w + 1) / 2, h = (h + 1) / 2) {
        levelsHost_.push_back({{cells, w, h, 0}});
        cells += w * h;
        if (w == 1 && h == 1) break;
    }
    levels_ = cl::Buffer(cl_.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                         levelsHost_.size() * sizeof(cl_int4), levelsHost_.data());
    const size_t bytes = static_cast<size_t>(cells) * sizeof(cl_float4);
    if (F_.size() != lights || pyramidBytes_ < bytes) {
        F_.clear();
        P_.clear();
        for (size_t l = 0; l < lights; ++l) {
            F_.emplace_back(cl_.context(), CL_MEM_READ_WRITE, bytes);
            P_.emplace_back(cl_.context(), CL_MEM_READ_WRITE, bytes);
        }
        pyramidBytes_ = bytes;
    }
    cl::CommandQueue& q = cl_.queue();
    std::vector<cl::Event> events;
    for (size_t l = 0; l < lights; ++l) {
        setKernelArgs(level0_, maps.flux[l], maps.position[l], static_cast<cl_int>(res * res),
                      F_[l], P_[l]);
        events.emplace_back();
        enqueue1D(q, level0_, static_cast<size_t>(res) * res, kLocalSize, &events.back());
        for (size_t k = 1; k < levelsHost_.size(); ++k) {
            const cl_int4& src = levelsHost_[k - 1];
            const cl_int4& dst = levelsHost_[k];
            setKernelArgs(reduce_, F_[l], P_[l], src.s[0], src.s[1], src.s[2], dst.s[0], dst.s[1],
                          dst.s[2]);
            events.emplace_back();
            q.enqueueNDRangeKernel(reduce_, cl::NullRange,
                                   cl::NDRange(roundUp(static_cast<size_t>(dst.s[1]), kLocal2D),
                                               roundUp(static_cast<size_t>(dst.s[2]), kLocal2D)),
                                   cl::NDRange(kLocal2D, kLocal2D), nullptr, &events.back());
        }
    }
    return eventMilliseconds(events);
}

double TsmMethod::filter(const FrameContext& ctx, const LightMapsCl& maps,
                         const SurfacePoints& points, cl::Buffer& out, FrameStats& stats) {
    const int count = points.count;
    const int taps = static_cast<int>(pattern().size());
    const size_t lights = maps.views->size();
    stats.set("rd_evaluations", static_cast<double>(count) * taps * static_cast<double>(lights));
    std::vector<cl::Event> events;
    for (size_t l = 0; l < lights && count > 0; ++l) {
        const LightView& lv = (*maps.views)[l];
        const bool point = lv.light.type == Light::Type::Point;
        const glm::vec3 s = point ? lv.light.vec : glm::normalize(lv.light.vec);
        setKernelArgs(
            filter_, points.xyz, static_cast<cl_int>(count), lightMapInfo(lv, ctx.lightResolution),
            cl_float4{{s.x, s.y, s.z, point ? 1.0f : 0.0f}}, F_[l], P_[l], levels_,
            static_cast<cl_int>(levelsHost_.size()), taps_, static_cast<cl_int>(taps), rings_,
            ringInfo_, static_cast<cl_float>(radiusMm_), static_cast<cl_int>(l > 0), out);
        events.emplace_back();
        enqueue1D(cl_.queue(), filter_, static_cast<size_t>(count), kLocalSize, &events.back());
    }
    return eventMilliseconds(events);
}

void TsmMethod::addPasses(FrameGraph& graph, const FrameContext& ctx) {
    const auto pyramid = graph.create<Marker>("tsm_pyramid");
    graph.addPass(
        "tsm_pyramid",
        [&](FrameGraph::Builder& b) {
            b.read(ctx.lightMaps);
            b.write(pyramid);
        },
        [this, &ctx](FrameGraph::Resources& res) {
            updateTables(ctx);
            res.setDeviceMs(buildPyramids(ctx, res.read(ctx.lightMaps)));
        });
    graph.addPass(
        "tsm_filter",
        [&](FrameGraph::Builder& b) {
            b.read(pyramid);
            b.read(ctx.lightMaps);
            b.read(ctx.points);
            b.write(ctx.radiosity);
        },
        [this, &ctx](FrameGraph::Resources& res) {
            const SurfacePoints& points = res.read(ctx.points);
            res.setDeviceMs(filter(ctx, res.read(ctx.lightMaps), points,
                                   ctx.radiosityBuffer(res, points.count), res.stats()));
        });
}

}  // namespace tsis
