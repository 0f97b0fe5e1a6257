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
// bench_physical [--quick] [--photons N] [--spp N] [--size W]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "bench_common.h"
#include "compare/image_compare.h"
#include "physics/dipole.h"
#include "physics/fresnel.h"
#include "physics/material.h"
#include "util/error.h"
#include "volumetric/slab.h"

namespace tsis::bench {
namespace {

const double kRadiiMfp[] = {0.1, 0.3, 1.0, 3.0, 10.0};
constexpr double kEventBudget = 2e8;  // scattering events per slab

// ∫ Rd 2πr dr over [r0, r1] (Simpson in r).
double integrateRd(const DipoleChannel& d, double r0, double r1) {
    const int n = 200;
    const double h = (r1 - r0) / n;
    double s = 0;
    for (int k = 0; k <= n; ++k) {
        const double r = r0 + k * h;
        const double w = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0);
        s += w * d.Rd(r) * 2.0 * M_PI * r;
    }
    return s * h / 3.0;
}

// Fresnel's first moment ∫₀¹ Fr(η, μ)μ dμ over the outside angles, by
// Simpson: c = 1 − 2·moment makes ∫(1 − Fr)/(cπ)·cosθ dω = 1 (pbrt's c, so the
// exitance equals B).
double fresnelMoment1(double eta) {
    const int n = 4000;
    double s = 0;
    for (int k = 0; k <= n; ++k) {
        const double mu = static_cast<double>(k) / n;
        const double w = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0);
        s += w * fresnelReflectance(eta, mu) * mu;
    }
    return s / (3.0 * n);
}

long long optionValue(const std::vector<std::string>& rest, const std::string& name,
                      long long def) {
    for (size_t i = 0; i + 1 < rest.size(); ++i)
        if (rest[i] == name) return std::stoll(rest[i + 1]);
    return def;
}

int run(const BenchArgs& a) {
    const long long photons = optionValue(a.rest, "--photons", a.quick ? 20000 : 400000);
    const int spp = static_cast<int>(optionValue(a.rest, "--spp", a.quick ? 16 : 1024));
    const int size = static_cast<int>(optionValue(a.rest, "--size", a.quick ? 32 : 64));
    std::string md = "# Physical accuracy: the dipole against volumetric transport\n\n";
    md += "Made by `build/bench/bench_physical` (bench/bench_physical.cpp) on " + timestamp() +
          "; " + std::to_string(photons) + " photons per slab, " + std::to_string(spp) +
          " paths per pixel at " + std::to_string(size) + "² for the scenes.\n\n";

    Table slab({"material", "channel", "R dipole", "R volumetric", "± (1σ)", "dipole / vol.",
                "ratio vol./dipole at 0.1ℓ", "0.3ℓ", "1ℓ", "3ℓ", "10ℓ", "normal L: Jensen / vol.",
                "normalised / vol."});
    const char* channels[] = {"R", "G", "B"};
    for (const Material& m : presetMaterials()) {
        if (a.quick && m.name != "marble" && m.name != "skin1") continue;
        if (m.sigmaA == glm::dvec3(0.0)) continue;  // spectralon: R = 1 in both (σa = 0)
        const Medium medium(m);
        // A pilot for the walks' length, then photons within an event budget
        // (cream's walks are ~100× skin1's).
        SlabOptions o;
        o.photons = 2000;
        const double events = std::max(1.0, traceSlab(medium, o).meanEvents);
        o.photons = std::clamp(static_cast<long long>(kEventBudget / events), 20000LL, photons);
        const SlabResult r = traceSlab(medium, o);
        const Dipole dipole(m);
        // pbrt's normalised exit term: (1 − Fr(η, cosθo)) / (c·π), c = 1 − 2·FM1(1/η).
        const double c = 1.0 - 2.0 * fresnelMoment1(m.eta);
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
                const double dip = integrateRd(d, r0, r1);
                row.push_back(dip > 0 ? fmt(r.binFlux[b][ch] / dip, 3) : "–");
            }
            // Normal view, normal light of unit irradiance: L = Ft·B·(exit term).
            const double volL = ft0 * r.normalRadiance[ch];
            const double b0 = ft0 * rd;
            row.push_back(fmt(ft0 / M_PI * b0 / volL, 3));
            row.push_back(fmt(ft0 / (c * M_PI) * b0 / volL, 3));
            slab.add(row);
        }
        std::fprintf(stderr, "slab %s: %lld photons, %.1f events each\n", m.name.c_str(), o.photons,
                     r.meanEvents);
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
    struct SceneCase {
        std::string mesh, material, sizeMm;
    };
    std::vector<SceneCase> scenes = {{"builtin:sphere", "marble", "10"},
                                     {"builtin:sphere", "skin1", "30"},
                                     {"builtin:default", "marble", "10"},
                                     {"builtin:default", "skin1", "10"}};
    if (a.quick) scenes.resize(1);
    Renderer renderer;
    Table t({"scene", "rel. RMSE reference vs volumetric", "after one global scale",
             "scale (vol./ref.)", "volumetric noise (rel. RMSE)", "volumetric s"});
    for (const SceneCase& s : scenes) {
        const std::vector<std::string> args = {
            "--mesh", s.mesh,    "--material",         s.material, "--size-mm",
            s.sizeMm, "--width", std::to_string(size), "--height", std::to_string(size)};
        BenchCase c = makeCase(args);
        const ReferenceImage ref = renderReference(renderer, c);
        c.options.method = "volumetric";
        c.options.keepAovs = true;
        c.options.spp = spp;
        const FrameResult vol = renderer.render(c.scene, c.options);
        c.options.seed = 2;
        const FrameResult vol2 = renderer.render(c.scene, c.options);
        const ImageF& v = vol.radiance;
        const double err = compareImages(ref.radiance, v, &ref.coverage, "reference", "volumetric")
                               .metrics.relRmse;
        double num = 0, den = 0;
        for (size_t i = 0; i < v.pixels.size(); ++i)
            if (ref.coverage.pixels[i / 3] > 0.5) {
                num += v.pixels[i] * ref.radiance.pixels[i];
                den += ref.radiance.pixels[i] * ref.radiance.pixels[i];
            }
        const double scale = den > 0 ? num / den : 0;
        ImageF scaled = ref.radiance;
        for (float& p : scaled.pixels) p = static_cast<float>(p * scale);
        const double errScaled =
            compareImages(scaled, v, &ref.coverage, "reference", "volumetric").metrics.relRmse;
        const double noise =
            compareImages(vol2.radiance, v, &ref.coverage, "a", "b").metrics.relRmse /
            std::sqrt(2.0);
        t.add({s.mesh + " " + s.material + " " + s.sizeMm + " mm", fmt(100 * err, 1) + "%",
               fmt(100 * errScaled, 1) + "%", fmt(scale, 3), fmt(100 * noise, 2) + "%",
               fmt(vol.stats.stageMs("volumetric") / 1000.0, 1)});
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
