// Tables 4.1–4.4 of the thesis on this machine: preprocessing ms and
// integration fps against N for each model, for tsis, lss and hybrid.
// One Renderer for everything; medians of repeated frames with min/max.
//   tsis:   preprocessing = gl_flux_atlas + gl_to_cl_flux_atlas + gl_to_cl_position_atlas + cdf +
//   sample; integration = gather hybrid: the same for its global part + gl_to_cl_light_maps;
//   integration = global_gather + local_ltsm lss:    preprocessing = gl_gbuffer + gl_to_cl_gbuffer
//   + lss_prepare + lss_upload;
//           integration = lss_gather (N = samples per pixel)
#include <cstdio>
#include <map>

#include "bench_common.h"
#include "render/method.h"
#include "util/progress.h"

namespace tsis::bench {
namespace {

struct MethodStages {
    const char* method;
    std::vector<std::string> preprocessing, integration;
};

const MethodStages kMethods[] = {
    {"tsis",
     {"gl_flux_atlas", "gl_to_cl_flux_atlas", "gl_to_cl_position_atlas", "cdf", "sample"},
     {"gather"}},
    {"lss", {"gl_gbuffer", "gl_to_cl_gbuffer", "lss_prepare", "lss_upload"}, {"lss_gather"}},
    {"hybrid",
     {"gl_flux_atlas", "gl_to_cl_flux_atlas", "gl_to_cl_position_atlas", "gl_to_cl_light_maps",
      "global_cdf", "global_sample"},
     {"global_gather", "local_ltsm"}},
};

int run(const BenchArgs& a) {
    // The thesis' sphere and five real meshes of 2.9K–20K triangles.
    std::vector<std::string> meshes = {"builtin:sphere",     "cow",      "head", "elephant",
                                       "ChineseDragon-10kv", "lion-head"};
    std::vector<int> ns = {49, 100, 169, 256, 400, 900, 1600, 2500};
    std::vector<std::string> lssMeshes = {"cow", "head"};
    if (a.quick) {
        meshes = {"builtin:sphere", "cow"};
        ns = {49, 900};
    }
    const std::vector<std::string> registered = methodNames();
    Renderer renderer;
    const std::string machine = machineLine(renderer);
    Table csv({"method", "mesh", "triangles", "covered_pixels", "N", "preprocessing_ms_median",
               "preprocessing_ms_min", "preprocessing_ms_max", "integration_ms_median",
               "integration_ms_min", "integration_ms_max", "integration_fps_median",
               "frame_ms_median", "frames", "load1"});
    // method → mesh → N → cell text
    std::map<std::string, std::map<std::string, std::map<int, std::pair<std::string, std::string>>>>
        cells;
    std::map<std::string, std::string> triangles;
    Progress progress("tables", static_cast<long long>(meshes.size() * ns.size() * 3));
    long long done = 0;
    for (const std::string& mesh : meshes) {
        BenchCase c = makeThesisCase({"--mesh", mesh, "--material", "marble", "--size-mm", "10"});
        for (const MethodStages& m : kMethods) {
            if (std::find(registered.begin(), registered.end(), m.method) == registered.end())
                continue;
            // lss costs ~10 ms per sample per frame here: the thesis' three
            // models for it (Tables 4.3/4.4), and 2 frames at N >= 900.
            const bool lss = std::string(m.method) == "lss";
            if (lss && std::find(lssMeshes.begin(), lssMeshes.end(), mesh) == lssMeshes.end())
                continue;
            for (int n : ns) {
                c.options.method = m.method;
                c.options.samples = n;
                const int frames = lss && n >= 900 ? std::min(a.frames, 2) : a.frames;
                const double load = loadAverage();
                // One warm-up frame per method and mesh (program builds, atlas, tables).
                std::vector<FrameStats> fs = renderFrames(renderer, c, frames, n == ns[0] ? 1 : 0);
                Summary pre = summarize(stageSums(fs, m.preprocessing));
                Summary integ = summarize(stageSums(fs, m.integration));
                Summary total = summarize(stageSums(fs, {"total"}));
                const std::string tris = std::to_string(c.scene.mesh.triangles.size());
                triangles[mesh] = tris;
                const double covered = fs.back().number("covered_pixels");
                csv.add({m.method, mesh, tris, fmt(covered, 0), std::to_string(n), fmt(pre.median),
                         fmt(pre.min), fmt(pre.max), fmt(integ.median), fmt(integ.min),
                         fmt(integ.max), fmt(1000.0 / integ.median, 1), fmt(total.median, 1),
                         std::to_string(frames), fmt(load)});
                cells[m.method][mesh][n] = {fmtRange(pre, 1), fmt(1000.0 / integ.median, 1) + " (" +
                                                                  fmt(1000.0 / integ.max, 1) + "–" +
                                                                  fmt(1000.0 / integ.min, 1) + ")"};
                progress.update(++done);
            }
        }
    }
    progress.finish();

    std::string md = "# Tables 4.1–4.4 on this machine\n\n";
    md += "Made by `bench/run.sh tables` (`build-bench/bench/bench_tables`) on " + timestamp() +
          ".\nMachine: " + machine + ".\n";
    md += "Scene: marble, 10 mm, default lights, 512×512, atlas 1024². Median (min–max) of " +
          std::to_string(a.frames) +
          " frames (lss at N ≥ 900: 2), one warm-up frame per method and model, one Renderer "
          "for all. Load "
          "average (1 min) per row in tables.csv.\n\n";
    const char* titles[3][2] = {
        {"Table 4.1 — tsis preprocessing (ms): flux atlas + hand-off + CDF + sampling",
         "Table 4.2 — tsis integration (fps = 1000 / gather ms)"},
        {"Table 4.3 — lss preprocessing (ms): camera G-buffer with irradiance + hand-off + prepare",
         "Table 4.4 — lss integration (fps = 1000 / lss_gather ms), N = samples per pixel"},
        {"hybrid preprocessing (ms): flux atlas + light maps + hand-offs + CDF + sampling",
         "hybrid integration (fps = 1000 / (global gather + local ltsm) ms)"}};
    for (int k = 0; k < 3; ++k) {
        const std::string method = kMethods[k].method;
        if (!cells.count(method)) continue;
        for (int part = 0; part < 2; ++part) {
            std::vector<std::string> header = {"model", "triangles"};
            for (int n : ns) header.push_back("N=" + std::to_string(n));
            Table t(header);
            for (const std::string& mesh : meshes) {
                if (!cells[method].count(mesh)) continue;
                std::vector<std::string> row = {mesh, triangles[mesh]};
                for (int n : ns)
                    row.push_back(part == 0 ? cells[method][mesh][n].first
                                            : cells[method][mesh][n].second);
                t.add(row);
            }
            md += std::string("## ") + titles[k][part] + "\n\n" + t.markdown() + "\n";
        }
    }
    writeResult("tables.csv", csv.csv());
    writeResult("tables.md", md);
    std::printf("wrote %s/tables.{md,csv}\n", resultsDir().c_str());
    return 0;
}

}  // namespace
}  // namespace tsis::bench

int main(int argc, char** argv) {
    return tsis::bench::guardedMain(tsis::bench::run, argc, argv, 3);
}
