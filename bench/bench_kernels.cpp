// Kernel efficiency: the device's FMA peak and memory bandwidth from
// microbenchmark kernels (bench/bench_peak.cl), next to the production
// kernels measured in the same process, runs interleaved so that load from
// other processes hits all alike:
//   * the gather (Rd evaluations/s) on the PERF-NOTES scenario (105k points ×
//     900 samples) in each layout, and inside real frames (cow, marble, N = 900);
//   * the CDF pyramid (bytes/s) and the sample draw at atlas 1024².
// Times from CL profiling events. Writes kernels.{md,csv}.
#include <cmath>
#include <cstdio>
#include <random>

#include "bench_common.h"
#include "cl/gather.h"
#include "cl/importance_sampler.h"
#include "cl/launch.h"
#include "util/embedded.h"
#include "util/progress.h"

namespace tsis {
// bench_peak.cl, embedded by bench/CMakeLists.txt.
const std::vector<EmbeddedFile>& benchKernels();
}  // namespace tsis

namespace tsis::bench {
namespace {

// Flops per Rd evaluation in the vector gather, an FMA counted as 2:
// d = xo − xi (3), |d|² (1 mul + 2 FMA = 5), sqrt (1), r·inv_step (1),
// fraction (1), interpolation v + t·step per channel (3 FMA = 6), the
// weighted accumulation b += w·f per channel (3 FMA = 6).
constexpr double kFlopsPerEvaluation = 23;

constexpr int kPoints = 105000, kSamples = 900, kAtlas = 1024;

std::vector<cl_float4> hemispherePoints(int count) {
    const int side = static_cast<int>(std::ceil(std::sqrt(double(count))));
    std::vector<cl_float4> p;
    for (int y = 0; y < side && static_cast<int>(p.size()) < count; ++y)
        for (int x = 0; x < side && static_cast<int>(p.size()) < count; ++x) {
            const float u = 2.0f * (x + 0.5f) / side - 1.0f, v = 2.0f * (y + 0.5f) / side - 1.0f;
            const float z = std::sqrt(std::max(0.0f, 1.0f - std::min(1.0f, u * u + v * v)));
            p.push_back({{5.0f * u, 5.0f * v, 5.0f * z, 0.0f}});
        }
    return p;
}

struct Gauge {
    std::string name, unit;
    std::vector<double> ms;
    double work = 0;  // flops, bytes or evaluations per run
};

int run(const BenchArgs& a) {
    const int runs = a.frames;
    Renderer renderer;
    ClRuntime& cl = renderer.cl();
    cl.addKernelFiles(benchKernels());
    cl::CommandQueue& q = cl.queue();
    const std::string machine = machineLine(renderer);
    const double load0 = loadAverage();

    // FMA peak.
    const int fmaItems = 2048, fmaIters = a.quick ? 2000 : 20000;
    cl::Buffer fmaOut(cl.context(), CL_MEM_WRITE_ONLY, fmaItems * sizeof(float));
    cl::Kernel fma16 = cl.kernel("bench_peak.cl", "bench_fma16");
    cl::Kernel fma8 = cl.kernel("bench_peak.cl", "bench_fma8");
    for (cl::Kernel* k : {&fma16, &fma8}) setKernelArgs(*k, fmaOut, fmaIters, 0.999f, 1e-3f);
    // Bandwidth: 128 MiB buffers.
    const size_t bwBytes = size_t(128) << 20, per = 256;
    const size_t bwItems = bwBytes / 64 / per;
    cl::Buffer bwIn(cl.context(), CL_MEM_READ_WRITE, bwBytes),
        bwOut(cl.context(), CL_MEM_READ_WRITE, bwBytes);
    q.enqueueFillBuffer(bwIn, 1.0f, 0, bwBytes);
    cl::Kernel copy = cl.kernel("bench_peak.cl", "bench_copy");
    setKernelArgs(copy, bwIn, bwOut, static_cast<int>(per));
    cl::Kernel readSum = cl.kernel("bench_peak.cl", "bench_read_sum");
    setKernelArgs(readSum, bwIn, bwOut, static_cast<int>(per));

    // Gather inputs: points over a hemisphere, samples over a sphere of 5 mm,
    // a table covering the whole diameter.
    std::vector<cl_float4> pts = hemispherePoints(kPoints);
    std::mt19937 rng(2);
    std::normal_distribution<float> g;
    std::vector<TsisSample> samples(kSamples);
    for (TsisSample& s : samples) {
        float v[3] = {g(rng), g(rng), g(rng)};
        const float k = 5.0f / std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        s = {v[0] * k, v[1] * k, v[2] * k, 0.0f, 1.0f, 1.0f, 1.0f, 0.0f};
    }
    std::vector<float> rgba(4 * TSIS_TABLE_SIZE);
    const float rMax = 10.5f;
    for (int k = 0; k < TSIS_TABLE_SIZE; ++k) {
        const float r = k * rMax / (TSIS_TABLE_SIZE - 1);
        rgba[4 * k] = std::exp(-r);
        rgba[4 * k + 1] = std::exp(-2 * r);
        rgba[4 * k + 2] = std::exp(-3 * r);
    }
    const TsisTableInfo info{rMax, (TSIS_TABLE_SIZE - 1) / rMax, TSIS_TABLE_SIZE, 0};
    const TsisTableInfo smallInfo{rMax, 1023 / rMax, 1024, 0};
    auto upload = [&](const void* data, size_t bytes) {
        return cl::Buffer(cl.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, bytes,
                          const_cast<void*>(data));
    };
    cl::Buffer pBuf = upload(pts.data(), pts.size() * sizeof(cl_float4));
    cl::Buffer sBuf = upload(samples.data(), samples.size() * sizeof(TsisSample));
    cl::Buffer tBuf = upload(rgba.data(), rgba.size() * sizeof(float));
    cl::Buffer outBuf(cl.context(), CL_MEM_READ_WRITE, kPoints * sizeof(cl_float4));
    struct Layout {
        int width;
        bool interleaved;
    };
    const std::vector<Layout> layouts = {
        {1, false}, {8, false}, {16, false}, {8, true}, {16, true}};
    std::vector<Gatherer> gatherers;
    for (const Layout& l : layouts) gatherers.emplace_back(cl, l.width, l.interleaved);

    // CDF pyramid and draw at atlas 1024² over random flux.
    std::vector<cl_float4> flux(size_t(kAtlas) * kAtlas);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (cl_float4& f : flux) f = {{u(rng), u(rng), u(rng), 0.0f}};
    cl::Buffer fBuf = upload(flux.data(), flux.size() * sizeof(cl_float4));
    cl::Buffer drawn(cl.context(), CL_MEM_READ_WRITE, kSamples * sizeof(TsisSample));
    ImportanceSampler sampler(cl);
    // Bytes the pyramid moves: level 0 reads float4 flux, writes Y; each
    // further level reads its parent's 4 floats per texel and writes 1.
    double pyramidBytes = double(kAtlas) * kAtlas * (16 + 4);
    for (double n = double(kAtlas) * kAtlas / 4; n >= 1; n /= 4) pyramidBytes += n * (16 + 4);

    // A real frame.
    BenchCase frame = makeThesisCase({"--mesh", "cow", "--material", "marble"});

    std::vector<Gauge> gauges;
    gauges.push_back(
        {"FMA float16 chains", "GFLOP/s", {}, double(fmaItems) * fmaIters * 8 * 16 * 2});
    gauges.push_back({"FMA float8 chains", "GFLOP/s", {}, double(fmaItems) * fmaIters * 8 * 8 * 2});
    gauges.push_back({"copy 128 MiB (read + write)", "GB/s", {}, 2.0 * bwBytes});
    gauges.push_back({"read-sum 128 MiB", "GB/s", {}, double(bwBytes)});
    for (const Layout& l : layouts)
        gauges.push_back({"gather " + std::to_string(l.width) + " points/item" +
                              (l.width > 1 ? (l.interleaved ? ", interleaved rows" : ", split rows")
                                           : ", float4 table"),
                          "G eval/s",
                          {},
                          double(kPoints) * kSamples});
    // Diagnostic: the same kernel with a 1024-entry table (24 KB, fits L1)
    // instead of 8192 (192 KB): how much the table's cache footprint costs.
    gauges.push_back({"gather 8 points/item, split rows, 1024-entry table (diagnostic)",
                      "G eval/s",
                      {},
                      double(kPoints) * kSamples});
    gauges.push_back({"CDF pyramid 1024²", "GB/s", {}, pyramidBytes});
    gauges.push_back({"draw 900 samples", "M samples/s", {}, double(kSamples)});
    gauges.push_back({"gather in a frame (cow, marble, N=900)", "G eval/s", {}, 0});
    gauges.push_back({"cdf in a frame", "GB/s", {}, pyramidBytes});

    auto timeKernel = [&](cl::Kernel& k, size_t global, size_t local) {
        cl::Event e;
        q.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(global), cl::NDRange(local), nullptr,
                               &e);
        return eventMilliseconds(e);
    };
    Progress progress("kernels", runs + 1);
    std::vector<double> loads;
    for (int r = -1; r < runs; ++r) {  // r = -1: builds and warms, not recorded
        loads.push_back(loadAverage());
        std::vector<double> ms;
        ms.push_back(timeKernel(fma16, fmaItems, 64));
        ms.push_back(timeKernel(fma8, fmaItems, 64));
        ms.push_back(timeKernel(copy, bwItems, 64));
        ms.push_back(timeKernel(readSum, bwItems, 64));
        for (Gatherer& gt : gatherers) {
            gt.run(pBuf, kPoints, sBuf, kSamples, tBuf, info, outBuf);
            ms.push_back(gt.lastMs());
        }
        gatherers[1].run(pBuf, kPoints, sBuf, kSamples, tBuf, smallInfo, outBuf);
        ms.push_back(gatherers[1].lastMs());
        sampler.buildPyramid(fBuf, kAtlas);
        ms.push_back(sampler.lastPyramidMs());
        sampler.draw(fBuf, fBuf, kAtlas, kSamples, 1, drawn);
        ms.push_back(sampler.lastDrawMs());
        FrameStats fs = renderer.render(frame.scene, frame.options).stats;
        ms.push_back(fs.stageMs("gather"));
        gauges[gauges.size() - 2].work = fs.number("rd_evaluations");
        ms.push_back(fs.stageMs("cdf"));
        if (r >= 0)
            for (size_t i = 0; i < gauges.size(); ++i) gauges[i].ms.push_back(ms[i]);
        progress.update(r + 2);
    }
    progress.finish();

    // Throughput per gauge: work / time, in the unit's scale.
    auto scale = [](const std::string& unit) { return unit == "M samples/s" ? 1e6 : 1e9; };
    Table csv({"what", "unit", "ms_median", "ms_min", "ms_max", "throughput_median",
               "throughput_at_min_ms"});
    Table md({"what", "ms median (min–max)", "throughput (median; best)"});
    std::vector<double> rate(gauges.size());
    for (size_t i = 0; i < gauges.size(); ++i) {
        Summary s = summarize(gauges[i].ms);
        const double k = scale(gauges[i].unit);
        rate[i] = gauges[i].work / (s.median * 1e-3) / k;
        const double best = gauges[i].work / (s.min * 1e-3) / k;
        csv.add({gauges[i].name, gauges[i].unit, fmt(s.median, 3), fmt(s.min, 3), fmt(s.max, 3),
                 fmt(rate[i], 3), fmt(best, 3)});
        md.add({gauges[i].name, fmtRange(s, 2),
                fmt(rate[i], 2) + " " + gauges[i].unit + "; " + fmt(best, 2)});
    }
    const double peak = rate[0], bandwidth = std::max(rate[2], rate[3]);
    const size_t g8 = 5, gFrame = gauges.size() - 2;  // gather 8 split; in a frame
    Summary load = summarize(loads);
    std::string text =
        "# Kernel efficiency\n\nMade by `bench/run.sh kernels` "
        "(`build-bench/bench/bench_kernels`) on " +
        timestamp() + ".\nMachine: " + machine + ".\nLoad average (1 min) " + fmtRange(load, 2) +
        " over the runs (" + fmt(load0, 2) + " at start). Median of " + std::to_string(runs) +
        " interleaved runs, CL profiling.\n\n" + md.markdown() + "\n";
    text += "Ratios (medians of the same runs):\n\n";
    text += "* Operation count assumed: " + fmt(kFlopsPerEvaluation, 0) +
            " flops per Rd evaluation (FMA = 2): distance 3 sub + 5, sqrt 1, index 2, "
            "interpolation 3 FMA, accumulation 3 FMA; table reads not counted.\n";
    for (size_t i = 4; i < 4 + layouts.size(); ++i)
        text += "* " + gauges[i].name + ": " + fmt(rate[i], 2) +
                " G eval/s = " + fmt(100 * rate[i] * kFlopsPerEvaluation / peak, 1) +
                "% of the float16 FMA peak (" + fmt(peak, 0) + " GFLOP/s)\n";
    text += "* gather in a frame: " + fmt(rate[gFrame], 2) +
            " G eval/s = " + fmt(100 * rate[gFrame] * kFlopsPerEvaluation / peak, 1) +
            "% of FMA peak (" + fmt(rate[gFrame] / rate[g8], 2) +
            "× the synthetic 8-lane figure)\n";
    text += "* the same 8-lane gather with a 1024-entry table (fits L1): " + fmt(rate[9], 2) +
            " G eval/s, " + fmt(rate[9] / rate[g8], 2) + "× the 8192-entry table\n";
    text += "* CDF pyramid: " + fmt(rate[10], 2) + " GB/s = " + fmt(100 * rate[10] / bandwidth, 1) +
            "% of the best of copy/read-sum (" + fmt(bandwidth, 1) + " GB/s), assuming " +
            fmt(pyramidBytes / 1e6, 1) + " MB moved; in a frame " +
            fmt(100 * rate[gFrame + 1] / bandwidth, 1) + "%\n";
    text += "* sample draw: " + fmt(1e3 * summarize(gauges[11].ms).median / kSamples, 3) +
            " µs per sample (11 dependent levels of 4 reads each: latency-bound, not bandwidth)\n";
    writeResult("kernels.csv", csv.csv());
    writeResult("kernels.md", text);
    std::printf("%s", text.c_str());
    return 0;
}

}  // namespace
}  // namespace tsis::bench

int main(int argc, char** argv) {
    return tsis::bench::guardedMain(tsis::bench::run, argc, argv, 7);
}
