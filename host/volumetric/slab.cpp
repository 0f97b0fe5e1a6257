#include "volumetric/slab.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <glm/geometric.hpp>
#include <optional>

#include "physics/fresnel.h"
#include "util/parallel.h"
#include "util/progress.h"
#include "volumetric/boundary.h"
#include "volumetric/dielectric.h"

namespace tsis {

namespace {

constexpr int kMaxEvents = 1000000;
constexpr double kRouletteWeight = 0.05;

struct Tally {
    glm::dvec3 sum{0.0}, sumSq{0.0}, cone{0.0}, coneSq{0.0};
    std::vector<glm::dvec3> bins;
    long long events = 0;
};

}  // namespace

double SlabResult::profile(int channel, double rMm, const Medium& m) const {
    const double r = rMm * m.sigmaT[channel];
    const auto it = std::upper_bound(edges.begin(), edges.end(), r);
    if (it == edges.begin() || it == edges.end()) return 0.0;
    const size_t b = static_cast<size_t>(it - edges.begin()) - 1;
    const double r0 = edges[b] / m.sigmaT[channel], r1 = edges[b + 1] / m.sigmaT[channel];
    return binFlux[b][channel] / (M_PI * (r1 * r1 - r0 * r0));
}

SlabResult traceSlab(const Medium& m, const SlabOptions& o) {
    SlabResult result;
    const int bins =
        static_cast<int>(std::round(std::log10(o.maxMfp / o.minMfp) * o.binsPerDecade));
    for (int b = 0; b <= bins; ++b)
        result.edges.push_back(o.minMfp * std::pow(10.0, static_cast<double>(b) / o.binsPerDecade));
    const double coneCos = std::cos(o.coneDegrees * M_PI / 180.0);
    const HalfSpace slab;
    // Chunks of photons, summed in order: the result does not depend on threads.
    const size_t chunk = 4096;
    const size_t chunks = static_cast<size_t>((o.photons + static_cast<long long>(chunk) - 1) /
                                              static_cast<long long>(chunk));
    std::vector<Tally> tallies(chunks);
    std::optional<Progress> progress;
    if (o.progressLabel) progress.emplace(o.progressLabel, static_cast<long long>(chunks));
    std::atomic<long long> chunksDone{0};
    parallelFor(chunks, 1, [&](size_t begin, size_t end) {
        for (size_t c = begin; c < end; ++c) {
            Tally& t = tallies[c];
            t.bins.assign(static_cast<size_t>(bins), glm::dvec3(0.0));
            const auto first = static_cast<long long>(c) * static_cast<long long>(chunk);
            const long long last = std::min(o.photons, first + static_cast<long long>(chunk));
            for (long long p = first; p < last; ++p) {
                Rng rng(o.seed, static_cast<uint64_t>(p));
                SpectralWeight w(rng);
                glm::dvec3 pos(0.0, -slab.epsilon(), 0.0), dir(0.0, -1.0, 0.0);
                glm::dvec3 out(0.0), cone(0.0);
                for (int event = 0; event < kMaxEvents; ++event) {
                    SurfaceHit hit;
                    const bool up = slab.intersect(pos, dir, kInfinity, hit);
                    const FreeFlight f = sampleFreeFlight(m, up ? hit.t : kInfinity, w, rng);
                    if (f.scattered) {
                        ++t.events;
                        pos += dir * f.t;
                        const glm::dvec3 v = w.value();
                        const double s = std::max({v.x, v.y, v.z});
                        if (s < kRouletteWeight) {
                            if (rng.uniform() >= s / kRouletteWeight) break;
                            w.scale(glm::dvec3(kRouletteWeight / s));
                        }
                        const double u1 = rng.uniform(), u2 = rng.uniform();
                        dir = uniformSphere(u1, u2);
                        continue;
                    }
                    const double cosI = dir.y;
                    if (rng.uniform() < fresnelReflectance(1.0 / m.eta, cosI)) {
                        dir.y = -dir.y;
                        pos = hit.position - glm::dvec3(0.0, slab.epsilon(), 0.0);
                        continue;
                    }
                    out = w.value();
                    const double r = std::hypot(hit.position.x, hit.position.z);
                    for (int ch = 0; ch < 3; ++ch) {
                        const double rm = r * m.sigmaT[ch];
                        const double k = std::floor(std::log10(rm / o.minMfp) * o.binsPerDecade);
                        if (k >= 0 && k < bins) t.bins[static_cast<size_t>(k)][ch] += out[ch];
                    }
                    const double cosOut =
                        std::sqrt(std::max(0.0, 1.0 - m.eta * m.eta * (1.0 - cosI * cosI)));
                    if (cosOut > coneCos) cone = out;
                    break;
                }
                t.sum += out;
                t.sumSq += out * out;
                t.cone += cone;
                t.coneSq += cone * cone;
            }
            if (progress) progress->update(++chunksDone);
        }
    });
    if (progress) progress->finish();
    Tally total;
    total.bins.assign(static_cast<size_t>(bins), glm::dvec3(0.0));
    for (const Tally& t : tallies) {
        total.sum += t.sum;
        total.sumSq += t.sumSq;
        total.cone += t.cone;
        total.coneSq += t.coneSq;
        total.events += t.events;
        for (size_t b = 0; b < t.bins.size(); ++b) total.bins[b] += t.bins[b];
    }
    const double n = static_cast<double>(o.photons);
    auto stderrOf = [n](const glm::dvec3& s, const glm::dvec3& s2) {
        const glm::dvec3 mean = s / n;
        return glm::sqrt(glm::max(glm::dvec3(0.0), s2 / n - mean * mean) / n);
    };
    const double coneArea = M_PI * (1.0 - coneCos * coneCos);
    result.reflectance = total.sum / n;
    result.reflectanceError = stderrOf(total.sum, total.sumSq);
    result.normalRadiance = total.cone / n / coneArea;
    result.normalRadianceError = stderrOf(total.cone, total.coneSq) / coneArea;
    result.meanEvents = static_cast<double>(total.events) / n;
    for (const glm::dvec3& b : total.bins) result.binFlux.push_back(b / n);
    // Batch means: Var(mean) = Σ_c (s_c − n_c·mean)² / (N·N) · C/(C − 1), s_c
    // a batch's sum over its n_c photons.
    result.binFluxError.assign(result.binFlux.size(), glm::dvec3(0.0));
    const double batches = static_cast<double>(tallies.size());
    for (size_t c = 0; c < tallies.size(); ++c) {
        const double nc =
            static_cast<double>(std::min(o.photons, static_cast<long long>((c + 1) * chunk)) -
                                static_cast<long long>(c * chunk));
        for (size_t b = 0; b < result.binFlux.size(); ++b) {
            const glm::dvec3 d = tallies[c].bins[b] - nc * result.binFlux[b];
            result.binFluxError[b] += d * d;
        }
    }
    for (glm::dvec3& e : result.binFluxError)
        e = batches > 1 ? glm::sqrt(e * (batches / (batches - 1))) / n : glm::dvec3(0.0);
    return result;
}

}  // namespace tsis
