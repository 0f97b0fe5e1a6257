#include "atlas/atlas.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <sstream>

#include "atlas/cache.h"
#include "atlas/chart.h"
#include "atlas/pack.h"
#include "mesh/mesh_io.h"
#include "mesh/uv_texels.h"
#include "support/atlas_meshes.h"
#include "support/scoped_env.h"
#include "util/error.h"

namespace tsis {
namespace {

using test::ScopedEnv;

// Every output triangle keeps its input corners (same positions, normals
// copied) and has UVs inside the 1-texel margin.
void expectSameSurface(const Mesh& in, const Mesh& out, int resolution) {
    ASSERT_EQ(out.triangles.size(), in.triangles.size());
    ASSERT_EQ(out.uvs.size(), out.positions.size());
    ASSERT_GE(out.positions.size(), in.positions.size());
    if (in.hasNormals()) {
        ASSERT_EQ(out.normals.size(), out.positions.size());
    }
    for (size_t t = 0; t < in.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = in.triangles[t][k], b = out.triangles[t][k];
            ASSERT_LT(b, out.positions.size());
            ASSERT_EQ(out.positions[b], in.positions[a]) << "triangle " << t;
            if (in.hasNormals()) {
                ASSERT_EQ(out.normals[b], in.normals[a]);
            }
        }
    const float lo = 1.0f / float(resolution), hi = 1.0f - lo;
    for (const glm::vec2& uv : out.uvs) {
        ASSERT_GE(uv.x, lo);
        ASSERT_GE(uv.y, lo);
        ASSERT_LE(uv.x, hi);
        ASSERT_LE(uv.y, hi);
    }
}

double pointSegment(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
    const glm::dvec2 d = b - a;
    const double l2 = glm::dot(d, d);
    const double t = l2 > 0 ? std::clamp(glm::dot(p - a, d) / l2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * d));
}

// Smallest distance in texels between UV border edges of different charts
// (charts: triangles connected through shared vertices).
double minChartGap(const Mesh& m, int resolution) {
    UnionFind charts = uvCharts(m);
    std::map<std::pair<uint32_t, uint32_t>, int> count;
    for (const auto& t : m.triangles)
        for (int e = 0; e < 3; ++e)
            ++count[{std::min(t[e], t[(e + 1) % 3]), std::max(t[e], t[(e + 1) % 3])}];
    struct Seg {
        glm::dvec2 a, b;
        uint32_t chart;
    };
    std::vector<Seg> segs;
    for (const auto& [e, c] : count)
        if (c == 1)
            segs.push_back({glm::dvec2(m.uvs[e.first]) * double(resolution),
                            glm::dvec2(m.uvs[e.second]) * double(resolution),
                            charts.find(e.first)});
    // Grid of 4-texel cells; only neighbouring cells can hold pairs closer than 4.
    std::map<std::pair<int, int>, std::vector<size_t>> grid;
    for (size_t i = 0; i < segs.size(); ++i) {
        const glm::dvec2 lo = glm::min(segs[i].a, segs[i].b) / 4.0,
                         hi = glm::max(segs[i].a, segs[i].b) / 4.0;
        for (int y = int(lo.y); y <= int(hi.y); ++y)
            for (int x = int(lo.x); x <= int(hi.x); ++x) grid[{x, y}].push_back(i);
    }
    double best = 4;
    for (const auto& [cell, ids] : grid)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                auto it = grid.find({cell.first + dx, cell.second + dy});
                if (it == grid.end()) continue;
                for (size_t i : ids)
                    for (size_t j : it->second) {
                        const Seg &s = segs[i], &t = segs[j];
                        if (s.chart == t.chart) continue;
                        best = std::min({best, pointSegment(s.a, t.a, t.b),
                                         pointSegment(s.b, t.a, t.b), pointSegment(t.a, s.a, s.b),
                                         pointSegment(t.b, s.a, s.b)});
                    }
            }
    return best;
}

std::filesystem::path scratchDir(const std::string& tag) {
    auto dir = std::filesystem::temp_directory_path() /
               ("tsis_atlas_test_" + tag + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

// Core invariants of a built atlas; its statistics for further checks.
AtlasStats checkAtlas(const Mesh& in, const AtlasOptions& opt) {
    AtlasStats st;
    const Mesh out = buildAtlas(in, opt, &st);
    expectSameSurface(in, out, opt.resolution);
    EXPECT_EQ(st.flipped, 0u);
    EXPECT_EQ(st.overlaps, 0u);
    EXPECT_GT(st.charts, 0);
    // Independent of the build's own statistics: overlaps at 2048² and exact
    // border tests; gutters at the target resolution.
    const AtlasStats fine = measureAtlas(out, 2048);
    EXPECT_EQ(fine.overlaps, 0u);
    EXPECT_EQ(fine.flipped, 0u);
    EXPECT_GE(minChartGap(out, opt.resolution), double(opt.gutterTexels) - 1e-3);
    std::printf("  %s: %d charts, coverage %.3f, r_wstd %.4f, r p1-p99 %.3f-%.3f, %.2f s\n",
                in.name.c_str(), st.charts, st.coverage, st.rWstd, st.rP01, st.rP99, st.seconds);
    return st;
}

// The atlas issue's quality goals, on two of the meshes it names.
TEST(Atlas, CowAndElephant) {
    for (const char* name : {"cow", "elephant"}) {
        const std::string path = test::cgalMesh(name);
        if (path.empty()) GTEST_SKIP() << test::kCgalTarball << " is not installed";
        const Mesh mesh = test::readOFF(path);
        ASSERT_FALSE(mesh.triangles.empty()) << path;
        const AtlasStats st = checkAtlas(mesh, AtlasOptions());
        EXPECT_GE(st.coverage, 0.65) << name;
        EXPECT_LE(st.rWstd, 0.05) << name;
        EXPECT_GE(st.rP01, 0.85) << name;
        EXPECT_LE(st.rP99, 1.2) << name;
    }
}

// A 1 × cells strip of unit squares as one chart (UV = xy).
atlas::Chart stripChart(int cells, uint32_t firstFace) {
    atlas::Chart c;
    for (int i = 0; i <= cells; ++i)
        for (int j = 0; j <= 1; ++j) {
            c.uv.emplace_back(i, j);
            c.mesh.positions.emplace_back(i, j, 0);
            c.mesh.sourceVertex.push_back(uint32_t(c.uv.size() - 1));
        }
    for (int i = 0; i < cells; ++i) {
        const int a = 2 * i, b = 2 * i + 1, d = 2 * i + 2, e = 2 * i + 3;
        c.mesh.triangles.push_back({a, d, e});
        c.mesh.triangles.push_back({a, e, b});
        c.mesh.faces.push_back(firstFace + uint32_t(2 * i));
        c.mesh.faces.push_back(firstFace + uint32_t(2 * i + 1));
    }
    return c;
}

TEST(Atlas, ElongatedChartsAreCutWithUVsKept) {
    std::vector<atlas::Chart> charts{stripChart(12, 0), stripChart(2, 24)};
    atlas::splitElongatedCharts(charts, 3.0);
    std::vector<uint32_t> faces;
    for (const atlas::Chart& c : charts) {
        double lo = INFINITY, hi = -INFINITY;
        for (const auto& t : c.mesh.triangles)
            for (int v : t) {
                EXPECT_EQ(c.uv[v], glm::dvec2(c.mesh.positions[v])) << "UVs moved";
                lo = std::min(lo, c.uv[v].x);
                hi = std::max(hi, c.uv[v].x);
            }
        EXPECT_LE(hi - lo, 3.0);
        faces.insert(faces.end(), c.mesh.faces.begin(), c.mesh.faces.end());
    }
    // 12 long: cut 12 → 6 → 3 (4 pieces); the 2 × 1 chart is left alone.
    EXPECT_EQ(charts.size(), 5u);
    EXPECT_EQ(faces.size(), 24u + 4u);
    std::sort(faces.begin(), faces.end());
    EXPECT_EQ(std::adjacent_find(faces.begin(), faces.end()), faces.end())
        << "a face in two pieces";
}

// Edges between faces of different labels.
size_t borderEdges(const atlas::Adjacency& adj, const std::vector<int>& labels) {
    size_t n = 0;
    for (size_t f = 0; f < labels.size(); ++f)
        for (int g : adj.across[f]) n += g >= 0 && labels[g] != labels[f];
    return n / 2;
}

// Two labels on a tube, their border a square wave 8 rings high and 4 segments
// wide per tooth: the 1-ring filters keep the teeth, a 3-ring border filter
// flattens them and keeps both labels about as large.
TEST(Atlas, BorderFilterStraightensTeeth) {
    const int rings = 40, segments = 64;
    const Mesh tube = test::tubeMesh(rings, segments, 4.0);
    const atlas::Adjacency adj = atlas::buildAdjacency(tube);
    std::vector<int> teeth(tube.triangles.size());
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const int border = rings / 2 + ((s / 4) % 2 ? 4 : -4);
            const size_t i = 2 * (size_t(r) * size_t(segments) + size_t(s));
            teeth[i] = teeth[i + 1] = r < border ? 0 : 1;
        }
    std::vector<int> kept = teeth, straight = teeth;
    atlas::smoothLabels(tube, adj, kept, 20);
    atlas::smoothLabels(tube, adj, straight, 20, 3);
    const size_t before = borderEdges(adj, teeth);
    EXPECT_GE(borderEdges(adj, kept), before * 9 / 10);
    // A border straight around the tube crosses 2·segments triangle edges.
    EXPECT_EQ(borderEdges(adj, straight), size_t(2 * segments));
    const size_t zeros = size_t(std::count(straight.begin(), straight.end(), 0));
    EXPECT_NEAR(double(zeros) / double(straight.size()), 0.5, 0.1);
}

// Connected pieces (across edges) of each value of `labels` (-1 skipped), summed.
size_t pieces(const atlas::Adjacency& adj, const std::vector<int>& labels) {
    UnionFind u{labels.size()};
    for (size_t f = 0; f < labels.size(); ++f)
        for (int g : adj.across[f])
            if (g >= 0 && labels[f] >= 0 && labels[size_t(g)] == labels[f])
                u.unite(uint32_t(f), uint32_t(g));
    size_t n = 0;
    for (size_t f = 0; f < labels.size(); ++f) n += labels[f] >= 0 && u.find(uint32_t(f)) == f;
    return n;
}

// A flat U of 30 × 60 grid cells (arms 10 wide along y, a base 10 high), cut
// in two across y at the median: the upper part is the two arm tips. The tip
// cut off from its part joins the other part, so each part is one piece.
TEST(Atlas, SplitPartsAreConnected) {
    Mesh u;
    u.name = "test:U";
    const int w = 30, h = 60;
    for (int j = 0; j <= h; ++j)
        for (int i = 0; i <= w; ++i) u.positions.emplace_back(i, j, 0);
    auto at = [&](int i, int j) { return unsigned(j * (w + 1) + i); };
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            if (j < 10 || i < 10 || i >= 20) {
                u.triangles.emplace_back(at(i, j), at(i + 1, j), at(i + 1, j + 1));
                u.triangles.emplace_back(at(i, j), at(i + 1, j + 1), at(i, j + 1));
            }
    const atlas::Adjacency adj = atlas::buildAdjacency(u);
    const std::vector<int> part = atlas::splitFaces(u, adj, 2);
    EXPECT_EQ(std::count(part.begin(), part.end(), -1), 0);
    EXPECT_EQ(pieces(adj, part), 2u);
    // The upper half is the two tips; one of them is left (a quarter of the faces).
    EXPECT_EQ(size_t(std::count(part.begin(), part.end(), 1)), u.triangles.size() / 4);

    // A sphere in 4: parts of about equal size, each one piece.
    const Mesh sphere = test::sphereMesh(60, 120);
    const atlas::Adjacency sadj = atlas::buildAdjacency(sphere);
    const std::vector<int> quarters = atlas::splitFaces(sphere, sadj, 4);
    EXPECT_EQ(pieces(sadj, quarters), 4u);
    for (int p = 0; p < 4; ++p)
        EXPECT_NEAR(double(std::count(quarters.begin(), quarters.end(), p)),
                    double(sphere.triangles.size()) / 4, 0.02 * double(sphere.triangles.size()))
            << p;
}

// Segmentation in 4 parts (as a big mesh is segmented, kParallelSegmentFaces
// in atlas.cpp): the same labels on 1, 2 or 4 threads and run after run;
// labels unique across parts and about as many, as connected and, once
// smoothed, with about as long borders as the whole mesh segmented at once.
TEST(Atlas, SegmentationInPartsIsDeterministicAndAsGood) {
    const Mesh sphere = test::sphereMesh(100, 200);
    const atlas::Adjacency adj = atlas::buildAdjacency(sphere);
    const int proxies = 40, parts = 4;
    std::vector<int> whole = atlas::segmentVSA(sphere, adj, proxies);
    std::vector<int> parted = atlas::segmentVSA(sphere, adj, proxies, parts, 2);
    ASSERT_EQ(parted.size(), sphere.triangles.size());
    EXPECT_EQ(parted, atlas::segmentVSA(sphere, adj, proxies, parts, 1));
    EXPECT_EQ(parted, atlas::segmentVSA(sphere, adj, proxies, parts, 4));
    EXPECT_EQ(parted, atlas::segmentVSA(sphere, adj, proxies, parts, 2));

    const std::vector<int> part = atlas::splitFaces(sphere, adj, parts);
    std::map<int, int> partOf;  // label -> its part
    for (size_t f = 0; f < parted.size(); ++f) {
        ASSERT_GE(parted[f], 0);
        const auto [it, fresh] = partOf.emplace(parted[f], part[f]);
        EXPECT_EQ(it->second, part[f]) << "label " << parted[f] << " in two parts";
    }
    const std::set<int> wholeLabels(whole.begin(), whole.end());
    EXPECT_NEAR(double(partOf.size()), double(wholeLabels.size()), 0.1 * proxies);
    EXPECT_LE(double(pieces(adj, parted)), 1.1 * double(partOf.size()));
    const int minFaces = int(sphere.triangles.size()) / proxies / 10;
    atlas::smoothLabels(sphere, adj, whole, minFaces, 1);
    atlas::smoothLabels(sphere, adj, parted, minFaces, 1);
    std::printf("  whole: %zu pieces, %zu border edges; in %d parts: %zu pieces, %zu edges\n",
                pieces(adj, whole), borderEdges(adj, whole), parts, pieces(adj, parted),
                borderEdges(adj, parted));
    EXPECT_LE(double(borderEdges(adj, parted)), 1.15 * double(borderEdges(adj, whole)));
}

// Many triangles under a small proxy cap (charts of ~2000 faces, the border
// filter at radius 3), as a big scan is built.
TEST(Atlas, FineMeshUnderTheProxyCap) {
    AtlasOptions opt;
    opt.maxProxies = 20;
    const Mesh sphere = test::sphereMesh(100, 200);
    ASSERT_GT(sphere.triangles.size() / size_t(opt.trianglesPerProxy), size_t(opt.maxProxies));
    const AtlasStats st = checkAtlas(sphere, opt);
    EXPECT_GE(st.coverage, 0.65);
    EXPECT_LE(st.rWstd, 0.05);
}

// A noisy scan: a sphere whose vertices move radially by up to ±80 % of an
// edge (hashed, deterministic; median angle between neighbouring faces 32°).
// Charted as it is, its pieces neither segment nor flatten cleanly: 3,559
// charts, coverage 0.32 at 512², 39 s; charted on its smoothed copy (the
// output keeps the noisy positions): 530 charts, coverage 0.60, 2.6 s. The
// area ratio spreads (r p1–p99 0.65–5.9): texel density follows the smoothed
// surface, and each texel carries its own area.
TEST(Atlas, NoisyScanIsChartedOnItsSmoothedShape) {
    Mesh noisy = test::sphereMesh(100, 200);
    noisy.name = "test:noisy sphere";
    const double edge = 2 * 3.14159265358979323846 / 200;
    uint32_t h = 12345;
    for (glm::vec3& p : noisy.positions) {
        h = h * 1664525u + 1013904223u;
        const double u = double(h >> 8) / double(1u << 24);  // [0, 1)
        p *= float(1 + 0.8 * edge * (2 * u - 1));
    }
    const atlas::Adjacency adj = atlas::buildAdjacency(noisy);
    EXPECT_GT(atlas::medianDihedralDegrees(noisy, adj), atlas::kRoughDihedralDegrees);
    EXPECT_GE(atlas::concaveShareOfSharpEdges(noisy, adj), atlas::kMinConcaveShare);
    int iterations = 0;
    const std::optional<Mesh> shape = atlas::smoothedForCharting(noisy, adj, &iterations);
    ASSERT_TRUE(shape);
    EXPECT_GT(iterations, 0);
    EXPECT_LE(atlas::medianDihedralDegrees(*shape, adj), atlas::kSmoothDihedralDegrees);
    AtlasOptions opt;
    opt.resolution = 512;
    const AtlasStats st = checkAtlas(noisy, opt);
    EXPECT_GE(st.coverage, 0.5);
    EXPECT_LE(st.charts, 4 * opt.maxProxies);
    // A clean mesh is charted as it is.
    const Mesh clean = test::sphereMesh(100, 200);
    const atlas::Adjacency cleanAdj = atlas::buildAdjacency(clean);
    EXPECT_FALSE(atlas::smoothedForCharting(clean, cleanAdj, &iterations));
    EXPECT_EQ(iterations, 0);
}

// Boxes, slabs and low-poly solids have a high median angle between faces
// (90° on a box) without being noisy: they are charted as they are, every
// face at one density. Smoothed, the 2 mm slab became a pillow whose faces
// mapped to strips (coverage 0.017).
TEST(Atlas, BoxesAndBlocksAreNotScans) {
    // A bar's sides are triangles as long as the bar (charts are cut between
    // triangles, never through one): they bound its scale.
    struct Solid {
        const char* what;
        Mesh mesh;
        double minCoverage;
    };
    const std::vector<Solid> solids = {
        {"cube", test::boxMesh(1, 1, 1), 0.3},
        {"slab 20x20x2", test::boxMesh(20, 20, 2), 0.3},
        {"bar 1x1x10", test::boxMesh(1, 1, 10), 0.12},
        {"plank 10x0.5x3", test::boxMesh(10, 0.5f, 3), 0.3},
        {"sheet 30x30x0.2", test::boxMesh(30, 30, 0.2f), 0.3},
        {"L block", test::prismMesh({{1, 1}, {1, 2}, {0, 2}, {0, 0}, {2, 0}, {2, 1}}, 0.5f), 0.3}};
    AtlasOptions opt;
    opt.resolution = 512;
    for (const Solid& s : solids) {
        const Mesh& m = s.mesh;
        const atlas::Adjacency adj = atlas::buildAdjacency(m);
        SCOPED_TRACE(s.what);
        EXPECT_GT(atlas::medianDihedralDegrees(m, adj), atlas::kRoughDihedralDegrees);
        EXPECT_LT(atlas::concaveShareOfSharpEdges(m, adj), atlas::kMinConcaveShare);
        int iterations = -1;
        EXPECT_FALSE(atlas::smoothedForCharting(m, adj, &iterations));
        EXPECT_EQ(iterations, 0);
        const AtlasStats st = checkAtlas(m, opt);
        EXPECT_GE(st.coverage, s.minCoverage);
        // Thin sides raster to few texels: r within the data meshes' bounds
        // (the smoothed slab's was 0.32-1.28, stddev 0.27).
        EXPECT_LE(st.rWstd, 0.05);
        EXPECT_GE(st.rP01, 0.95);
        EXPECT_LE(st.rP99, 1.05);
    }
}

TEST(Atlas, ClosedSphereAndTube) {
    AtlasOptions opt;
    opt.resolution = 512;
    checkAtlas(test::sphereMesh(24, 48), opt);
    checkAtlas(test::tubeMesh(20, 32, 6.0), opt);
}

TEST(Atlas, GutterOfFourTexels) {
    AtlasOptions opt;
    opt.resolution = 256;
    opt.gutterTexels = 4;
    checkAtlas(test::sphereMesh(16, 32), opt);
}

TEST(Atlas, DegenerateAndNonManifoldTrianglesStillGetUVs) {
    Mesh m = test::sphereMesh(8, 16);
    const unsigned n = unsigned(m.positions.size());
    m.triangles.emplace_back(0, 0, 1);  // repeated index
    m.triangles.emplace_back(1, 2, 1);  // repeated index
    m.triangles.emplace_back(0, 1, 2);  // third face on an edge (non-manifold)
    m.positions.emplace_back(5, 5, 5);  // an isolated zero-area triangle
    m.normals.emplace_back(0, 1, 0);
    m.triangles.emplace_back(n, n, n);
    AtlasStats st;
    const Mesh out = buildAtlas(m, AtlasOptions(), &st);
    expectSameSurface(m, out, 1024);
    EXPECT_EQ(st.flipped, 0u);
    EXPECT_EQ(st.overlaps, 0u);
}

double secondsOf(const std::function<void()>& f) {
    const auto start = std::chrono::steady_clock::now();
    f();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// One triangle N times over the same three vertices (repair would drop them;
// the builder must not need it): every face its own chart, every vertex a hub
// of N faces. The vertex-ring filter was faces × degree × labels there (3,000
// copies: 13 s on an idle machine, 6,000: 87 s).
Mesh coincident(int n) {
    Mesh m;
    m.name = "coincident";
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    for (int i = 0; i < n; ++i)
        m.triangles.push_back(i % 2 ? glm::uvec3(0, 2, 1) : glm::uvec3(1, 2, 0));
    return m;
}

TEST(Atlas, CoincidentFacesAreNotQuadratic) {
    const Mesh big = coincident(6000);
    std::vector<int> labels(big.triangles.size());
    std::iota(labels.begin(), labels.end(), 0);
    const atlas::Adjacency adj = atlas::buildAdjacency(big);
    EXPECT_LT(secondsOf([&] { atlas::smoothLabels(big, adj, labels, 1, 0); }),
              10.0);  // well above the fix (room for a loaded CI)

    const Mesh m = coincident(3000);
    AtlasOptions opt;
    opt.resolution = 512;
    opt.useCache = false;
    Mesh out;
    EXPECT_LT(secondsOf([&] { out = buildAtlas(m, opt); }), 30.0);
    EXPECT_EQ(out.triangles.size(), m.triangles.size());
}

// Loose triangles, each its own component: VSA's seeding costs components ×
// faces and no density can pack 60,000 charts into 512²: a clear error, soon.
TEST(Atlas, TooManyLooseTrianglesFailSoon) {
    Mesh m;
    m.name = "loose";
    for (uint32_t i = 0; i < 60000; ++i) {
        const float e = 1e-7f * float(i);
        m.positions.insert(m.positions.end(), {{e, 0, 0}, {1 + e, 0, 0}, {0, 1 - e, e}});
        m.triangles.emplace_back(3 * i, 3 * i + 1, 3 * i + 2);
    }
    AtlasOptions opt;
    opt.resolution = 512;
    opt.useCache = false;
    std::string msg;
    const double s = secondsOf([&] {
        try {
            buildAtlas(m, opt);
        } catch (const Error& e) {
            msg = e.what();
        }
    });
    EXPECT_LT(s, 15.0);
    EXPECT_NE(msg.find("cannot pack 60000 charts"), std::string::npos) << msg;
}

// An L of two needles: its frame is a unit square but its area 1e-12, so the
// density from the area alone put a 10^6-texel-wide raster on it (the fuzzer
// found such a mesh: 5 s at 64², beyond its time limit). The longest side caps
// the density, and an outline too big for the frame is never rasterised.
TEST(Atlas, ChartOfNoAreaPacksAtOnce) {
    const std::vector<glm::dvec2> uv = {{0, 0}, {1, 0}, {1, 1e-12}, {1 + 1e-12, 1}, {1, 1}};
    const std::vector<atlas::Tri> tris = {{0, 1, 2}, {1, 4, 3}};
    const std::vector<atlas::PackChart> charts = {{&uv, &tris}};
    atlas::PackResult r;
    EXPECT_LT(secondsOf([&] { r = atlas::packCharts(charts, 64, 2, 1); }), 2.0);
    ASSERT_EQ(r.uv.size(), 1u);
    for (const glm::dvec2& p : r.uv[0]) {
        EXPECT_GE(p.x, 0.0);
        EXPECT_LE(p.x, 1.0);
        EXPECT_GE(p.y, 0.0);
        EXPECT_LE(p.y, 1.0);
    }
    EXPECT_GT(r.texelsPerUnit, 30.0);  // fills most of the frame, not a speck
}

// The fuzzer's binary STL (float words as read): denormal corners and one whose
// corners span 10^31. Scaled to 10 mm a sliver survives repair whose in-plane
// frame rounds to collinear; it was an internal CHECK, it now gets UVs.
TEST(Atlas, SliverTriangleRoundedCollinearGetsUVs) {
    const uint32_t words[4][12] = {
        {0, 0, 0, 0, 0, 0, 0x80000000, 0x3f, 0, 0, 0, 0x80000000},
        {0, 0, 0, 0, 0, 0, 0, 0, 0x80000000, 0x3f, 0x80000000, 0x3f},
        {0x60, 0, 0, 0x80000000, 0x3f, 0, 0, 0x80000000, 0x3f, 0, 0x3f800000, 0},
        {0, 0, 0, 0x3f800000, 0x74726576, 0x695f7865, 0x6369646e, 0x3f807365, 0, 0, 0, 0x3f800000}};
    std::string stl(80, ' ');
    const uint32_t count = 4;
    stl.append(reinterpret_cast<const char*>(&count), 4);
    for (const auto& w : words) {
        stl.append(reinterpret_cast<const char*>(w), sizeof(w));
        stl.append(2, '\0');
    }
    Mesh m = parseSTL(stl, "sliver.stl");
    ensureNormals(m);
    normalizeMesh(m, 10.0);
    AtlasOptions opt;
    opt.resolution = 64;
    opt.useCache = false;
    opt.threads = 1;
    const Mesh out = buildAtlas(m, opt);
    EXPECT_EQ(out.triangles.size(), m.triangles.size());
    for (const glm::vec2& uv : out.uvs) EXPECT_TRUE(std::isfinite(uv.x) && std::isfinite(uv.y));
}

// A fan of N faces around one vertex, 80% of them label 0 and pairs of label 1
// (so the edge rule leaves them): the vertex-ring rule gives the pairs to the
// majority, with the centre a hub (N = 400) as with an ordinary vertex (N = 200).
TEST(Atlas, VertexRingRuleSameAtHubs) {
    for (int n : {200, 400}) {
        Mesh m;
        m.positions.push_back({0, 0, 0});
        for (int i = 0; i < n; ++i) {
            const double a = 2 * M_PI * i / n;
            m.positions.push_back({float(std::cos(a)), float(std::sin(a)), 0});
        }
        std::vector<int> labels;
        for (int i = 0; i < n; ++i) {
            m.triangles.emplace_back(0, 1 + i, 1 + (i + 1) % n);
            labels.push_back(i % 10 < 8 ? 0 : 1);
        }
        const atlas::Adjacency adj = atlas::buildAdjacency(m);
        atlas::smoothLabels(m, adj, labels, 1, 0);
        EXPECT_EQ(std::count(labels.begin(), labels.end(), 0), n) << n;
    }
}

TEST(Atlas, ClearErrors) {
    Mesh empty;
    empty.name = "empty.off";
    EXPECT_THROW(buildAtlas(empty, AtlasOptions()), Error);
    Mesh bad = test::sphereMesh(4, 8);
    bad.triangles.emplace_back(0, 1, 999);
    try {
        buildAtlas(bad, AtlasOptions());
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("test:sphere"), std::string::npos) << e.what();
    }
}

TEST(Atlas, SegmentsIntersectExactly) {
    using atlas::segmentsIntersect;
    EXPECT_TRUE(segmentsIntersect({0, 0}, {1, 1}, {0, 1}, {1, 0}));
    EXPECT_FALSE(segmentsIntersect({0, 0}, {1, 0}, {0, 1e-30}, {1, 1e-30}));
    EXPECT_TRUE(segmentsIntersect({0, 0}, {1, 0}, {0.5, 0}, {0.5, 1}));  // touching
    EXPECT_TRUE(segmentsIntersect({0, 0}, {2, 0}, {1, 0}, {3, 0}));      // collinear overlap
    EXPECT_FALSE(segmentsIntersect({0, 0}, {1, 0}, {2, 0}, {3, 0}));
    // One float ulp off a diagonal: decided exactly.
    const glm::dvec2 a(0.1f, 0.1f), b(0.7f, 0.7f), d(0.3f, 0.9f);
    EXPECT_FALSE(segmentsIntersect(a, b, {0.3f, std::nextafter(0.3f, 1.0f)}, d));
    EXPECT_TRUE(segmentsIntersect(a, b, {0.3f, std::nextafter(0.3f, 0.0f)}, d));
    EXPECT_TRUE(segmentsIntersect(a, b, {0.3f, 0.3f}, d));
}

TEST(Atlas, MeasureFindsFlipsAndOverlaps) {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    m.triangles = {{0, 1, 2}, {1, 3, 2}};
    m.uvs = {{0.1f, 0.1f}, {0.6f, 0.1f}, {0.1f, 0.6f}, {0.6f, 0.6f}};
    AtlasStats ok = measureAtlas(m, 64);
    EXPECT_EQ(ok.charts, 1);
    EXPECT_EQ(ok.flipped, 0u);
    EXPECT_EQ(ok.overlaps, 0u);
    EXPECT_NEAR(ok.rWstd, 0, 1e-9);
    EXPECT_NEAR(ok.coverage, 0.25, 0.02);
    m.uvs[3] = {0.05f, 0.05f};  // folds the second triangle over the first
    const AtlasStats bad = measureAtlas(m, 64);
    EXPECT_EQ(bad.flipped, 1u);
    EXPECT_GE(bad.overlaps, 1u);
}

TEST(Atlas, JsonKeys) {
    AtlasStats st;
    st.charts = 3;
    const std::string j = atlasStatsJson(st).dump();
    for (const char* key : {"charts", "coverage", "r_wstd", "r_p01", "r_p99", "r_min", "r_max",
                            "flipped", "overlaps", "seconds"})
        EXPECT_NE(j.find(std::string("\"") + key + "\""), std::string::npos) << key;
}

TEST(Atlas, Png) {
    const auto dir = scratchDir("png");
    const Mesh out = buildAtlas(test::sphereMesh(8, 16), AtlasOptions());
    const std::string path = (dir / "atlas.png").string();
    writeAtlasPng(path, out, 128);
    std::ifstream in(path, std::ios::binary);
    char sig[8] = {};
    in.read(sig, 8);
    EXPECT_EQ(std::string(sig + 1, 3), "PNG");
    std::filesystem::remove_all(dir);
}

TEST(AtlasCache, HitIsIdenticalAndCorruptEntryIsRebuilt) {
    const auto dir = scratchDir("cache");
    const ScopedEnv env("TSIS_CACHE_DIR", dir.string());
    const std::string path = test::cgalMesh("cow");
    const Mesh mesh = path.empty() ? test::sphereMesh(16, 32) : test::readOFF(path);
    AtlasOptions opt;

    AtlasStats first, second, third, fourth;
    const Mesh a = atlas::buildAtlasCached(mesh, opt, &first);
    EXPECT_FALSE(first.fromCache);
    const Mesh b = atlas::buildAtlasCached(mesh, opt, &second);
    EXPECT_TRUE(second.fromCache);
    EXPECT_EQ(a.uvs, b.uvs);
    EXPECT_EQ(a.triangles, b.triangles);
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(second.charts, first.charts);
    EXPECT_EQ(second.coverage, first.coverage);
    EXPECT_LT(second.seconds, first.seconds);

    // Flip one byte in the middle of the entry: rebuilt, not trusted.
    const auto file = dir / "atlas" / (atlas::cacheKey(mesh, opt) + ".atlas");
    ASSERT_TRUE(std::filesystem::exists(file));
    {
        std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
        f.seekp(std::streamoff(std::filesystem::file_size(file) / 2));
        f.put('\x5a');
    }
    const Mesh c = atlas::buildAtlasCached(mesh, opt, &third);
    EXPECT_FALSE(third.fromCache);
    EXPECT_EQ(c.uvs, a.uvs);  // the builder is deterministic
    // A truncated entry too.
    std::filesystem::resize_file(file, 100);
    atlas::buildAtlasCached(mesh, opt, &third);
    EXPECT_FALSE(third.fromCache);
    atlas::buildAtlasCached(mesh, opt, &fourth);
    EXPECT_TRUE(fourth.fromCache);

    // A folder in the entry's place: a miss, and the build goes on.
    std::filesystem::remove(file);
    std::filesystem::create_directories(file / "sub");
    AtlasStats fifth;
    EXPECT_EQ(atlas::buildAtlasCached(mesh, opt, &fifth).uvs, a.uvs);
    EXPECT_FALSE(fifth.fromCache);

    // Other options, other entry.
    AtlasOptions other = opt;
    other.resolution = 512;
    EXPECT_NE(atlas::cacheKey(mesh, other), atlas::cacheKey(mesh, opt));
    std::filesystem::remove_all(dir);
}

// The atlas splits vertices along its seams: each copy has its source's file
// texcoords, and each triangle its material, built or from the cache.
TEST(AtlasCache, CarriesTexcoordsAndMaterials) {
    const auto dir = scratchDir("cache_texcoords");
    const ScopedEnv env("TSIS_CACHE_DIR", dir.string());
    Mesh mesh = test::sphereMesh(16, 32);
    for (const glm::vec3& p : mesh.positions) mesh.texcoords.emplace_back(p.x + p.y, p.z);
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
        mesh.materialIds.push_back(t % 5 == 4 ? kNoFileMaterial : uint32_t(t % 5));
    AtlasOptions opt;
    opt.resolution = 256;
    for (int pass = 0; pass < 2; ++pass) {
        AtlasStats stats;
        const Mesh out = atlas::buildAtlasCached(mesh, opt, &stats);
        EXPECT_EQ(stats.fromCache, pass == 1);
        EXPECT_GT(out.positions.size(), mesh.positions.size());  // seams split
        ASSERT_EQ(out.texcoords.size(), out.positions.size());
        EXPECT_EQ(out.materialIds, mesh.materialIds);
        for (size_t t = 0; t < mesh.triangles.size(); ++t)
            for (int k = 0; k < 3; ++k)
                ASSERT_EQ(out.texcoords[out.triangles[t][k]], mesh.texcoords[mesh.triangles[t][k]])
                    << t << " " << k;
    }
    std::filesystem::remove_all(dir);
}

// The atlas belongs to the shape, not the size: the mesh at 30 mm finds the
// entry made at 10 mm (issue 25: a new --size-mm rebuilt it), with the same
// UVs and three times the positions.
TEST(AtlasPolicy, AnotherSizeFindsTheCachedAtlas) {
    const auto dir = scratchDir("cache_size");
    const ScopedEnv env("TSIS_CACHE_DIR", dir.string());
    const Mesh mesh = test::sphereMesh(16, 32);
    AtlasOptions opt;
    AtlasStats first, second;
    const Mesh a = atlasAtSize(mesh, 10.0, "build", opt, &first);
    const Mesh b = atlasAtSize(mesh, 30.0, "build", opt, &second);
    EXPECT_FALSE(first.fromCache);
    EXPECT_TRUE(second.fromCache);
    EXPECT_EQ(a.uvs, b.uvs);
    ASSERT_EQ(a.positions.size(), b.positions.size());
    for (size_t v = 0; v < a.positions.size(); ++v)
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(b.positions[v][c], 3.0f * a.positions[v][c], 1e-5f) << v;
    std::filesystem::remove_all(dir);
}

TEST(AtlasPolicy, Modes) {
    const auto dir = scratchDir("policy");
    const ScopedEnv env("TSIS_CACHE_DIR", dir.string());
    const Mesh plain = test::sphereMesh(8, 16);
    AtlasOptions opt;
    opt.resolution = 256;

    // No UVs: auto builds, file is an error naming the mesh.
    const Mesh built = ensureAtlas(plain, "auto", opt);
    EXPECT_EQ(built.uvs.size(), built.positions.size());
    try {
        ensureAtlas(plain, "file", opt);
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("test:sphere"), std::string::npos) << e.what();
    }
    // Valid UVs are used as they are by auto and file.
    EXPECT_EQ(ensureAtlas(built, "auto", opt).uvs, built.uvs);
    EXPECT_EQ(ensureAtlas(built, "file", opt).uvs, built.uvs);
    // Invalid UVs (everything folded onto one triangle): auto rebuilds, file fails.
    Mesh folded = built;
    for (size_t v = 0; v < folded.uvs.size(); ++v)
        folded.uvs[v] = glm::vec2(0.1f + 0.3f * float(v % 3), 0.2f + 0.3f * float(v % 2));
    const Mesh rebuilt = ensureAtlas(folded, "auto", opt);
    EXPECT_EQ(measureAtlas(rebuilt, 512).overlaps, 0u);
    EXPECT_THROW(ensureAtlas(folded, "file", opt), Error);
    EXPECT_THROW(ensureAtlas(plain, "sometimes", opt), Error);
    // build ignores valid UVs.
    AtlasStats st;
    ensureAtlas(built, "build", opt, &st);
    EXPECT_GT(st.charts, 0);
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tsis

namespace tsis {
namespace {

// The measured table of the report: run with --gtest_also_run_disabled_tests
// (TSIS_ATLAS_MESHES="cow head ..." to choose meshes, TSIS_ATLAS_PNG_DIR to
// also write the pictures).
TEST(AtlasReport, DISABLED_DataMeshes) {
    std::string names = "cow head elephant ChineseDragon-10kv armadillo bunny00";
    if (const char* e = std::getenv("TSIS_ATLAS_MESHES")) names = e;
    std::istringstream list(names);
    std::printf(
        "| mesh | triangles | charts | coverage | r_wstd | r p1–p99 | r min–max | flips | overlaps "
        "| seconds |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
    for (std::string name; list >> name;) {
        const std::string path = test::cgalMesh(name);
        if (path.empty()) GTEST_SKIP() << test::kCgalTarball << " is not installed";
        const Mesh mesh = test::readOFF(path);
        AtlasOptions opt;
        if (const char* e = std::getenv("TSIS_ATLAS_MAXDIST"))
            opt.maxChartDistortion = std::atof(e);
        if (const char* e = std::getenv("TSIS_ATLAS_TPP")) opt.trianglesPerProxy = std::atoi(e);
        AtlasStats st;
        const Mesh out = buildAtlas(mesh, opt, &st);
        const AtlasStats fine = measureAtlas(out, 2048);
        std::printf(
            "| %s | %zu | %d | %.3f | %.4f | %.3f–%.3f | %.3f–%.3f | %zu | %zu (%zu at 2048²) | "
            "%.2f |\n",
            name.c_str(), mesh.triangles.size(), st.charts, st.coverage, st.rWstd, st.rP01, st.rP99,
            st.rMin, st.rMax, st.flipped, st.overlaps, fine.overlaps, st.seconds);
        std::fflush(stdout);
        if (const char* dir = std::getenv("TSIS_ATLAS_PNG_DIR"))
            writeAtlasPng(std::string(dir) + "/" + name + ".png", out, 1024);
    }
}

}  // namespace
}  // namespace tsis
