// Throughput of the gather layouts in the PERF-NOTES scenario (≈105k covered
// pixels × N = 900). Not a correctness test: skipped unless TSIS_CL_BENCH is
// set, e.g. `TSIS_CL_BENCH=1 tsis_cl_tests --gtest_filter='GatherBench*'`.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <thread>

#include "cl/cl_test_fixture.h"
#include "cl/gather.h"
#include "cl/importance_sampler.h"

namespace tsis {
namespace {

using test::ClTest;

double cpuSeconds() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

// Points as a camera sees them: a 324 x 324 grid over a hemisphere of radius
// 5 mm (a 10 mm object) in scanline order, so neighbouring work-items hold
// neighbouring surface points, as covered pixels do.
std::vector<cl_float4> pixelPoints(int count) {
    const int side = int(std::ceil(std::sqrt(double(count))));
    std::vector<cl_float4> p;
    for (int y = 0; y < side && int(p.size()) < count; ++y) {
        for (int x = 0; x < side && int(p.size()) < count; ++x) {
            const float u = 2.0f * (x + 0.5f) / side - 1.0f;
            const float v = 2.0f * (y + 0.5f) / side - 1.0f;
            const float z = std::sqrt(std::max(0.0f, 1.0f - std::min(1.0f, u * u + v * v)));
            p.push_back({{5.0f * u, 5.0f * v, 5.0f * z, 0.0f}});
        }
    }
    return p;
}

// Samples anywhere on a sphere of radius 5 mm; the table covers the whole
// diameter so every pair is evaluated.
std::vector<cl_float4> spherePoints(int count, uint32_t seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<float> g;
    std::vector<cl_float4> p(count);
    for (cl_float4& x : p) {
        float v[3] = {g(rng), g(rng), g(rng)};
        const float s = 5.0f / std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        x = {{v[0] * s, v[1] * s, v[2] * s, 0.0f}};
    }
    return p;
}

using GatherBench = ClTest;

TEST_F(GatherBench, RdEvaluationsPerSecond) {
    if (!std::getenv("TSIS_CL_BENCH")) GTEST_SKIP() << "set TSIS_CL_BENCH=1 to run";
    const int count = 105000;
    const int n = 900;
    const int runs =
        std::getenv("TSIS_CL_BENCH_RUNS") ? std::atoi(std::getenv("TSIS_CL_BENCH_RUNS")) : 7;

    const std::vector<cl_float4> points = pixelPoints(count);
    std::vector<TsisSample> samples(n);
    const std::vector<cl_float4> sp = spherePoints(n, 2);
    for (int i = 0; i < n; ++i)
        samples[i] = {sp[i].s[0], sp[i].s[1], sp[i].s[2], 0.0f, 1.0f, 1.0f, 1.0f, 0.0f};
    std::vector<float> rgba(4 * TSIS_TABLE_SIZE);
    const float rMax = 10.5f;
    for (int k = 0; k < TSIS_TABLE_SIZE; ++k) {
        const float r = k * rMax / (TSIS_TABLE_SIZE - 1);
        rgba[4 * k] = std::exp(-r);
        rgba[4 * k + 1] = std::exp(-2 * r);
        rgba[4 * k + 2] = std::exp(-3 * r);
    }
    const TsisTableInfo info{rMax, (TSIS_TABLE_SIZE - 1) / rMax, TSIS_TABLE_SIZE, 0};
    cl::Buffer p = upload(points);
    cl::Buffer s = upload(samples);
    cl::Buffer t = upload(rgba);
    cl::Buffer out = buffer(count * sizeof(cl_float4));

    std::printf("gather %d points x %d samples on %s, median of %d runs (CL profiling)\n", count, n,
                rt.deviceName().c_str(), runs);
    // Interleaved runs, so that load from other processes on the machine hits
    // every layout alike.
    const std::vector<int> widths = {1, 8, 16};
    std::vector<Gatherer> gatherers;
    for (int w : widths) {
        gatherers.emplace_back(rt, w);
        gatherers.back().run(p, count, s, n, t, info, out);  // first use: build, warm caches
        gatherers.back().lastMs();
    }
    // Also the process's CPU time per run: on a machine shared with other jobs
    // the wall time is theirs too; evaluations per CPU-second times the cores
    // estimates what an idle machine does.
    std::vector<std::vector<double>> ms(widths.size()), cpu(widths.size());
    for (int r = 0; r < runs; ++r) {
        for (size_t k = 0; k < widths.size(); ++k) {
            const double c0 = cpuSeconds();
            gatherers[k].run(p, count, s, n, t, info, out);
            ms[k].push_back(gatherers[k].lastMs());
            cpu[k].push_back(cpuSeconds() - c0);
        }
    }
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    for (size_t k = 0; k < widths.size(); ++k) {
        std::sort(ms[k].begin(), ms[k].end());
        std::sort(cpu[k].begin(), cpu[k].end());
        const double median = ms[k][ms[k].size() / 2];
        const double evals = double(gatherers[k].lastEvaluations());
        std::printf(
            "  %2d points/work-item: %8.2f ms  %.3f G evaluations/s  (min %.2f, max %.2f ms); "
            "CPU %.3f s/run -> %.3f G/s on %u idle cores\n",
            widths[k], median, evals / (median * 1e6), ms[k].front(), ms[k].back(),
            cpu[k][cpu[k].size() / 2], cores * evals / (cpu[k][cpu[k].size() / 2] * 1e9), cores);
    }
}

TEST_F(GatherBench, PyramidAndDraw) {
    if (!std::getenv("TSIS_CL_BENCH")) GTEST_SKIP() << "set TSIS_CL_BENCH=1 to run";
    for (int res : {512, 1024}) {
        std::mt19937 rng(3);
        std::uniform_real_distribution<float> u(0.0f, 1.0f);
        std::vector<cl_float4> flux(size_t(res) * res);
        for (cl_float4& f : flux) f = {{u(rng), u(rng), u(rng), 0.0f}};
        cl::Buffer f = upload(flux);
        cl::Buffer samples = buffer(900 * sizeof(TsisSample));
        ImportanceSampler sampler(rt);
        std::vector<double> pyr, draw;
        for (int r = 0; r < 8; ++r) {
            sampler.buildPyramid(f, res);
            sampler.draw(f, f, res, 900, r, samples);
            if (r == 0) continue;  // first use: builds
            pyr.push_back(sampler.lastPyramidMs());
            draw.push_back(sampler.lastDrawMs());
        }
        std::sort(pyr.begin(), pyr.end());
        std::sort(draw.begin(), draw.end());
        std::printf("res %d: pyramid %.2f ms (%d levels), draw 900 samples %.3f ms (medians)\n",
                    res, pyr[pyr.size() / 2], std::countr_zero(unsigned(res)) + 1,
                    draw[draw.size() / 2]);
    }
}

}  // namespace
}  // namespace tsis
