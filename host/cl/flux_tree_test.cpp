#include "cl/flux_tree.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <random>

#include "support/analytic_table.h"
#include "support/cl_fixture.h"

namespace tsis {
namespace {

using test::analyticTable;
using test::ClTest;
using test::lookup;

// A 32×32 atlas of two charts: the left half of the atlas on the plane z = 0,
// the right half on the plane z = 3 (so blocks across the seam are far apart
// in 3D), ~80% of the texels covered, random flux and texel areas.
struct SyntheticAtlas {
    static constexpr int kRes = 32;
    std::vector<cl_float4> flux, position, normal;

    explicit SyntheticAtlas(uint32_t seed) {
        std::mt19937 rng(seed);
        std::uniform_real_distribution<float> u(0.0f, 1.0f);
        const size_t n = size_t(kRes) * kRes;
        flux.assign(n, {{0, 0, 0, 0}});
        position.assign(n, {{0, 0, 0, 0}});
        normal.assign(n, {{0, 0, 1, 0}});
        for (int y = 0; y < kRes; ++y)
            for (int x = 0; x < kRes; ++x) {
                if (u(rng) > 0.8f) continue;
                const size_t i = size_t(y) * kRes + x;
                const bool right = x >= kRes / 2;
                const float s = 0.125f;  // mm per texel
                position[i] = {{(x % (kRes / 2)) * s, y * s, right ? 3.0f : 0.0f, 1.0f}};
                normal[i] = {{0, 0, 1, s * s * (0.8f + 0.4f * u(rng))}};
                flux[i] = {{u(rng), u(rng), u(rng), 1.0f}};
            }
    }
    bool covered(size_t i) const { return position[i].s[3] > 0; }
    glm::dvec3 at(size_t i) const { return {position[i].s[0], position[i].s[1], position[i].s[2]}; }
};

class FluxTreeTest : public ClTest {
  protected:
    FluxTree tree{rt};
    SyntheticAtlas atlas{5};

    void build() {
        std::vector<float> positions;
        for (const cl_float4& p : atlas.position) positions.insert(positions.end(), p.s, p.s + 4);
        tree.setLeaves(positions);
        tree.build(upload(atlas.flux), upload(atlas.position), upload(atlas.normal));
    }
    std::vector<TsisFluxNode> nodes() {
        return download<TsisFluxNode>(tree.nodes(), tree.topology().size());
    }
    // The texels under node i of the tree.
    void texelsUnder(int i, std::vector<int>& out) const {
        const cl_int4& t = tree.topology()[size_t(i)];
        if (t.s[1] == 0) {
            if (atlas.covered(size_t(t.s[2]))) out.push_back(t.s[2]);
            return;
        }
        for (int c = t.s[0]; c < t.s[0] + t.s[1]; ++c) texelsUnder(c, out);
    }
    // B at `points` through the tree with `epsilon`.
    std::vector<cl_float4> gather(const std::vector<cl_float4>& points, float epsilon,
                                  const ProfileTable& t, float ell = 0.5f) {
        cl::Buffer out = buffer(points.size() * sizeof(cl_float4));
        std::vector<cl_int> order(points.size());
        for (size_t j = 0; j < order.size(); ++j) order[j] = cl_int(order.size() - 1 - j);
        tree.gather(upload(points), upload(order), int(points.size()), epsilon, ell, upload(t.rgba),
                    t.info, out);
        return download<cl_float4>(out, points.size());
    }
    // The exact sum over every covered texel of p's medium, in double.
    glm::dvec3 exact(const cl_float4& p, const ProfileTable& t) const {
        glm::dvec3 b(0.0);
        for (size_t i = 0; i < atlas.flux.size(); ++i) {
            if (!atlas.covered(i) || atlas.position[i].s[3] != p.s[3]) continue;
            const double r = glm::length(glm::dvec3(p.s[0], p.s[1], p.s[2]) - atlas.at(i));
            for (int c = 0; c < 3; ++c) b[c] += atlas.flux[i].s[c] * lookup(t, r, c);
        }
        return b;
    }
};

std::vector<cl_float4> pointsOnCharts(int count, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 2.0f), side(0.0f, 1.0f);
    std::vector<cl_float4> p(count);
    for (cl_float4& x : p) x = {{u(rng), 2 * u(rng), side(rng) < 0.5f ? 0.0f : 3.0f, 1.0f}};
    return p;
}

// The leaves are the covered texels, each once, in Morton order of their
// positions (the two charts, 3 mm apart, do not interleave), and every node's
// children are contiguous and at most 8.
TEST_F(FluxTreeTest, LeavesAreTheCoveredTexelsInSpatialOrder) {
    build();
    const std::vector<int>& leaves = tree.leafTexels();
    std::vector<int> sorted = leaves;
    std::sort(sorted.begin(), sorted.end());
    std::vector<int> covered;
    for (size_t i = 0; i < atlas.flux.size(); ++i)
        if (atlas.covered(i)) covered.push_back(int(i));
    EXPECT_EQ(sorted, covered);
    int switches = 0;
    for (size_t k = 1; k < leaves.size(); ++k)
        switches += (atlas.at(size_t(leaves[k])).z > 1) != (atlas.at(size_t(leaves[k - 1])).z > 1);
    EXPECT_EQ(switches, 1) << "one run per chart";
    std::vector<int> under;
    texelsUnder(0, under);
    std::sort(under.begin(), under.end());
    EXPECT_EQ(under, covered) << "the root holds every texel once";
    for (const cl_int4& t : tree.topology()) EXPECT_LE(t.s[1], 8);
    EXPECT_LE(tree.depth(), TSIS_FLUX_TREE_MAX_DEPTH);
}

// Every node sums its texels' flux and area, sits at their flux-weighted
// position, and its radius holds every one of them.
TEST_F(FluxTreeTest, NodesSumTheirTexelsAndBoundThemInRadius) {
    build();
    const std::vector<TsisFluxNode> n = nodes();
    for (size_t i = 0; i < n.size(); ++i) {
        std::vector<int> texels;
        texelsUnder(int(i), texels);
        glm::dvec3 flux(0.0), weighted(0.0);
        double area = 0, weight = 0;
        for (int t : texels) {
            const cl_float4& f = atlas.flux[size_t(t)];
            flux += glm::dvec3(f.s[0], f.s[1], f.s[2]);
            area += atlas.normal[size_t(t)].s[3];
            const double y709 = TSIS_LUMINANCE(f.s[0], f.s[1], f.s[2]);
            weighted += y709 * atlas.at(size_t(t));
            weight += y709;
        }
        const std::string where = "node " + std::to_string(i);
        EXPECT_NEAR(n[i].fr, flux.x, 1e-5 * (1 + flux.x)) << where;
        EXPECT_NEAR(n[i].fb, flux.z, 1e-5 * (1 + flux.z)) << where;
        EXPECT_NEAR(n[i].area, area, 1e-5 * (1 + area)) << where;
        if (weight <= 0) continue;
        const glm::dvec3 p(n[i].px, n[i].py, n[i].pz);
        EXPECT_LT(glm::length(p - weighted / weight), 1e-4) << where;
        for (int t : texels)
            EXPECT_LE(glm::length(atlas.at(size_t(t)) - p), n[i].radius + 1e-5) << where;
    }
    // The root spans both charts (3 mm apart): its radius says so.
    EXPECT_GT(n.front().radius, 1.5f);
}

TEST_F(FluxTreeTest, EpsilonZeroIsTheExactSumOverTheAtlas) {
    build();
    const ProfileTable t = analyticTable(10.0);
    const std::vector<cl_float4> points = pointsOnCharts(37, 2);  // not a multiple of 8
    const std::vector<cl_float4> b = gather(points, 0.0f, t);
    for (size_t j = 0; j < points.size(); ++j) {
        const glm::dvec3 e = exact(points[j], t);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(b[j].s[c], e[c], 2e-5 * e[c]) << j << " " << c;
    }
    // Every covered texel for every lane of each group of 8.
    size_t covered = 0;
    for (size_t i = 0; i < atlas.flux.size(); ++i) covered += atlas.covered(i);
    EXPECT_EQ(tree.lastEvaluations(), static_cast<long long>(5 * 8 * covered));
}

TEST_F(FluxTreeTest, ErrorFallsAndCostRisesAsEpsilonFalls) {
    build();
    const ProfileTable t = analyticTable(10.0);
    const std::vector<cl_float4> points = pointsOnCharts(64, 3);
    double lastError = 1e9;
    long long lastCost = 0;
    for (float epsilon : {0.5f, 0.1f, 0.03f, 0.01f}) {
        const std::vector<cl_float4> b = gather(points, epsilon, t);
        const long long cost = tree.lastEvaluations();
        double worst = 0;
        for (size_t j = 0; j < points.size(); ++j) {
            const glm::dvec3 e = exact(points[j], t);
            for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(b[j].s[c] / e[c] - 1));
        }
        std::printf("epsilon %.3f: worst relative error %.5f, %lld evaluations\n", epsilon, worst,
                    cost);
        EXPECT_LT(worst, lastError) << epsilon;
        EXPECT_GT(cost, lastCost) << epsilon;
        // The bound: the midpoint error of a node used whole is O(epsilon).
        EXPECT_LT(worst, epsilon) << epsilon;
        lastError = worst;
        lastCost = cost;
    }
}

// Two media interleaved on the same planes (every third texel medium 2, tag
// 2): no node mixes them but the ones near the root (tag 0), and a point sums
// only its own medium's texels, exactly at epsilon 0 and within the bound at
// 0.05.
TEST_F(FluxTreeTest, MediaNeverMixInANodeNorLightEachOther) {
    for (size_t i = 0; i < atlas.position.size(); ++i)
        if (atlas.covered(i) && i % 3 == 0) atlas.position[i].s[3] = 2.0f;
    build();
    const std::vector<cl_int4>& topology = tree.topology();
    int mixed = 0;
    for (size_t i = 0; i < topology.size(); ++i) {
        std::vector<int> texels;
        texelsUnder(int(i), texels);
        bool one = true;
        for (int t : texels)
            one = one && atlas.position[size_t(t)].s[3] == atlas.position[size_t(texels[0])].s[3];
        if (!one) {
            EXPECT_EQ(topology[i].s[3], 0) << "node " << i;
            ++mixed;
        } else if (!texels.empty()) {
            EXPECT_EQ(float(topology[i].s[3]), atlas.position[size_t(texels[0])].s[3]) << i;
        }
    }
    EXPECT_EQ(mixed, 1) << "only the root holds both";
    const ProfileTable t = analyticTable(10.0);
    std::vector<cl_float4> points = pointsOnCharts(40, 4);
    for (size_t j = 0; j < points.size(); j += 2) points[j].s[3] = 2.0f;
    for (float epsilon : {0.0f, 0.05f}) {
        const std::vector<cl_float4> b = gather(points, epsilon, t);
        for (size_t j = 0; j < points.size(); ++j) {
            const glm::dvec3 e = exact(points[j], t);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(b[j].s[c], e[c], (epsilon > 0 ? epsilon : 2e-5) * e[c])
                    << j << " " << c << " epsilon " << epsilon;
        }
    }
}

TEST_F(FluxTreeTest, SameInputsGiveTheSameBits) {
    build();
    const ProfileTable t = analyticTable(10.0);
    const std::vector<cl_float4> points = pointsOnCharts(40, 4);
    const std::vector<cl_float4> a = gather(points, 0.05f, t);
    build();
    const std::vector<cl_float4> b = gather(points, 0.05f, t);
    for (size_t j = 0; j < points.size(); ++j)
        for (int c = 0; c < 3; ++c) EXPECT_EQ(a[j].s[c], b[j].s[c]);
}

}  // namespace
}  // namespace tsis

namespace tsis {
namespace {

// A full 8×4 image: runs of 8 in the order are the 4×2 tiles, row-major within.
TEST(FluxTreeOrder, GroupsPixelsByTiles) {
    std::vector<int> pixels(32);
    for (int i = 0; i < 32; ++i) pixels[i] = i;
    const std::vector<int> order = FluxTree::tileOrder(pixels, 8);
    const std::vector<int> expected = {0,  1,  2,  3,  8,  9,  10, 11, 4,  5,  6,
                                       7,  12, 13, 14, 15, 16, 17, 18, 19, 24, 25,
                                       26, 27, 20, 21, 22, 23, 28, 29, 30, 31};
    EXPECT_EQ(order, expected);
    // With holes: still a permutation of the covered points.
    const std::vector<int> sparse = {1, 5, 9, 30};
    EXPECT_EQ(FluxTree::tileOrder(sparse, 8), (std::vector<int>{0, 2, 1, 3}));
}

}  // namespace
}  // namespace tsis
