// What every benchmark program shares: scenes built exactly as `tsis render`
// builds them, medians with min/max, the machine's state (load average) and
// results written as Markdown + CSV under bench/results/ (atomically).
#pragma once

#include <string>
#include <vector>

#include "render/render_options.h"
#include "render/renderer.h"
#include "scene/scene.h"

namespace tsis::bench {

// A scene and options from `tsis render` arguments ("--mesh", "cow", ...).
struct BenchCase {
    Scene scene;
    RenderOptions options;
};
BenchCase makeCase(const std::vector<std::string>& renderArgs);
// The same under the thesis' model (--model thesis) and its 512² atlas: the
// benches that reproduce the thesis' tables keep them, so the reproduction
// does not move.
BenchCase makeThesisCase(std::vector<std::string> renderArgs);

struct Summary {
    double median = 0, min = 0, max = 0;
    int count = 0;
};
Summary summarize(std::vector<double> values);

// Renders `frames` frames after `warmup` unmeasured ones with one Renderer and
// returns every measured frame's stats.
std::vector<FrameStats> renderFrames(Renderer& renderer, const BenchCase& c, int frames,
                                     int warmup = 1);
// Per frame, the sum of the named stages' ms.
std::vector<double> stageSums(const std::vector<FrameStats>& frames,
                              const std::vector<std::string>& stages);

// Radiance (and coverage) of a frame rendered with keepAovs, and the relative
// RMSE of a frame's radiance against it over the reference's covered pixels.
struct ReferenceImage {
    ImageF radiance, coverage;
    double ms = 0;  // what the reference frame cost
};
ReferenceImage renderReference(Renderer& renderer, BenchCase c);
double relativeRmse(const FrameResult& frame, const ReferenceImage& ref);

// The 1-minute load average (/proc/loadavg), and a one-line description of the
// machine: CPU model, cores, OpenCL device.
double loadAverage();
std::string machineLine(Renderer& renderer);
std::string timestamp();  // UTC, ISO 8601

// A table: written as NAME.csv (all columns) and appended to a Markdown text.
class Table {
  public:
    explicit Table(std::vector<std::string> header) : header_(std::move(header)) {}
    void add(std::vector<std::string> row) { rows_.push_back(std::move(row)); }
    std::string csv() const;
    std::string markdown() const;

  private:
    std::vector<std::string> header_;
    std::vector<std::vector<std::string>> rows_;
};

std::string fmt(double v, int decimals = 2);
std::string fmtRange(const Summary& s, int decimals = 2);  // "median (min–max)"

// bench/results/ in the source tree, or $TSIS_BENCH_RESULTS when set.
std::string resultsDir();
void writeResult(const std::string& name,
                 const std::string& text);  // atomically, into resultsDir()

// Common command-line handling: `--quick` (fewer configurations) and `--frames N`.
struct BenchArgs {
    bool quick = false;
    int frames = 5;
    std::vector<std::string> rest;
};
BenchArgs parseBenchArgs(int argc, char** argv, int defaultFrames);

// Runs body, reporting tsis::Error / cl::Error as one line; the exit code.
int guardedMain(int (*body)(const BenchArgs&), int argc, char** argv, int defaultFrames);

}  // namespace tsis::bench
