#include "bench_common.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "cli/scene_options.h"
#include "compare/image_compare.h"
#include "util/args.h"
#include "util/error.h"
#include "util/output_file.h"

namespace tsis::bench {

BenchCase makeCase(const std::vector<std::string>& renderArgs) {
    Args args("bench", sceneOptionSpecs(), renderArgs);
    BenchCase c{sceneFromArgs(args), renderOptionsFromArgs(args)};
    // Repeated frames of one case stand for frames whose lighting changed (the
    // thesis' tables time the flux atlas every frame): nothing is reused.
    c.options.reuseLighting = false;
    return c;
}

BenchCase makeThesisCase(std::vector<std::string> renderArgs) {
    // The thesis' atlas too: 512² whatever the object's size (not --atlas-res 0's choice).
    renderArgs.insert(renderArgs.begin(), {"--model", "thesis", "--atlas-res", "512"});
    return makeCase(renderArgs);
}

Summary summarize(std::vector<double> v) {
    Summary s;
    s.count = static_cast<int>(v.size());
    if (v.empty()) return s;
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    s.median = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
    s.min = v.front();
    s.max = v.back();
    return s;
}

std::vector<FrameStats> renderFrames(Renderer& renderer, const BenchCase& c, int frames,
                                     int warmup) {
    std::vector<FrameStats> out;
    for (int i = 0; i < warmup; ++i) renderer.render(c.scene, c.options);
    for (int i = 0; i < frames; ++i) out.push_back(renderer.render(c.scene, c.options).stats);
    return out;
}

std::vector<double> stageSums(const std::vector<FrameStats>& frames,
                              const std::vector<std::string>& stages) {
    std::vector<double> out;
    for (const FrameStats& f : frames) {
        double ms = 0;
        for (const std::string& s : stages) ms += f.stageMs(s);
        out.push_back(ms);
    }
    return out;
}

ReferenceImage renderReference(Renderer& renderer, BenchCase c) {
    c.options.method = "reference";
    c.options.keepAovs = true;
    FrameResult f = renderer.render(c.scene, c.options);
    return {f.radiance, f.coverage, f.stats.stageMs("total")};
}

double relativeRmse(const FrameResult& frame, const ReferenceImage& ref) {
    return compareImages(frame.radiance, ref.radiance, &ref.coverage, "method", "reference")
        .metrics.relRmse;
}

double loadAverage() {
    std::ifstream in("/proc/loadavg");
    double l = -1;
    in >> l;
    return l;
}

std::string machineLine(Renderer& renderer) {
    std::ifstream in("/proc/cpuinfo");
    std::string line, model = "unknown CPU";
    while (std::getline(in, line))
        if (line.rfind("model name", 0) == 0) {
            model = line.substr(line.find(':') + 2);
            break;
        }
    std::ostringstream s;
    s << model << ", " << std::thread::hardware_concurrency() << " cores; OpenCL "
      << renderer.cl().deviceName() << "; GL " << renderer.glRenderer() << " ("
      << renderer.glPlatform() << ")";
    return s.str();
}

std::string timestamp() {
    std::time_t t = std::time(nullptr);
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%MZ", std::gmtime(&t));
    return buf;
}

std::string Table::csv() const {
    std::ostringstream s;
    auto row = [&](const std::vector<std::string>& r) {
        for (size_t i = 0; i < r.size(); ++i) s << (i ? "," : "") << r[i];
        s << "\n";
    };
    row(header_);
    for (const auto& r : rows_) row(r);
    return s.str();
}

std::string Table::markdown() const {
    std::ostringstream s;
    auto row = [&](const std::vector<std::string>& r) {
        s << "|";
        for (const std::string& c : r) s << " " << c << " |";
        s << "\n";
    };
    row(header_);
    s << "|";
    for (size_t i = 0; i < header_.size(); ++i) s << "---|";
    s << "\n";
    for (const auto& r : rows_) row(r);
    return s.str();
}

std::string fmt(double v, int decimals) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

std::string fmtRange(const Summary& s, int decimals) {
    return fmt(s.median, decimals) + " (" + fmt(s.min, decimals) + "–" + fmt(s.max, decimals) + ")";
}

std::string resultsDir() {
    if (const char* e = std::getenv("TSIS_BENCH_RESULTS")) return e;
    return TSIS_BENCH_RESULTS_DIR;
}

void writeResult(const std::string& name, const std::string& text) {
    std::filesystem::create_directories(resultsDir());
    writeTextFile(std::filesystem::path(resultsDir()) / name, text);
}

BenchArgs parseBenchArgs(int argc, char** argv, int defaultFrames) {
    BenchArgs a;
    a.frames = defaultFrames;
    for (int i = 1; i < argc; ++i) {
        std::string s = argv[i];
        if (s == "--quick")
            a.quick = true;
        else if (s == "--frames" && i + 1 < argc)
            a.frames = std::max(1, std::atoi(argv[++i]));
        else
            a.rest.push_back(s);
    }
    return a;
}

int guardedMain(int (*body)(const BenchArgs&), int argc, char** argv, int defaultFrames) {
    try {
        return body(parseBenchArgs(argc, argv, defaultFrames));
    } catch (const Error& e) {
        std::fprintf(stderr, "bench: error: %s\n", e.what());
    } catch (const cl::Error& e) {
        std::fprintf(stderr, "bench: error: OpenCL call %s failed with code %d\n", e.what(),
                     e.err());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench: error: %s\n", e.what());
    }
    return 1;
}

}  // namespace tsis::bench
