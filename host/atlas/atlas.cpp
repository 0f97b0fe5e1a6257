// buildAtlas: segmentation, charts, packing, output mesh (see atlas.h).
#include "atlas/atlas.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <deque>
#include <thread>

#include "atlas/cache.h"
#include "atlas/chart.h"
#include "atlas/pack.h"
#include "util/error.h"
#include "util/progress.h"
#include "util/timer.h"

namespace tsis {

namespace {

// Stand-in segmentation when CGAL cannot make a polygon mesh of the soup:
// breadth-first patches of about `size` faces.
std::vector<int> patchLabels(const atlas::Adjacency& adj, int size) {
    const size_t n = adj.across.size();
    std::vector<int> labels(n, -1);
    int next = 0;
    for (size_t s = 0; s < n; ++s) {
        if (!adj.usable[s] || labels[s] >= 0) continue;
        std::deque<int> queue{int(s)};
        labels[s] = next;
        int count = 1;
        while (!queue.empty() && count < size) {
            const int f = queue.front();
            queue.pop_front();
            for (int g : adj.across[f])
                if (g >= 0 && labels[g] < 0 && count < size) {
                    labels[g] = next;
                    ++count;
                    queue.push_back(g);
                }
        }
        ++next;
    }
    return labels;
}

void validateInput(const Mesh& mesh, const AtlasOptions& opt) {
    if (mesh.triangles.empty()) fail(mesh.name, ": no triangles to make an atlas of");
    if (opt.resolution < 16 || opt.resolution > 32768)
        fail("atlas: resolution ", opt.resolution, " is outside 16..32768");
    if (opt.gutterTexels < 0 || opt.gutterTexels > opt.resolution / 8)
        fail("atlas: gutter of ", opt.gutterTexels, " texels does not suit resolution ",
             opt.resolution);
    for (const glm::vec3& p : mesh.positions)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            fail(mesh.name, ": a vertex position is not finite");
    for (const glm::uvec3& t : mesh.triangles)
        if (t.x >= mesh.positions.size() || t.y >= mesh.positions.size() ||
            t.z >= mesh.positions.size())
            fail(mesh.name, ": a triangle refers to a missing vertex");
    if (mesh.hasNormals() && mesh.normals.size() != mesh.positions.size())
        fail(mesh.name, ": ", mesh.normals.size(), " normals for ", mesh.positions.size(),
             " vertices");
    if (mesh.hasTexcoords() && mesh.texcoords.size() != mesh.positions.size())
        fail(mesh.name, ": ", mesh.texcoords.size(), " texture coordinates for ",
             mesh.positions.size(), " vertices");
    if (!mesh.materialIds.empty() && mesh.materialIds.size() != mesh.triangles.size())
        fail(mesh.name, ": ", mesh.materialIds.size(), " material ids for ", mesh.triangles.size(),
             " triangles");
}

}  // namespace

namespace atlas {

// Charts longer than this times their width are cut (see splitElongatedCharts):
// at 3, coverage at 1024² rises from 0.61-0.72 to 0.66-0.76 on the data meshes.
constexpr double kMaxChartAspect = 3;

// Widest filter of chart borders (vertex rings; see smoothLabels). Armadillo
// subdivided to 832K triangles (radius 3) packs to 0.678 instead of 0.624 at
// 1024²; the radius is capped for speed (the filter visits ~6·radius² faces
// per border face).
constexpr int kMaxBorderRadius = 3;

// Segmentation of a mesh with at least kParallelSegmentFaces usable faces runs
// in parts of about kSegmentPartFaces (2 to 16; segmentVSA), in parallel: VSA
// is single-threaded and was half of a 1.2M-triangle scan's build. The part
// count follows the mesh, not the thread count, so that an atlas (and the
// cache entry it is stored under) is the same on any machine. The noisy scan
// (1.2M triangles) in 2, 4 and 8 parts: 2127, 2018 and 2045 charts (whole:
// 2190), coverage 0.60 each; in 8 parts on 2 cores VSA takes half the CPU
// time and a third of the wall time (bench/results/atlas_build.md).
constexpr size_t kParallelSegmentFaces = 200000;
constexpr size_t kSegmentPartFaces = 150000;
constexpr int kMaxSegmentParts = 16;
int segmentParts(size_t usable) {
    if (usable < kParallelSegmentFaces) return 1;
    return std::clamp(int(usable / kSegmentPartFaces), 2, kMaxSegmentParts);
}

Mesh buildAtlasWithSources(const Mesh& mesh, const AtlasOptions& opt, AtlasStats* stats,
                           std::vector<uint32_t>* sourceVertex) {
    const Timer timer;
    validateInput(mesh, opt);
    const Adjacency adj = buildAdjacency(mesh);
    const size_t usable = size_t(std::count(adj.usable.begin(), adj.usable.end(), 1));
    if (usable == 0) fail(mesh.name, ": every triangle is degenerate (no area)");

    const double resScale = std::max(1.0, double(opt.resolution) / 1024.0);
    const size_t cap = size_t(std::max(1.0, opt.maxProxies * resScale * resScale));
    const size_t wanted = usable / size_t(std::max(1, opt.trianglesPerProxy));
    const int proxies = std::max(opt.minProxies, int(std::min(wanted, cap)));
    // Faces per chart that segmentation aims at: trianglesPerProxy unless the
    // cap made charts bigger.
    const int facesPerProxy =
        std::max(std::max(1, opt.trianglesPerProxy), int(usable / size_t(std::max(1, proxies))));
    // TSIS_ATLAS_DEBUG=1: wall and process CPU seconds after each stage on stderr.
    const bool debug = std::getenv("TSIS_ATLAS_DEBUG") != nullptr;
    auto stage = [&](const char* name) {
        if (!debug) return;
        timespec ts;
        clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
        std::fprintf(stderr, "atlas %s: %.2f s (cpu %.2f s)\n", name, timer.ms() / 1000,
                     ts.tv_sec + 1e-9 * ts.tv_nsec);
    };
    // One progress line for the whole build: segmentation (CGAL, no progress of
    // its own) to 40%, charts to 90%, packing and the output mesh to 100%.
    Progress progress("atlas", 1000);
    // Segmentation and flattening see the smoothed copy of a noisy scan
    // (smooth.cpp); the output keeps the mesh's own positions.
    int smoothing = 0;
    const std::optional<Mesh> smoothed = smoothedForCharting(mesh, adj, &smoothing);
    const Mesh& shape = smoothed ? *smoothed : mesh;
    if (debug) std::fprintf(stderr, "atlas smoothing: %d λ|μ steps\n", smoothing);
    stage("shape");
    const int threads = opt.threads > 0 ? opt.threads : int(std::thread::hardware_concurrency());
    const int parts = segmentParts(usable);
    if (debug) std::fprintf(stderr, "atlas segmentation: %d parts\n", parts);
    std::vector<int> labels = segmentVSA(shape, adj, proxies, parts, threads);
    stage("segmented");
    progress.update(400);
    if (labels.empty()) labels = patchLabels(adj, facesPerProxy);
    // Under the cap, charts hold more faces than trianglesPerProxy and VSA
    // leaves their borders jagged over several triangles: straightened over
    // about √(facesPerProxy / trianglesPerProxy) rings.
    int borderRadius = 0;
    if (wanted > cap) {
        const double finer = double(facesPerProxy) / std::max(1, opt.trianglesPerProxy);
        borderRadius = std::clamp(int(std::lround(std::sqrt(finer))), 1, kMaxBorderRadius);
    }
    smoothLabels(shape, adj, labels, std::max(1, facesPerProxy / 10), borderRadius);
    stage("labels smoothed");

    ChartOptions copt;
    copt.maxDistortion = opt.maxChartDistortion;
    copt.threads = opt.threads;
    copt.onProgress = [&](double f) { progress.update(400 + (long long)(500 * f)); };
    std::vector<Chart> charts = makeCharts(shape, adj, labels, copt);
    stage("charts parameterised");
    if (debug) std::fprintf(stderr, "atlas charts: %zu\n", charts.size());
    splitElongatedCharts(charts, kMaxChartAspect);
    if (debug) std::fprintf(stderr, "atlas charts after elongation splits: %zu\n", charts.size());

    std::vector<PackChart> packIn;
    packIn.reserve(charts.size());
    for (const Chart& c : charts) packIn.push_back({&c.uv, &c.mesh.triangles});
    const PackResult packed = packCharts(packIn, opt.resolution, opt.gutterTexels, threads);
    stage("packed");
    progress.update(950);

    // Output vertices: one per (chart, chart vertex), numbered in the order the
    // triangles first use them; degenerate triangles get their own vertices
    // parked on one UV point.
    struct Where {
        int chart = -1, tri = -1;
    };
    std::vector<Where> where(mesh.triangles.size());
    std::vector<size_t> base(charts.size() + 1, 0);
    for (size_t c = 0; c < charts.size(); ++c) {
        for (size_t i = 0; i < charts[c].mesh.faces.size(); ++i)
            where[charts[c].mesh.faces[i]] = {int(c), int(i)};
        base[c + 1] = base[c] + charts[c].mesh.positions.size();
    }
    std::vector<int64_t> outOf(base.back(), -1);
    std::vector<int64_t> firstCopy(mesh.positions.size(), -1);  // an output vertex per input vertex
    Mesh out;
    out.name = mesh.name;
    out.triangles.resize(mesh.triangles.size());
    std::vector<uint32_t> source;
    auto addVertex = [&](uint32_t src, glm::dvec2 uv) {
        source.push_back(src);
        out.uvs.emplace_back(glm::vec2(uv));
        if (firstCopy[src] < 0) firstCopy[src] = int64_t(source.size() - 1);
        return uint32_t(source.size() - 1);
    };
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const Where w = where[t];
        if (w.chart < 0) continue;
        const Chart& c = charts[w.chart];
        for (int k = 0; k < 3; ++k) {
            const int local = c.mesh.triangles[w.tri][k];
            int64_t& o = outOf[base[w.chart] + local];
            if (o < 0) o = addVertex(c.mesh.sourceVertex[local], packed.uv[w.chart][local]);
            out.triangles[t][k] = uint32_t(o);
        }
    }
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        if (where[t].chart >= 0) continue;
        const glm::uvec3 tri = mesh.triangles[t];
        glm::dvec2 park(0.5 / opt.resolution);
        for (int k = 0; k < 3; ++k)
            if (firstCopy[tri[k]] >= 0) {
                park = glm::dvec2(out.uvs[size_t(firstCopy[tri[k]])]);
                break;
            }
        if (park == glm::dvec2(0.5 / opt.resolution) && !out.uvs.empty())
            park = glm::dvec2(out.uvs[0]);
        for (int k = 0; k < 3; ++k) out.triangles[t][k] = addVertex(tri[k], park);
    }
    copySourceAttributes(mesh, source, out);
    if (stats) {
        *stats = measureAtlas(out, opt.resolution);
        stats->seconds = timer.ms() / 1000.0;
        stats->fromCache = false;
    }
    progress.finish();
    if (sourceVertex) *sourceVertex = std::move(source);
    return out;
}

}  // namespace atlas

Mesh buildAtlas(const Mesh& mesh, const AtlasOptions& opt, AtlasStats* stats) {
    return atlas::buildAtlasWithSources(mesh, opt, stats, nullptr);
}

}  // namespace tsis
