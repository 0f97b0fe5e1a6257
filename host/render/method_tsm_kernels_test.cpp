// kernels/tsm.cl against host double versions: the pyramid's level 0 and its
// 2×2 reduction, and the 21-tap filter B(xo) = Σ_k Φ_k·Rd̄_ring(k)(Δz_k) read
// from a hand-made pyramid (kernels/tsm.cl, host/render/method_tsm.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "render/method_tsm.h"
#include "support/analytic_table.h"
#include "support/cl_fixture.h"
#include "support/kernel_reference.h"

namespace tsis {
namespace {

// An index of these small test grids (int arithmetic, then widened).
size_t idx(int i) {
    return static_cast<size_t>(i);
}

using test::ClTest;
using test::Conditioning;

class TsmKernelTest : public ClTest {
  protected:
    cl::Kernel level0 = rt.kernel("tsm.cl", "tsis_tsm_level0");
    cl::Kernel reduce = rt.kernel("tsm.cl", "tsis_tsm_reduce");
    cl::Kernel filter = rt.kernel("tsm.cl", "tsis_tsm_filter");
};

std::vector<cl_float4> randomFloat4(size_t n, uint32_t seed, float lo, float hi, double empty) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(lo, hi);
    std::uniform_real_distribution<double> e(0.0, 1.0);
    std::vector<cl_float4> v(n, {{0, 0, 0, 0}});
    for (cl_float4& x : v)
        if (e(rng) >= empty) x = {{u(rng), u(rng), u(rng), 1.0f}};
    return v;
}

// F = (Φ, medium tag) exactly; P = (Y·x, Y) with Y the luminance of Φ. Tolerance on P:
// 1e-6 relative (Y is three float products summed).
TEST_F(TsmKernelTest, Level0IsFluxAndLuminanceWeightedPositions) {
    const int count = 37;
    const std::vector<cl_float4> flux = randomFloat4(count, 1, 0.0f, 2.0f, 0.2);
    const std::vector<cl_float4> pos = randomFloat4(count, 2, -5.0f, 5.0f, 0.0);
    cl::Buffer F = buffer(count * sizeof(cl_float4)), P = buffer(count * sizeof(cl_float4));
    run(level0, count, upload(flux), upload(pos), count, F, P);
    const std::vector<cl_float4> f = download<cl_float4>(F, count),
                                 p = download<cl_float4>(P, count);
    for (int i = 0; i < count; ++i) {
        const double y = test::luminance(test::xyz(flux[i]));
        for (int c = 0; c < 3; ++c) {
            EXPECT_EQ(f[i].s[c], flux[i].s[c]) << i;
            EXPECT_NEAR(p[i].s[c], y * pos[i].s[c], 1e-6 * std::abs(y * pos[i].s[c])) << i;
        }
        EXPECT_EQ(f[i].s[3], flux[i].s[3]) << i;
        EXPECT_NEAR(p[i].s[3], y, 1e-6 * y) << i;
    }
}

// A 5×3 level to 3×2: each cell the sum of the up-to-four cells under it
// (odd edges sum what exists), F's w the cells' one medium tag (0 none, -1
// several: one cell of tag 2 among tags 1). Tolerance 1e-6 of the sum of
// magnitudes.
TEST_F(TsmKernelTest, ReduceSumsTwoByTwoWithOddEdges) {
    const int sw = 5, sh = 3, dw = 3, dh = 2, src = 4, dst = src + sw * sh;
    const size_t cells = idx(dst + dw * dh);
    std::vector<cl_float4> F0 = randomFloat4(cells, 3, -1.0f, 3.0f, 0.1);
    F0[idx(src + 1)].s[3] = 2.0f;
    const std::vector<cl_float4> P0 = randomFloat4(cells, 4, -4.0f, 4.0f, 0.1);
    cl::Buffer F = upload(F0), P = upload(P0);
    setKernelArgs(reduce, F, P, src, sw, sh, dst, dw, dh);
    rt.queue().enqueueNDRangeKernel(reduce, cl::NullRange, cl::NDRange(8, 8), cl::NDRange(8, 8));
    const std::vector<cl_float4> f = download<cl_float4>(F, cells),
                                 p = download<cl_float4>(P, cells);
    for (int y = 0; y < dh; ++y)
        for (int x = 0; x < dw; ++x)
            for (int c = 0; c < 4; ++c) {
                double fs = 0, fm = 0, ps = 0, pm = 0;
                for (int sy = 2 * y; sy < std::min(2 * y + 2, sh); ++sy)
                    for (int sx = 2 * x; sx < std::min(2 * x + 2, sw); ++sx) {
                        const size_t i = idx(src + sy * sw + sx);
                        fs += F0[i].s[c];
                        fm += std::abs(F0[i].s[c]);
                        ps += P0[i].s[c];
                        pm += std::abs(P0[i].s[c]);
                    }
                const size_t d = idx(dst + y * dw + x);
                if (c == 3) {
                    float tag = 0;
                    for (int sy = 2 * y; sy < std::min(2 * y + 2, sh); ++sy)
                        for (int sx = 2 * x; sx < std::min(2 * x + 2, sw); ++sx) {
                            const float t = F0[idx(src + sy * sw + sx)].s[3];
                            if (t != 0) tag = tag == 0 || tag == t ? t : -1;
                        }
                    EXPECT_EQ(f[d].s[3], tag) << x << ", " << y;
                } else {
                    EXPECT_NEAR(f[d].s[c], fs, 1e-6 * fm) << x << ", " << y << " channel " << c;
                }
                EXPECT_NEAR(p[d].s[c], ps, 1e-6 * pm) << x << ", " << y << " channel " << c;
            }
    // The source level is only read.
    for (size_t i = 0; i < size_t(dst); ++i) EXPECT_EQ(f[i].s[0], F0[i].s[0]) << i;
}

// A pyramid over an 8×8 map: level 0 random (a fifth of the cells unlit),
// the levels above its 2×2 sums (in double, then float).
struct Pyramid {
    std::vector<cl_int4> levels;
    std::vector<cl_float4> F, P;
};
Pyramid pyramid(int res, uint32_t seed) {
    Pyramid py;
    int cells = 0;
    for (int w = res;; w = (w + 1) / 2) {
        py.levels.push_back({{cells, w, w, 0}});
        cells += w * w;
        if (w == 1) break;
    }
    const std::vector<cl_float4> flux = randomFloat4(idx(res * res), seed, 0.1f, 1.0f, 0.2);
    const std::vector<cl_float4> pos = randomFloat4(idx(res * res), seed + 1, -3.0f, 3.0f, 0.0);
    std::vector<glm::dvec4> F(size_t(cells), glm::dvec4(0.0)), P(size_t(cells), glm::dvec4(0.0));
    for (int i = 0; i < res * res; ++i) {
        const double y = test::luminance(test::xyz(flux[size_t(i)]));
        F[size_t(i)] = glm::dvec4(test::xyz(flux[size_t(i)]), 0.0);
        P[size_t(i)] = glm::dvec4(y * test::xyz(pos[size_t(i)]), y);
    }
    for (size_t l = 1; l < py.levels.size(); ++l) {
        const cl_int4 s = py.levels[l - 1], d = py.levels[l];
        for (int y = 0; y < d.s[2]; ++y)
            for (int x = 0; x < d.s[1]; ++x)
                for (int sy = 2 * y; sy < std::min(2 * y + 2, s.s[2]); ++sy)
                    for (int sx = 2 * x; sx < std::min(2 * x + 2, s.s[1]); ++sx) {
                        F[idx(d.s[0] + y * d.s[1] + x)] += F[idx(s.s[0] + sy * s.s[1] + sx)];
                        P[idx(d.s[0] + y * d.s[1] + x)] += P[idx(s.s[0] + sy * s.s[1] + sx)];
                    }
    }
    for (size_t i = 0; i < F.size(); ++i) {
        py.F.push_back({{float(F[i].x), float(F[i].y), float(F[i].z), float(F[i].w)}});
        py.P.push_back({{float(P[i].x), float(P[i].y), float(P[i].z), float(P[i].w)}});
    }
    return py;
}

// tsm_bilinear: the four cells around c (cell j's centre at j), clamped.
// Continuous in c, so its floor needs no conditioning.
void cellBilinear(const Pyramid& py, const cl_int4& level, double cx, double cy, glm::dvec4* f,
                  glm::dvec4* p) {
    const double fx = std::floor(cx), fy = std::floor(cy);
    const double tx = cx - fx, ty = cy - fy;
    const int x0 = std::clamp(int(fx), 0, level.s[1] - 1),
              y0 = std::clamp(int(fy), 0, level.s[2] - 1);
    const int xs[2] = {x0, std::min(x0 + 1, level.s[1] - 1)};
    const int ys[2] = {y0, std::min(y0 + 1, level.s[2] - 1)};
    *f = *p = glm::dvec4(0.0);
    for (int k = 0; k < 4; ++k) {
        const double w = ((k & 1) ? tx : 1.0 - tx) * ((k & 2) ? ty : 1.0 - ty);
        const size_t i = idx(level.s[0] + ys[k >> 1] * level.s[1] + xs[k & 1]);
        const cl_float4 a = py.F[i], b = py.P[i];
        *f += w * glm::dvec4(a.s[0], a.s[1], a.s[2], a.s[3]);
        *p += w * glm::dvec4(b.s[0], b.s[1], b.s[2], b.s[3]);
    }
}

TEST_F(TsmKernelTest, FilterMatchesHostDoubleSum) {
    const int res = 8;
    const Pyramid py = pyramid(res, 5);
    const std::vector<TsisTsmTap> taps = TsmMethod::pattern();
    // One table per ring: the analytic profile scaled by ring + 1.
    const ProfileTable base = test::analyticTable(7.0);
    std::vector<ProfileTable> rings(TsmMethod::kRings, base);
    std::vector<float> ringsRgba;
    for (int j = 0; j < TsmMethod::kRings; ++j) {
        for (float& v : rings[size_t(j)].rgba) v *= float(j + 1);
        ringsRgba.insert(ringsRgba.end(), rings[size_t(j)].rgba.begin(),
                         rings[size_t(j)].rgba.end());
    }
    std::mt19937 rng(6);
    std::uniform_real_distribution<float> u(-3.5f, 3.5f);
    std::vector<cl_float4> pts;
    pts.reserve(40);
    for (int i = 0; i < 40; ++i) pts.push_back({{u(rng), u(rng), 0.3f * u(rng), 0.0f}});
    const float radius = 9.0f;

    cl::Buffer F = upload(py.F), P = upload(py.P), levels = upload(py.levels);
    cl::Buffer tapBuf = upload(taps), ringBuf = upload(ringsRgba), p = upload(pts);
    cl::Buffer out = buffer(pts.size() * sizeof(cl_float4));
    // A point light (perspective map, source = its position) and a
    // directional one (orthographic, source = its direction of travel).
    for (bool point : {true, false}) {
        const glm::vec3 eye(1.0f, 2.0f, 9.0f);
        const TsisLightMapInfo l = test::lightMap(eye, point, res, 4.0f);
        const glm::vec3 dir = -glm::normalize(eye);
        const cl_float4 source =
            point ? cl_float4{{eye.x, eye.y, eye.z, 1.0f}} : cl_float4{{dir.x, dir.y, dir.z, 0.0f}};
        Conditioning cond;
        std::vector<glm::dvec3> want(pts.size(), glm::dvec3(0.0)), mag = want;
        for (size_t j = 0; j < pts.size(); ++j) {
            const glm::dvec3 xo = test::xyz(pts[j]);
            const glm::dvec3 o = test::project(l, xo);
            const glm::dvec3 travel =
                point ? glm::normalize(xo - glm::dvec3(eye)) : glm::dvec3(dir);
            const double rt = radius / (double(l.tau_per_w) * o.z);
            for (const TsisTsmTap& tap : taps) {
                const int ring = int(tap.ring);
                const double footprint = tap.area * rt * rt;
                const double v = 0.5 * std::log2(std::max(footprint, 1.0));
                cond.floor(v - 0.5);  // rint's boundaries are half-integers
                const int lod =
                    std::clamp(int(std::nearbyint(v)) - 1, 0, int(py.levels.size()) - 1);
                const double scale = 1.0 / double(1 << lod);
                glm::dvec4 f, pp;
                cellBilinear(py, py.levels[size_t(lod)], (o.x + rt * tap.x) * scale - 0.5,
                             (o.y + rt * tap.y) * scale - 0.5, &f, &pp);
                if (!(pp.w > 0.0)) continue;
                const double dz = std::abs(glm::dot(glm::dvec3(pp) / pp.w - xo, travel));
                for (int c = 0; c < 3; ++c) {
                    const double term =
                        f[c] * footprint * scale * scale * test::lookup(rings[size_t(ring)], dz, c);
                    want[j][c] += term;
                    mag[j][c] += std::abs(term);
                }
            }
        }
        ASSERT_EQ(cond.close, 0) << "a footprint on a mip-level boundary: choose another radius";
        for (int accumulate : {0, 1}) {
            run(filter, pts.size(), p, int(pts.size()), l, source, F, P, levels,
                int(py.levels.size()), tapBuf, int(taps.size()), ringBuf, base.info, radius,
                accumulate, out);
            const std::vector<cl_float4> got = download<cl_float4>(out, pts.size());
            const double times = accumulate ? 2.0 : 1.0;
            // Tolerance: 1e-5 of Σ|terms| (21 float products summed; Δz moves
            // by float rounding where |Rd̄'| ≤ 2.5·(ring + 1)).
            for (size_t j = 0; j < pts.size(); ++j)
                for (int c = 0; c < 3; ++c)
                    ASSERT_NEAR(got[j].s[c], times * want[j][c], 1e-5 * times * mag[j][c] + 1e-12)
                        << (point ? "point" : "directional") << " light, point " << j << " channel "
                        << c << " accumulate " << accumulate;
        }
        int lit = 0;
        for (const glm::dvec3& b : want) lit += b.x > 0.0;
        EXPECT_GT(lit, 30) << "the test sees light";
    }
}

}  // namespace
}  // namespace tsis
