// kernels/mis.cl against host double versions, each kernel on its own inputs:
// the light maps' texel irradiance and area, where the texture-space samples
// land in every map (and N p_T), and the gather's two weighted sums
// B = Σ_i c(x_i) w_i Rd + Σ_l Σ_k (1 − c(x)) Φ_l Rd / (n q τ²)
// (kernels/mis.cl; the derivation in host/render/method_mis.h).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "mis_shared.h"
#include "support/analytic_table.h"
#include "support/cl_fixture.h"
#include "support/kernel_reference.h"

namespace tsis {
namespace {

using test::ClTest;
using test::Conditioning;

constexpr int kRes = 8;
constexpr int kLights = 2;
constexpr size_t kPer = size_t(kRes) * kRes;

// Two orthographic lights from +z with different texel sizes (0.5 and
// 0.4375 mm), maps of the plane z ≈ 0 with a fifth of the texels unlit.
struct Maps {
    std::vector<TsisLightMapInfo> lights;
    std::vector<cl_float4> flux, position;
    Maps() {
        for (int l = 0; l < kLights; ++l) {
            const float half = l == 0 ? 2.0f : 1.75f;
            lights.push_back(test::lightMap(glm::vec3(0, 0, 10.0f + l), false, kRes, half));
            const test::LightMaps m = test::planeLightMaps(lights.back(), 1, 20 + l, 0.2);
            flux.insert(flux.end(), m.flux.begin(), m.flux.end());
            position.insert(position.end(), m.position.begin(), m.position.end());
        }
    }
};

// tsis_mis_texels in double: (E, 1/A) per lit texel, A from the nearer lit
// neighbour on each axis.
std::vector<glm::dvec4> hostTexels(const Maps& maps, Conditioning& cond) {
    std::vector<glm::dvec4> irr(maps.flux.size(), glm::dvec4(0.0));
    for (size_t g = 0; g < maps.flux.size(); ++g) {
        if (!(maps.flux[g].s[3] > 0.0f)) continue;
        const size_t base = g / kPer * kPer;
        const int x = int((g - base) % kRes), y = int((g - base) / kRes);
        const glm::dvec3 p = test::xyz(maps.position[g]);
        glm::dvec3 axis[2] = {glm::dvec3(0.0), glm::dvec3(0.0)};
        for (int a = 0; a < 2; ++a) {
            double best = INFINITY;
            for (int s = -1; s <= 1; s += 2) {
                const int nx = x + (a == 0 ? s : 0), ny = y + (a == 1 ? s : 0);
                if (nx < 0 || ny < 0 || nx >= kRes || ny >= kRes) continue;
                const size_t n = base + size_t(ny * kRes + nx);
                if (!(maps.flux[n].s[3] > 0.0f)) continue;
                const glm::dvec3 d = test::xyz(maps.position[n]) - p;
                if (cond.less(glm::dot(d, d), best)) {
                    best = glm::dot(d, d);
                    axis[a] = d;
                }
            }
        }
        const double area = glm::length(glm::cross(axis[0], axis[1]));
        if (area > 0.0) irr[g] = glm::dvec4(test::xyz(maps.flux[g]) / area, 1.0 / area);
    }
    return irr;
}

std::vector<cl_float4> toFloat4(const std::vector<glm::dvec4>& v) {
    std::vector<cl_float4> f;
    f.reserve(v.size());
    for (const glm::dvec4& x : v) f.push_back({{float(x.x), float(x.y), float(x.z), float(x.w)}});
    return f;
}

// mis_visible in double: light m's texel that sees x (within two texel sizes
// of the map's surface there), or -1; tc its texel coordinates.
int visible(const Maps& maps, const std::vector<cl_float4>& irr, int m, const glm::dvec3& x,
            glm::dvec2* tc, Conditioning& cond) {
    const TsisLightMapInfo& l = maps.lights[size_t(m)];
    const glm::dvec3 c = test::project(l, x);
    *tc = glm::dvec2(c);
    const int t = test::texel(l, c.x, c.y, cond);
    if (t < 0) return -1;
    const size_t g = size_t(m) * kPer + size_t(t);
    const double invArea = irr[g].s[3];
    if (!(invArea > 0.0)) return -1;
    const glm::dvec3 d = test::xyz(maps.position[g]) - x;
    return cond.less(glm::dot(d, d) * invArea, 4.0) ? int(g) : -1;
}

// Samples on lit texels of light 0 (most of them seen by both lights) and a
// few off the surface (seen by none).
std::vector<TsisSample> samples(const Maps& maps, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<TsisSample> s;
    for (size_t g = 0; g < kPer; ++g)
        if (maps.flux[g].s[3] > 0.0f && u(rng) < 0.6f) {
            const cl_float4 p = maps.position[g];
            s.push_back({p.s[0], p.s[1], p.s[2], float(g), u(rng), u(rng), u(rng), 1.0f});
        }
    for (int k = 0; k < 3; ++k)
        s.push_back({0.3f * k + 0.11f, 0.13f, 4.0f, 0.0f, 1.0f, 1.0f, 1.0f, 1.0f});
    return s;
}

class MisKernelTest : public ClTest {
  protected:
    cl::Kernel texels = rt.kernel("mis.cl", "tsis_mis_texels");
    cl::Kernel prepare = rt.kernel("mis.cl", "tsis_mis_prepare");
    cl::Kernel gather = rt.kernel("mis.cl", "tsis_mis_gather");
    Maps maps;
    TsisMisInfo info = [] {
        TsisMisInfo mi{};
        mi.lights = kLights;
        mi.res = kRes;
        mi.n_dist = 5;
        mi.segments = 8;
        mi.q_size = 16;
        mi.q_inv_step = 16.0f / 3.5f;
        mi.tex_scale = 0.7f;
        mi.seed = 9;
        return mi;
    }();
};

// Irradiance and inverse area: 1e-6 relative (a cross product and a division
// in float). The texel edges and the isolated texels give zeros.
TEST_F(MisKernelTest, TexelsGiveIrradianceAndInverseArea) {
    Conditioning cond;
    const std::vector<glm::dvec4> want = hostTexels(maps, cond);
    ASSERT_EQ(cond.close, 0) << "two neighbours at the same distance: choose other maps";
    cl::Buffer out = buffer(maps.flux.size() * sizeof(cl_float4));
    run(texels, maps.flux.size(), upload(maps.flux), upload(maps.position), info, out);
    const std::vector<cl_float4> got = download<cl_float4>(out, maps.flux.size());
    int lit = 0;
    for (size_t g = 0; g < want.size(); ++g) {
        for (int c = 0; c < 4; ++c)
            ASSERT_NEAR(got[g].s[c], want[g][c], 1e-6 * std::abs(want[g][c])) << g << " " << c;
        lit += want[g].w > 0.0;
    }
    EXPECT_GT(lit, int(kPer)) << "most texels of both maps have an area";
}

// Where each sample lands in each map, (x, y, 1/A or 0), and N p_T =
// tex_scale·Y(Σ_l E_l). Tolerance: 1e-5 relative (texel coordinates are a
// float projection; the sum of two irradiances).
TEST_F(MisKernelTest, PrepareGivesEachSampleItsTexelsAndDensity) {
    Conditioning cond;
    const std::vector<cl_float4> irr = toFloat4(hostTexels(maps, cond));
    const std::vector<TsisSample> s = samples(maps, 4);
    info.n_tex = int(s.size());
    const size_t n = s.size();
    std::vector<glm::dvec4> seen(n * kLights);
    std::vector<double> density(n);
    int seenBoth = 0;
    for (size_t i = 0; i < n; ++i) {
        const glm::dvec3 x(s[i].px, s[i].py, s[i].pz);
        glm::dvec3 e(0.0);
        int count = 0;
        for (int m = 0; m < kLights; ++m) {
            glm::dvec2 tc;
            const int g = visible(maps, irr, m, x, &tc, cond);
            const glm::dvec4 v = g >= 0 ? glm::dvec4(test::xyz(irr[size_t(g)]), irr[size_t(g)].s[3])
                                        : glm::dvec4(0.0);
            e += glm::dvec3(v);
            count += g >= 0;
            seen[size_t(m) * n + i] = glm::dvec4(tc, v.w, 0.0);
        }
        seenBoth += count == kLights;
        density[i] = info.tex_scale * test::luminance(e);
    }
    ASSERT_EQ(cond.close, 0) << "a sample on a texel or visibility boundary: choose other samples";
    EXPECT_GT(seenBoth, int(n) / 4) << "a good part of the samples is seen by both lights";

    cl::Buffer seenBuf = buffer(n * kLights * sizeof(cl_float4)),
               densityBuf = buffer(n * sizeof(float));
    run(prepare, n, upload(s), info, upload(maps.lights), upload(maps.position), upload(irr),
        seenBuf, densityBuf);
    const std::vector<cl_float4> gotSeen = download<cl_float4>(seenBuf, n * kLights);
    const std::vector<float> gotDensity = download<float>(densityBuf, n);
    for (size_t k = 0; k < seen.size(); ++k)
        for (int c = 0; c < 4; ++c)
            ASSERT_NEAR(gotSeen[k].s[c], seen[k][c], 1e-5 * std::abs(seen[k][c])) << k << " " << c;
    for (size_t i = 0; i < n; ++i) ASSERT_NEAR(gotDensity[i], density[i], 1e-5 * density[i]) << i;
}

// The gather: both sums for every point, against double. Its inputs are made
// up where the earlier kernels would give them (seen, N p_T as their host
// versions give them; a radius table and a density table of our own).
TEST_F(MisKernelTest, GatherMatchesHostDoubleSum) {
    Conditioning cond;
    const std::vector<cl_float4> irr = toFloat4(hostTexels(maps, cond));
    const std::vector<TsisSample> s = samples(maps, 5);
    const size_t n = s.size();
    info.n_tex = int(n);
    std::vector<cl_float4> seen(n * kLights);
    std::vector<float> density(n);
    for (size_t i = 0; i < n; ++i) {
        glm::dvec3 e(0.0);
        for (int m = 0; m < kLights; ++m) {
            glm::dvec2 tc;
            const int g = visible(maps, irr, m, glm::dvec3(s[i].px, s[i].py, s[i].pz), &tc, cond);
            const float invArea = g >= 0 ? irr[size_t(g)].s[3] : 0.0f;
            if (g >= 0) e += test::xyz(irr[size_t(g)]);
            seen[size_t(m) * n + i] = {{float(tc.x), float(tc.y), invArea, 0.0f}};
        }
        density[i] = float(info.tex_scale * test::luminance(e));
    }
    const int K = info.segments;
    std::vector<float> radii;
    for (int k = 0; k <= K; ++k) radii.push_back(3.5f * std::pow(float(k) / float(K), 1.5f));
    std::vector<float> q;
    q.reserve(size_t(info.q_size));
    for (int b = 0; b < info.q_size; ++b) q.push_back(0.8f / (1.0f + 0.5f * float(b)));
    const ProfileTable t = test::analyticTable(4.0);
    std::mt19937 rng(8);
    std::uniform_real_distribution<float> u(-1.6f, 1.6f);
    std::vector<cl_float4> pts;
    // One medium throughout (tag 1, as the maps' covered texels).
    pts.reserve(24);
    for (int j = 0; j < 24; ++j) pts.push_back({{u(rng), u(rng), 0.03f, 1.0f}});

    // Host: kernels/mis.cl's tsis_mis_gather in double.
    const auto cdf = [&](double r) {
        if (!(r > radii[0])) return 0.0;
        if (!(r < radii[size_t(K)])) return 1.0;
        int lo = 0;
        while (radii[size_t(lo) + 1] <= r) ++lo;
        return (lo + (r - radii[size_t(lo)]) / (radii[size_t(lo) + 1] - radii[size_t(lo)])) / K;
    };
    const auto qOf = [&](double r, double z, double tail) {
        const double b = std::sqrt(r * r + z * z) * info.q_inv_step;
        if (!(cond.less(b, info.q_size) && tail > 0.0)) return 0.0;
        return q[size_t(cond.floor(b))] / tail;
    };
    std::vector<glm::dvec3> want(pts.size(), glm::dvec3(0.0)), mag = want;
    int dSamples = 0;
    for (size_t j = 0; j < pts.size(); ++j) {
        const glm::dvec3 xo = test::xyz(pts[j]);
        glm::dvec3 o[kLights];
        glm::dvec2 zt[kLights];
        for (int m = 0; m < kLights; ++m) {
            const TsisLightMapInfo& l = maps.lights[size_t(m)];
            const glm::dvec3 c = test::project(l, xo);
            o[m] = glm::dvec3(c.x, c.y, l.tau_per_w * c.z);
            const test::LitPoint lit =
                test::bilinear(l, maps.flux, maps.position, size_t(m) * kPer, c.x, c.y);
            if (lit.point.w > 0.0 && lit.point.w < 1e-4) ++cond.close;  // z jumps to 0 at w = 0
            const double z =
                lit.point.w > 0.0 ? glm::length(glm::dvec3(lit.point) / lit.point.w - xo) : 0.0;
            zt[m] = glm::dvec2(z, 1.0 - cdf(z));
        }
        // The weight c(x) from N p_T and the light-map densities at x's texels.
        const auto weight = [&](double pt, double pd) {
            pd *= info.n_dist;
            return pt + pd > 0.0 ? pt / (pt + pd) : 1.0;
        };
        const auto add = [&](const glm::dvec3& w, const glm::dvec3& x) {
            for (int c = 0; c < 3; ++c) {
                const double term = w[c] * test::lookup(t, glm::length(xo - x), c);
                want[j][c] += term;
                mag[j][c] += std::abs(term);
            }
        };
        // T samples.
        for (size_t i = 0; i < n; ++i) {
            double pd = 0.0;
            for (int m = 0; m < kLights; ++m) {
                const cl_float4 v = seen[size_t(m) * n + i];
                if (v.s[2] > 0.0f)
                    pd += qOf(glm::length(glm::dvec2(v.s[0], v.s[1]) - glm::dvec2(o[m])) * o[m].z,
                              zt[m].x, zt[m].y) *
                          o[m].z * o[m].z * v.s[2];
            }
            const double c = weight(density[i], pd);
            add(c * glm::dvec3(s[i].wr, s[i].wg, s[i].wb), glm::dvec3(s[i].px, s[i].py, s[i].pz));
        }
        // D samples: per light, n points of an R2 sequence shifted by a hash.
        for (int l = 0; l < kLights; ++l) {
            const uint32_t h = tsis_hash(uint32_t(j) ^ tsis_hash(info.seed * 8u + uint32_t(l)));
            const double s1 = tsis_hash_unit(h), s2 = tsis_hash_unit(tsis_hash(h + 0x9e3779b9U));
            const double tau = o[l].z, z = zt[l].x, tail = zt[l].y;
            for (int k = 0; k < info.n_dist; ++k) {
                const double a1 = s1 + 0.7548776662 * k, a2 = s2 + 0.5698402910 * k;
                const double u1 = a1 - cond.floor(a1), u2 = a2 - std::floor(a2);
                const double sk = (1.0 - tail * (1.0 - u1)) * K;
                const int seg = std::clamp(int(cond.floor(sk)), 0, K - 1);
                const double s0 = radii[size_t(seg)], ds = radii[size_t(seg) + 1] - s0;
                const double sd = s0 + (sk - seg) * ds;
                const double r = std::sqrt(std::max(sd * sd - z * z, 0.0));
                if (!(r > 0.0) || !(ds > 0.0) || !(tail > 0.0)) continue;
                const double qd = 1.0 / (K * ds * tail * 2.0 * M_PI * sd);
                const TsisLightMapInfo& ll = maps.lights[size_t(l)];
                const int tx = test::texel(ll, o[l].x + r / tau * std::cos(2 * M_PI * u2),
                                           o[l].y + r / tau * std::sin(2 * M_PI * u2), cond);
                if (tx < 0) continue;
                const size_t g = size_t(l) * kPer + size_t(tx);
                if (!(maps.flux[g].s[3] > 0.0f)) continue;
                const glm::dvec3 x = test::xyz(maps.position[g]);
                glm::dvec3 e(0.0);
                double pd = 0.0;
                for (int m = 0; m < kLights; ++m) {
                    glm::dvec2 tc;
                    const int gm = visible(maps, irr, m, x, &tc, cond);
                    if (gm < 0) continue;
                    e += test::xyz(irr[size_t(gm)]);
                    pd += qOf(glm::length(tc - glm::dvec2(o[m])) * o[m].z, zt[m].x, zt[m].y) *
                          o[m].z * o[m].z * irr[size_t(gm)].s[3];
                }
                const double c = weight(info.tex_scale * test::luminance(e), pd);
                add((1.0 - c) * test::xyz(maps.flux[g]) / (info.n_dist * qd * tau * tau), x);
                ++dSamples;
            }
        }
    }
    ASSERT_EQ(cond.close, 0) << "a decision on its boundary: choose other points or seed";
    EXPECT_GT(dSamples, int(pts.size()) * kLights * info.n_dist / 2) << "most D samples land";

    cl::Buffer out = buffer(pts.size() * sizeof(cl_float4));
    run(gather, pts.size(), upload(pts), int(pts.size()), info, upload(s), upload(seen),
        upload(density), upload(maps.lights), upload(maps.flux), upload(maps.position), upload(irr),
        upload(radii), upload(q), upload(t.rgba), t.info, out);
    const std::vector<cl_float4> got = download<cl_float4>(out, pts.size());
    // Tolerance: 1e-5 of Σ|terms| (float sums of ~70 weighted products; the
    // weights are ratios of float densities).
    for (size_t j = 0; j < pts.size(); ++j) {
        for (int c = 0; c < 3; ++c)
            ASSERT_NEAR(got[j].s[c], want[j][c], 1e-5 * mag[j][c])
                << "point " << j << " channel " << c;
        EXPECT_EQ(got[j].s[3], 0.0f);
    }
}

}  // namespace
}  // namespace tsis
