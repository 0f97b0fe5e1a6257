// The dipole model's own error against volumetric light transport (issue 15,
// item 3): bench/results/physical.md and physical.csv.
//
//  1. Semi-infinite slab, a beam straight down (volumetric/slab.h, the light
//     tracer): total reflectance per entered flux, dipole closed form vs
//     volumetric; the radial profile's ratio volumetric/dipole in the bins
//     around 0.1, 0.3, 1, 3 and 10 mean free paths ℓ = 1/σt′ (bins of 1/10
//     decade, both averaged over the same annulus); the normal-view radiance
//     under a normal directional light, each exit term's over the volumetric.
//  2. Scenes: `tsis render --method reference` against `--method volumetric`
//     (radiance, relative RMSE over covered pixels, also after one global
//     scale), default lights and camera, small images.
//
//  --models (item 4): instead, per radial profile model (--profile) and exit
//     term (--exit), the same slab and scenes against volumetric transport:
//     bench/results/physical_models.md.
//  --truth (issue 24 item 2): instead, the two spheres' volumetric radiance
//     by the light tracer (volumetric/light_trace.h), the camera walk's
//     independent twin, into tests/validation/truth_*.exr (mean and standard
//     error per pixel) and truth.json (the interior pixels' mean per channel
//     and its standard error, from batches), for tests/volumetric_truth_test.cpp.
//     Batches of photons until the interior mean's error is below 1% in every
//     channel or --seconds (default 1200) per sphere run out.
//
// bench_physical [--quick] [--models | --truth [--seconds S]] [--photons N] [--spp N] [--size W]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "bench_common.h"
#include "compare/image_compare.h"
#include "image/image_io.h"
#include "physics/dipole.h"
#include "physics/fresnel.h"
#include "physics/material.h"
#include "render/profiles.h"
#include "scene/projection.h"
#include "util/error.h"
#include "util/json.h"
#include "util/output_file.h"
#include "util/parallel.h"
#include "util/timer.h"
#include "volumetric/light_trace.h"
#include "volumetric/mc_profile.h"
#include "volumetric/mesh_boundary.h"
#include "volumetric/slab.h"

namespace tsis::bench {
namespace {

const double kRadiiMfp[] = {0.1, 0.3, 1.0, 3.0, 10.0};
constexpr double kEventBudget = 2e8;  // scattering events per slab

// ∫ Rd 2πr dr over [r0, r1] (Simpson in r).
double integrateRd(const std::function<double(double)>& rd, double r0, double r1) {
    const int n = 200;
    const double h = (r1 - r0) / n;
    double s = 0;
    for (int k = 0; k <= n; ++k) {
        const double r = r0 + k * h;
        const double w = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0);
        s += w * rd(r) * 2.0 * M_PI * r;
    }
    return s * h / 3.0;
}

// A slab's volumetric trace within the event budget.
SlabResult traceBudgeted(const Material& m, long long photons) {
    const Medium medium(m);
    // A pilot for the walks' length, then photons within an event budget
    // (cream's walks are ~100× skin1's).
    SlabOptions o;
    o.photons = 2000;
    const double events = std::max(1.0, traceSlab(medium, o).meanEvents);
    o.photons = std::clamp(static_cast<long long>(kEventBudget / events), 20000LL, photons);
    const SlabResult r = traceSlab(medium, o);
    std::fprintf(stderr, "slab %s: %lld photons, %.1f events each\n", m.name.c_str(), o.photons,
                 r.meanEvents);
    return r;
}

// The slab materials: spectralon (σa = 0: R = 1 in both) left out.
bool slabMaterial(const BenchArgs& a, const Material& m) {
    if (a.quick && m.name != "marble" && m.name != "skin1") return false;
    return m.sigmaA != glm::dvec3(0.0);
}

// A method's radiance against the volumetric one over the covered pixels:
// relative RMSE, after the least-squares global scale, and that scale.
struct SceneError {
    double err, errScaled, scale;
};
SceneError sceneError(const ImageF& ref, const ImageF& vol, const ImageF& coverage) {
    const double err =
        compareImages(ref, vol, &coverage, "reference", "volumetric").metrics.relRmse;
    double num = 0, den = 0;
    for (size_t i = 0; i < vol.pixels.size(); ++i)
        if (coverage.pixels[i / 3] > 0.5) {
            num += vol.pixels[i] * ref.pixels[i];
            den += ref.pixels[i] * ref.pixels[i];
        }
    const double scale = den > 0 ? num / den : 0;
    ImageF scaled = ref;
    for (float& p : scaled.pixels) p = static_cast<float>(p * scale);
    return {err, compareImages(scaled, vol, &coverage, "reference", "volumetric").metrics.relRmse,
            scale};
}

struct SceneCase {
    std::string mesh, material, sizeMm;
    std::vector<std::string> args(int size) const {
        // The subsurface term alone: the GGX lobe and --aa's edge samples
        // would add the same reflected light to both images and dilute the error.
        return {"--mesh",
                mesh,
                "--material",
                material,
                "--size-mm",
                sizeMm,
                "--width",
                std::to_string(size),
                "--height",
                std::to_string(size),
                "--no-specular",
                "--aa",
                "1"};
    }
    std::string name() const { return mesh + " " + material + " " + sizeMm + " mm"; }
};

std::vector<SceneCase> sceneCases(const BenchArgs& a) {
    std::vector<SceneCase> scenes = {{"builtin:sphere", "marble", "10"},
                                     {"builtin:sphere", "skin1", "30"},
                                     {"builtin:default", "marble", "10"},
                                     {"builtin:default", "skin1", "10"},
                                     {"cow", "marble", "10"}};
    if (a.quick) scenes.resize(1);
    return scenes;
}

FrameResult renderVolumetric(Renderer& renderer, BenchCase c, int spp, uint32_t seed) {
    c.options.method = "volumetric";
    c.options.keepAovs = true;
    c.options.spp = spp;
    c.options.seed = seed;
    return renderer.render(c.scene, c.options);
}

long long optionValue(const std::vector<std::string>& rest, const std::string& name,
                      long long def) {
    for (size_t i = 0; i + 1 < rest.size(); ++i)
        if (rest[i] == name) return std::stoll(rest[i + 1]);
    return def;
}

const ProfileModel kModels[] = {ProfileModel::Dipole, ProfileModel::BetterDipole, ProfileModel::Pbd,
                                ProfileModel::Mc};
const ExitTerm kExits[] = {ExitTerm::Jensen, ExitTerm::Normalized};

const EnergyTarget kEnergies[] = {EnergyTarget::SemiInfinite, EnergyTarget::Object};

std::string combination(ProfileModel m, ExitTerm e, EnergyTarget t = EnergyTarget::SemiInfinite) {
    return std::string(profileModelName(m)) + " + " + exitTermName(e) +
           (t == EnergyTarget::Object ? " + energy object" : "");
}

// Item 4: every profile model and exit term against volumetric transport.
int runModels(const BenchArgs& a, long long photons, int spp, int size) {
    std::string md = "# Physical accuracy of the profile models and exit terms\n\n";
    md += "Made by `build/bench/bench_physical --models --photons " + std::to_string(photons) +
          " --spp " + std::to_string(spp) + " --size " + std::to_string(size) +
          "` (bench/bench_physical.cpp) on " + timestamp() +
          "; the slab and scenes of [physical.md](physical.md), each profile (`--profile`), "
          "exit term (`--exit`) and energy target (`--energy`) against `--method "
          "volumetric`.\n\n";
    std::vector<std::string> header = {"material", "channel", "R vol."};
    for (ProfileModel m : kModels)
        header.push_back(std::string("R ") + profileModelName(m) + " / vol.");
    for (ProfileModel m : kModels) header.push_back(std::string("shape ") + profileModelName(m));
    for (ProfileModel m : kModels)
        for (ExitTerm e : kExits) header.push_back("normal L " + combination(m, e) + " / vol.");
    Table slab(header);
    Table mc({"material", "channel", "α′", "R mc", "R std. error", "r99 / ℓ",
              "max bin rel. error within r99", "trusted to / ℓ", "simulation s", "cached load ms"});
    // Per combination: the sum of |normal L / vol. − 1| over the slab rows.
    std::vector<double> slabError(std::size(kModels) * std::size(kExits), 0.0);
    int rows = 0;
    const char* channels[] = {"R", "G", "B"};
    for (const Material& m : presetMaterials()) {
        if (!slabMaterial(a, m)) continue;
        const SlabResult r = traceBudgeted(m, photons);
        const Medium medium(m);
        {
            // --profile mc: its noise at the default path count, the cost of
            // its simulation and of reading it back from the disk cache.
            const McProfileInput in = mcProfileInput(m.sigmaSPrime, m.sigmaA, m.eta);
            // First use: its cache entry removed, simulated and stored; then
            // read back.
            if (const auto dir = mcProfileCacheDirectory())
                std::filesystem::remove(*dir / (mcProfileKey(in) + ".mcprofile"));
            const Timer simTimer;
            const McProfile p = mcProfileFromDisk(in, nullptr);
            const double simSeconds = simTimer.ms() / 1000.0;
            const Timer loadTimer;
            bool loaded = false;
            mcProfileFromDisk(in, &loaded);
            const std::string loadMs = loaded ? fmt(loadTimer.ms(), 2) : "no cache";
            for (int ch = 0; ch < 3; ++ch) {
                const double r99 = p.radiusHolding(ch, 0.99);
                double worst = 0;
                for (size_t b = 0; b + 1 < p.edges.size() && p.edges[b + 1] <= r99; ++b)
                    if (p.binFlux[b][ch] > 0 && p.edges[b] >= 0.1)
                        worst = std::max(worst, p.binFluxError[b][ch] / p.binFlux[b][ch]);
                mc.add({m.name, std::string("RGB").substr(ch, 1), fmt(in.albedo[ch], 4),
                        fmt(p.reflectance[ch], 4), fmt(p.reflectanceError[ch], 5), fmt(r99, 3),
                        fmt(100 * worst, 2) + "%", fmt(p.edges[p.trusted[ch]], 3),
                        fmt(simSeconds, 2), loadMs});
            }
        }
        const double ft0 = fresnelTransmittance(m.eta, 1.0);
        const double exits[] = {1.0, normalizedExitScale(m.eta)};
        for (int ch = 0; ch < 3; ++ch) {
            std::vector<std::string> row = {m.name, channels[ch], fmt(r.reflectance[ch], 4)};
            std::vector<std::string> shapes, normal;
            const double mfp = 1.0 / medium.sigmaT[ch];
            for (size_t mi = 0; mi < std::size(kModels); ++mi) {
                const KeyedProfile p = radialProfile(m, kModels[mi]);
                auto rd = [&](double x) { return p.f(x)[ch]; };
                // Total: geometric segments from 1e-4 to 300 free paths.
                double total = 0;
                for (double r0 = 1e-4; r0 < 300.0; r0 *= 1.5)
                    total += integrateRd(rd, r0 * mfp, 1.5 * r0 * mfp);
                row.push_back(fmt(total / r.reflectance[ch], 3));
                // Shape: exp(RMS of ln(vol./model)) over the bins in 0.1–10 ℓ.
                double sum = 0;
                int n = 0;
                for (size_t b = 0; b + 1 < r.edges.size(); ++b) {
                    if (r.edges[b] < 0.1 || r.edges[b + 1] > 10.0) continue;
                    const double model = integrateRd(rd, r.edges[b] * mfp, r.edges[b + 1] * mfp);
                    if (model <= 0 || r.binFlux[b][ch] <= 0) continue;
                    sum += std::pow(std::log(r.binFlux[b][ch] / model), 2);
                    ++n;
                }
                shapes.push_back(n ? fmt(std::exp(std::sqrt(sum / n)), 3) : "–");
                // Normal view, normal light of unit irradiance: L = Ft·B·(exit term).
                const double volL = ft0 * r.normalRadiance[ch];
                for (size_t e = 0; e < std::size(kExits); ++e) {
                    const double ratio = ft0 / M_PI * exits[e] * ft0 * total / volL;
                    normal.push_back(fmt(ratio, 3));
                    slabError[mi * std::size(kExits) + e] += std::abs(ratio - 1.0);
                }
            }
            row.insert(row.end(), shapes.begin(), shapes.end());
            row.insert(row.end(), normal.begin(), normal.end());
            slab.add(row);
            ++rows;
        }
    }

    // Scenes: one volumetric image each; a reference per model. The exit term
    // scales every pixel's radiance by its constant (1 or 1/c, the shader's
    // u_exitScale), so one reference per model gives both.
    Renderer renderer;
    std::vector<std::string> sceneHeader = {"combination", "slab: mean |normal L / vol. − 1|"};
    const std::vector<SceneCase> scenes = sceneCases(a);
    for (const SceneCase& s : scenes) sceneHeader.push_back(s.name() + ": rel. RMSE (scaled)");
    Table summary(sceneHeader);
    // Rows: model × exit × energy target (--energy object is 1 on the slab).
    const size_t nE = std::size(kEnergies);
    std::vector<std::vector<std::string>> cells(slabError.size() * nE);
    for (size_t k = 0; k < cells.size(); ++k) {
        const size_t me = k / nE;
        cells[k] = {combination(kModels[me / 2], kExits[me % 2], kEnergies[k % nE]),
                    fmt(100 * slabError[me] / std::max(rows, 1), 1) + "%"};
    }
    for (const SceneCase& s : scenes) {
        BenchCase c = makeThesisCase(s.args(size));
        const FrameResult vol = renderVolumetric(renderer, c, spp, 1);
        const double exits[] = {1.0, normalizedExitScale(c.scene.material.eta)};
        for (size_t mi = 0; mi < std::size(kModels); ++mi)
            for (size_t t = 0; t < nE; ++t) {
                c.options.profile = kModels[mi];
                c.options.energy = kEnergies[t];
                const ReferenceImage ref = renderReference(renderer, c);
                for (size_t e = 0; e < std::size(kExits); ++e) {
                    ImageF radiance = ref.radiance;
                    for (float& p : radiance.pixels) p = static_cast<float>(p * exits[e]);
                    const SceneError err = sceneError(radiance, vol.radiance, ref.coverage);
                    cells[(mi * 2 + e) * nE + t].push_back(fmt(100 * err.err, 1) + "% (" +
                                                           fmt(100 * err.errScaled, 1) + "%)");
                    std::fprintf(stderr, "%s %s: %.3f\n", s.name().c_str(),
                                 combination(kModels[mi], kExits[e], kEnergies[t]).c_str(),
                                 err.err);
                }
            }
    }
    for (const auto& row : cells) summary.add(row);
    md +=
        "## Which combination is closest\n\n"
        "Slab: the normal-view radiance under a normal light (as physical.md), mean over the "
        "presets' channels. Scenes: relative RMSE of `--method reference --profile P --exit E` "
        "against `--method volumetric` (radiance, covered pixels; after one global scale in "
        "parentheses), default lights and camera, " +
        std::to_string(size) + "², `--spp " + std::to_string(spp) + "`.\n\n" + summary.markdown() +
        "\n## Semi-infinite slab per preset\n\n"
        "R: total reflectance per entered flux (each model's ∫Rd 2πr dr, numerically). Shape: "
        "exp(RMS of ln(volumetric / model)) over the 1/10-decade annuli in 0.1–10 ℓ (1 = the "
        "same shape). Normal L: as physical.md, per model and exit term.\n\n" +
        slab.markdown() +
        "\n## The mc profile's noise and cost\n\n"
        "`--profile mc` (volumetric/mc_profile.h) at its default " +
        std::to_string(kMcProfilePaths) +
        " paths per (α′, η), on this run's first use (its cache entry removed): total reflectance "
        "and its standard error; r99, the radius "
        "holding 99 % of the binned flux; the largest relative standard error of a 1/10-decade "
        "annulus from 0.1 ℓ to r99 (batch means); where the tail fit takes over; seconds to "
        "simulate (all three channels at once, " +
        std::to_string(hostThreads()) +
        " threads) and milliseconds to load from the disk cache.\n\n" + mc.markdown() + "\n";
    writeResult("physical_models.md", md);
    std::printf("wrote %s/physical_models.md\n", resultsDir().c_str());
    return 0;
}

// Issue 24 item 2: the spheres' truth by light tracing.
int runTruth(const BenchArgs& a, int size) {
    const double budget = static_cast<double>(optionValue(a.rest, "--seconds", 1200));
    const std::vector<SceneCase> scenes = {{"builtin:sphere", "marble", "10"},
                                           {"builtin:sphere", "skin1", "30"}};
    // tests/validation/ beside bench/ in the source tree.
    const std::string dir =
        (std::filesystem::path(TSIS_BENCH_RESULTS_DIR).parent_path().parent_path() / "tests" /
         "validation" / "")
            .string();
    Json out = Json::object();
    Renderer renderer;
    for (const SceneCase& s : scenes) {
        BenchCase c = makeThesisCase(s.args(size));
        c.options.keepAovs = true;
        const std::vector<char> mask = interiorPixels(renderer.render(c.scene, c.options).coverage);
        const MeshBoundary boundary(c.scene.mesh);
        const WalkScene walk{&boundary, Medium(c.scene.material), c.scene.lights, glm::dvec3(0.0)};
        Pinhole cam;
        cam.eye = glm::dvec3(c.scene.camera.eye);
        cam.target = glm::dvec3(c.scene.camera.target);
        cam.up = glm::dvec3(c.scene.camera.up);
        cam.fovYDegrees = c.scene.camera.fovYDegrees;
        cam.width = cam.height = size;
        const double radius = boundingRadius(c.scene.mesh);
        const size_t pixels = static_cast<size_t>(size) * size;
        // Batches of photons, each its own image (its own Rng streams).
        const uint64_t perBatch = 4000;
        std::vector<std::vector<glm::dvec3>> batches;
        Timer timer;
        auto maskedMean = [&](const std::vector<glm::dvec3>& img) {
            glm::dvec3 sum(0.0);
            int n = 0;
            for (size_t p = 0; p < pixels; ++p)
                if (mask[p]) {
                    sum += img[p];
                    ++n;
                }
            return sum / static_cast<double>(std::max(n, 1));
        };
        glm::dvec3 mean(0.0), error(1.0);
        while (timer.ms() / 1000.0 < budget) {
            // As many batches as there are threads, in parallel.
            const size_t first = batches.size(), add = hostThreads();
            batches.resize(first + add, std::vector<glm::dvec3>(pixels, glm::dvec3(0.0)));
            parallelFor(add, 1, [&](size_t b0, size_t b1) {
                for (size_t b = b0; b < b1; ++b) {
                    WalkCounters counters;
                    traceLight(walk, cam, radius, (first + b) * perBatch, perBatch, perBatch, 1234,
                               batches[first + b], counters);
                }
            });
            const double n = static_cast<double>(batches.size());
            glm::dvec3 sum(0.0), sumSq(0.0);
            for (const auto& img : batches) {
                const glm::dvec3 m = maskedMean(img);
                sum += m;
                sumSq += m * m;
            }
            mean = sum / n;
            error = glm::sqrt(glm::max(sumSq / n - mean * mean, glm::dvec3(0.0)) / (n - 1));
            std::fprintf(stderr,
                         "%s: %zu batches, mean %.5g %.5g %.5g, error %.2f%% %.2f%% %.2f%%\n",
                         s.name().c_str(), batches.size(), mean.x, mean.y, mean.z,
                         100 * error.x / mean.x, 100 * error.y / mean.y, 100 * error.z / mean.z);
            if (batches.size() >= 8 && error.x < 0.01 * mean.x && error.y < 0.01 * mean.y &&
                error.z < 0.01 * mean.z)
                break;
        }
        // Per-pixel mean and standard error over the batches.
        ImageF meanImg{size, size, 3, std::vector<float>(pixels * 3)}, errImg = meanImg;
        const double n = static_cast<double>(batches.size());
        for (size_t p = 0; p < pixels; ++p)
            for (int ch = 0; ch < 3; ++ch) {
                double sum = 0, sumSq = 0;
                for (const auto& img : batches) {
                    sum += img[p][ch];
                    sumSq += img[p][ch] * img[p][ch];
                }
                const double m = sum / n;
                meanImg.pixels[p * 3 + ch] = static_cast<float>(m);
                errImg.pixels[p * 3 + ch] =
                    static_cast<float>(std::sqrt(std::max(0.0, sumSq / n - m * m) / (n - 1)));
            }
        const std::string base = "truth_" + s.material + "_sphere_" + s.sizeMm + "mm";
        writeImageF(dir + base + ".exr", meanImg);
        writeImageF(dir + base + "_stderr.exr", errImg);
        Json entry = Json::object();
        entry["args"] = s.args(size);
        entry["photons"] = static_cast<double>(n * perBatch);
        entry["interior_mean"] = {mean.x, mean.y, mean.z};
        entry["interior_mean_error"] = {error.x, error.y, error.z};
        entry["seconds"] = timer.ms() / 1000.0;
        out[base] = entry;
    }
    writeTextFile(dir + "truth.json", dumpJson(out) + "\n");
    std::printf("wrote %struth.json\n", dir.c_str());
    return 0;
}

int run(const BenchArgs& a) {
    const long long photons = optionValue(a.rest, "--photons", a.quick ? 20000 : 400000);
    const int spp = static_cast<int>(optionValue(a.rest, "--spp", a.quick ? 16 : 1024));
    const int size = static_cast<int>(optionValue(a.rest, "--size", a.quick ? 32 : 64));
    if (std::find(a.rest.begin(), a.rest.end(), "--models") != a.rest.end())
        return runModels(a, photons, spp, size);
    if (std::find(a.rest.begin(), a.rest.end(), "--truth") != a.rest.end())
        return runTruth(a, size);
    std::string md = "# Physical accuracy: the dipole against volumetric transport\n\n";
    md += "Made by `build/bench/bench_physical` (bench/bench_physical.cpp) on " + timestamp() +
          "; " + std::to_string(photons) + " photons per slab, " + std::to_string(spp) +
          " paths per pixel at " + std::to_string(size) + "² for the scenes.\n\n";

    Table slab({"material", "channel", "R dipole", "R volumetric", "± (1σ)", "dipole / vol.",
                "ratio vol./dipole at 0.1ℓ", "0.3ℓ", "1ℓ", "3ℓ", "10ℓ", "normal L: Jensen / vol.",
                "normalised / vol."});
    const char* channels[] = {"R", "G", "B"};
    for (const Material& m : presetMaterials()) {
        if (!slabMaterial(a, m)) continue;
        const Medium medium(m);
        const SlabResult r = traceBudgeted(m, photons);
        const Dipole dipole(m);
        // pbrt's normalised exit term: (1 − Fr(η, cosθo)) / (c·π), c = 1 − 2·FM1(1/η).
        const double c = 1.0 / normalizedExitScale(m.eta);
        const double ft0 = fresnelTransmittance(m.eta, 1.0);
        for (int ch = 0; ch < 3; ++ch) {
            const DipoleChannel& d = dipole.ch[ch];
            const double rd = d.totalReflectance();
            std::vector<std::string> row = {m.name,
                                            channels[ch],
                                            fmt(rd, 4),
                                            fmt(r.reflectance[ch], 4),
                                            fmt(r.reflectanceError[ch], 4),
                                            fmt(rd / r.reflectance[ch], 3)};
            for (double mfp : kRadiiMfp) {
                // The bin around mfp, both sides averaged over it.
                size_t b = 0;
                while (b + 1 < r.edges.size() && r.edges[b + 1] <= mfp) ++b;
                const double r0 = r.edges[b] / medium.sigmaT[ch],
                             r1 = r.edges[b + 1] / medium.sigmaT[ch];
                const double dip = integrateRd([&](double x) { return d.Rd(x); }, r0, r1);
                row.push_back(dip > 0 ? fmt(r.binFlux[b][ch] / dip, 3) : "–");
            }
            // Normal view, normal light of unit irradiance: L = Ft·B·(exit term).
            const double volL = ft0 * r.normalRadiance[ch];
            const double b0 = ft0 * rd;
            row.push_back(fmt(ft0 / M_PI * b0 / volL, 3));
            row.push_back(fmt(ft0 / (c * M_PI) * b0 / volL, 3));
            slab.add(row);
        }
    }
    md +=
        "## Semi-infinite slab, beam straight down\n\n"
        "R: total reflectance per unit entered flux (dipole: the closed form of ∫Rd 2πr dr). "
        "Ratios of the radial profile in the 1/10-decade annulus around each radius "
        "(ℓ = 1/σt′ of the channel). Normal L: the normal-view radiance under a normal "
        "directional light, each exit term's over the volumetric (flux leaving within 10° "
        "of the normal).\n\n" +
        slab.markdown() + "\n";

    // Scenes: reference (dipole) against volumetric, default lights and camera.
    Renderer renderer;
    Table t({"scene", "rel. RMSE reference vs volumetric", "after one global scale",
             "scale (vol./ref.)", "volumetric noise (rel. RMSE)", "volumetric s"});
    for (const SceneCase& s : sceneCases(a)) {
        BenchCase c = makeThesisCase(s.args(size));
        const ReferenceImage ref = renderReference(renderer, c);
        const FrameResult vol = renderVolumetric(renderer, c, spp, 1);
        const FrameResult vol2 = renderVolumetric(renderer, c, spp, 2);
        const ImageF& v = vol.radiance;
        const auto [err, errScaled, scale] = sceneError(ref.radiance, v, ref.coverage);
        const double noise =
            compareImages(vol2.radiance, v, &ref.coverage, "a", "b").metrics.relRmse /
            std::sqrt(2.0);
        t.add({s.name(), fmt(100 * err, 1) + "%", fmt(100 * errScaled, 1) + "%", fmt(scale, 3),
               fmt(100 * noise, 2) + "%", fmt(vol.stats.stageMs("volumetric") / 1000.0, 1)});
        std::fprintf(stderr, "%s %s: %.3f (%.3f scaled)\n", s.mesh.c_str(), s.material.c_str(), err,
                     errScaled);
    }
    md +=
        "## Scenes: `--method reference` against `--method volumetric`\n\n"
        "Radiance over the covered pixels, default lights and camera, " +
        std::to_string(size) + "², `--spp " + std::to_string(spp) +
        "`; the volumetric noise is half the RMSE between two seeds × √2 (one image's).\n"
        "Commands: `tsis render --mesh M --material X --size-mm S --width " +
        std::to_string(size) + " --height " + std::to_string(size) +
        " --method reference|volumetric --spp " + std::to_string(spp) +
        " --aov DIR` and `tsis compare ref/radiance.exr "
        "vol/radiance.exr --mask vol/coverage.exr`.\n\n" +
        t.markdown() + "\n";
    writeResult("physical.md", md);
    writeResult("physical.csv", slab.csv());
    std::printf("wrote %s/physical.{md,csv}\n", resultsDir().c_str());
    return 0;
}

}  // namespace
}  // namespace tsis::bench

int main(int argc, char** argv) {
    return tsis::bench::guardedMain(tsis::bench::run, argc, argv, 1);
}
