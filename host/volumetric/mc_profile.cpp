// Monte Carlo radial profile and its disk cache; see mc_profile.h.
#include "volumetric/mc_profile.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <mutex>

#include "physics/material.h"
#include "util/cache_dir.h"
#include "util/error.h"
#include "util/hash.h"
#include "util/input_file.h"
#include "util/output_file.h"
#include "volumetric/medium.h"
#include "volumetric/slab.h"

namespace tsis {

namespace {

constexpr char kMagic[8] = {'T', 'S', 'I', 'S', 'M', 'C', 'P', '\x01'};
// Bins the tail is fitted to and blended in over.
constexpr int kFitBins = 4;

struct Header {
    char magic[8];
    uint32_t version, bins;
    double albedo[3], eta;
    int64_t paths;
    double reflectance[3], reflectanceError[3];
};

template <typename T>
void append(std::string& out, const T* p, size_t n) {
    out.append(reinterpret_cast<const char*>(p), n * sizeof(T));
}

}  // namespace

double asymptoticDecay(double albedo) {
    if (albedo >= 1.0) return 0.0;
    // g(ν) = α′·atanh(ν)/ν − 1 rises from α′ − 1 < 0 (ν → 0) to +∞ (ν → 1).
    double lo = 0.0, hi = 1.0;
    for (int i = 0; i < 200; ++i) {
        const double nu = 0.5 * (lo + hi);
        (albedo * std::atanh(nu) / nu > 1.0 ? hi : lo) = nu;
    }
    return 0.5 * (lo + hi);
}

McProfileInput mcProfileInput(const glm::dvec3& sigmaSPrime, const glm::dvec3& sigmaA, double eta) {
    McProfileInput in;
    for (int c = 0; c < 3; ++c)
        in.albedo[c] = std::min(kMcMaxAlbedo, sigmaSPrime[c] / (sigmaSPrime[c] + sigmaA[c]));
    in.eta = eta;
    if (const char* v = std::getenv("TSIS_MC_PROFILE_PATHS")) {
        char* end = nullptr;
        errno = 0;
        const long long n = std::strtoll(v, &end, 10);
        if (end == v || *end != '\0' || errno != 0 || n < 1000 || n > (1LL << 40))
            fail("TSIS_MC_PROFILE_PATHS '", v, "': must be a whole number in [1000, 2^40]");
        in.paths = n;
    }
    return in;
}

std::string mcProfileKey(const McProfileInput& in) {
    Hasher h;
    h.add(kMcProfileVersion).add(in.albedo.x).add(in.albedo.y).add(in.albedo.z).add(in.eta);
    h.add(in.paths);
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h.digest()));
    return hex;
}

McProfile simulateMcProfile(const McProfileInput& in, bool progress) {
    Material unit;
    unit.sigmaSPrime = in.albedo;
    unit.sigmaA = 1.0 - in.albedo;
    unit.eta = in.eta;
    SlabOptions o;
    o.photons = in.paths;
    o.seed = Hasher().add(mcProfileKey(in)).digest();
    o.minMfp = 0.01;
    o.maxMfp = 1000;
    o.binsPerDecade = 10;
    o.progressLabel = progress ? "mc profile" : nullptr;
    const SlabResult r = traceSlab(Medium(unit), o);
    McProfile p;
    p.input = in;
    p.reflectance = r.reflectance;
    p.reflectanceError = r.reflectanceError;
    p.edges = r.edges;
    p.binFlux = r.binFlux;
    p.binFluxError = r.binFluxError;
    p.derive();
    return p;
}

void McProfile::derive() {
    const size_t bins = binFlux.size();
    lnCentre.assign(bins, 0.0);
    lnDensity.assign(bins, glm::dvec3(0.0));
    core = 0;
    while (core + 1 < bins && edges[core] < kMcCoreMfp * (1 - 1e-9)) ++core;
    for (size_t b = 0; b < bins; ++b) {
        lnCentre[b] = 0.5 * (std::log(edges[b]) + std::log(edges[b + 1]));
        const double area = M_PI * (edges[b + 1] * edges[b + 1] - edges[b] * edges[b]);
        for (int c = 0; c < 3; ++c)
            lnDensity[b][c] = binFlux[b][c] > 0 ? std::log(binFlux[b][c] / area) : -HUGE_VAL;
    }
    // A bin's mean density belongs where the density equals it, not at the
    // bin's geometric centre: with the local slope q = d ln ρ/d ln x (from
    // the neighbouring bins), ρ ∝ x^q over an annulus [x0, x1] has the mean
    // ρ(xc)·M/xc^q, M = 2(x1^(q+2) − x0^(q+2))/((q+2)(x1² − x0²)); the value
    // at xc is the mean times xc^q/M (without it the table integrates ~1 % low).
    const std::vector<glm::dvec3> mean = lnDensity;
    for (size_t b = 0; b < bins; ++b)
        for (int c = 0; c < 3; ++c) {
            const size_t lo = b > 0 && std::isfinite(mean[b - 1][c]) ? b - 1 : b;
            const size_t hi = b + 1 < bins && std::isfinite(mean[b + 1][c]) ? b + 1 : b;
            if (lo == hi || !std::isfinite(mean[b][c])) continue;
            const double q = (mean[hi][c] - mean[lo][c]) / (lnCentre[hi] - lnCentre[lo]);
            const double x0 = edges[b], x1 = edges[b + 1], xc = std::exp(lnCentre[b]);
            const double m = std::abs(q + 2) < 1e-6
                                 ? 2 * std::log(x1 / x0) / (x1 * x1 - x0 * x0)
                                 : 2 * (std::pow(x1, q + 2) - std::pow(x0, q + 2)) /
                                       ((q + 2) * (x1 * x1 - x0 * x0));
            lnDensity[b][c] += q * std::log(xc) - std::log(m);
        }
    for (int c = 0; c < 3; ++c) {
        nu[c] = asymptoticDecay(input.albedo[c]);
        // Trusted: up to the last bin past the flux's peak whose error is
        // below kMcTrustedError (the batch estimate of a bin's error is itself
        // noisy: a bin or two above it in between are kept).
        size_t peak = 0;
        for (size_t b = 0; b < bins; ++b)
            if (binFlux[b][c] > binFlux[peak][c]) peak = b;
        size_t end = peak + 1;
        for (size_t b = peak; b < bins; ++b)
            if (binFlux[b][c] > 0 && binFluxError[b][c] <= kMcTrustedError * binFlux[b][c])
                end = b + 1;
        // Empty bins inside (few paths): the next bin's value.
        for (size_t b = end; b-- > 0;)
            if (!std::isfinite(lnDensity[b][c]))
                lnDensity[b][c] = b + 1 < bins ? lnDensity[b + 1][c] : -700.0;
        trusted[c] = static_cast<int>(end);
        // The tail A·e^(−νx)/x^p: transport's asymptotic decay ν, A and p a
        // weighted line (inverse relative variances) through ln ρ + νx over
        // ln x of the last trusted bins, p in [0, 4] (the dipoles' far ρ falls
        // as e^(−σtr x)/x²; nearer in, and at low α′, faster).
        double sw = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
        for (size_t b = end - std::min<size_t>(end, kFitBins); b < end; ++b) {
            const double rel = binFlux[b][c] > 0 ? binFluxError[b][c] / binFlux[b][c] : 1.0;
            const double w = 1.0 / std::max(rel * rel, 1e-8);
            const double u = lnCentre[b], y = lnDensity[b][c] + nu[c] * std::exp(u);
            sw += w;
            sx += w * u;
            sy += w * y;
            sxx += w * u * u;
            sxy += w * u * y;
        }
        const double det = sw * sxx - sx * sx;
        const double slope = det > 1e-12 * sw * sxx ? (sw * sxy - sx * sy) / det : -2.0;
        power[c] = std::clamp(-slope, 0.0, 4.0);
        lnA[c] = (sy + power[c] * sx) / sw;
        // The core disk, x < kMcCoreMfp: its flux (R minus the flux binned
        // beyond, the same walks' exits) spread evenly. Single scattering's
        // ρ ∝ 1/x there is integrable but, point-sampled by the methods at
        // texels next to the pixel, speckles the image; the disk's mean keeps
        // its energy with a bounded peak.
        double outside = 0;
        for (size_t b = core; b < bins; ++b) outside += binFlux[b][c];
        inner[c] = std::max(0.0, reflectance[c] - outside) / (M_PI * edges[core] * edges[core]);
    }
}

double McProfile::density(int c, double x) const {
    const int last = trusted[c] - 1;
    const double lx = std::log(std::max(x, 1e-300));
    const auto tail = [&] { return lnA[c] - nu[c] * x - power[c] * lx; };
    if (x < edges[core]) return inner[c] > 0 ? inner[c] : std::exp(lnDensity[core][c]);
    if (lx >= lnCentre[last]) return std::exp(tail());
    if (lx < lnCentre[core]) return std::exp(lnDensity[core][c]);
    const size_t b = static_cast<size_t>(
        std::upper_bound(lnCentre.begin() + core, lnCentre.begin() + last + 1, lx) -
        lnCentre.begin() - 1);
    const double t = (lx - lnCentre[b]) / (lnCentre[b + 1] - lnCentre[b]);
    const double in = (1 - t) * lnDensity[b][c] + t * lnDensity[b + 1][c];
    const int first = std::max(0, last - kFitBins + 1);
    if (first == last || lx <= lnCentre[first]) return std::exp(in);
    const double s = (lx - lnCentre[first]) / (lnCentre[last] - lnCentre[first]);
    return std::exp((1 - s) * in + s * tail());
}

glm::dvec3 McProfile::rd(double r, const glm::dvec3& sigmaT) const {
    glm::dvec3 out;
    for (int c = 0; c < 3; ++c) out[c] = sigmaT[c] * sigmaT[c] * density(c, sigmaT[c] * r);
    return out;
}

double McProfile::radiusHolding(int c, double fraction) const {
    double total = 0;
    for (const glm::dvec3& f : binFlux) total += f[c];
    double sum = 0;
    for (size_t b = 0; b < binFlux.size(); ++b) {
        sum += binFlux[b][c];
        if (sum >= fraction * total) return edges[b + 1];
    }
    return edges.back();
}

std::string serializeMcProfile(const McProfile& p) {
    Header h;
    std::memset(&h, 0, sizeof h);
    std::memcpy(h.magic, kMagic, sizeof kMagic);
    h.version = kMcProfileVersion;
    h.bins = static_cast<uint32_t>(p.binFlux.size());
    for (int c = 0; c < 3; ++c) {
        h.albedo[c] = p.input.albedo[c];
        h.reflectance[c] = p.reflectance[c];
        h.reflectanceError[c] = p.reflectanceError[c];
    }
    h.eta = p.input.eta;
    h.paths = p.input.paths;
    std::string bytes;
    append(bytes, &h, 1);
    append(bytes, p.edges.data(), p.edges.size());
    append(bytes, p.binFlux.data(), p.binFlux.size());
    append(bytes, p.binFluxError.data(), p.binFluxError.size());
    const uint64_t sum = fnv1a(bytes.data(), bytes.size());
    append(bytes, &sum, 1);
    return bytes;
}

std::optional<McProfile> parseMcProfile(const std::string& bytes, const McProfileInput& in) {
    Header h;
    if (bytes.size() < sizeof h + sizeof(uint64_t)) return std::nullopt;
    std::memcpy(&h, bytes.data(), sizeof h);
    if (std::memcmp(h.magic, kMagic, sizeof kMagic) != 0 ||
        h.version != uint32_t(kMcProfileVersion) || h.bins == 0 || h.bins > 100000)
        return std::nullopt;
    const size_t body = (h.bins + 1) * sizeof(double) + 2 * h.bins * sizeof(glm::dvec3);
    if (bytes.size() != sizeof h + body + sizeof(uint64_t)) return std::nullopt;
    uint64_t stored;
    std::memcpy(&stored, bytes.data() + bytes.size() - sizeof stored, sizeof stored);
    if (stored != fnv1a(bytes.data(), bytes.size() - sizeof stored)) return std::nullopt;
    McProfile p;
    p.input.albedo = {h.albedo[0], h.albedo[1], h.albedo[2]};
    p.input.eta = h.eta;
    p.input.paths = h.paths;
    if (!(p.input == in)) return std::nullopt;
    p.reflectance = {h.reflectance[0], h.reflectance[1], h.reflectance[2]};
    p.reflectanceError = {h.reflectanceError[0], h.reflectanceError[1], h.reflectanceError[2]};
    const char* q = bytes.data() + sizeof h;
    p.edges.resize(h.bins + 1);
    std::memcpy(p.edges.data(), q, p.edges.size() * sizeof(double));
    q += p.edges.size() * sizeof(double);
    p.binFlux.resize(h.bins);
    std::memcpy(p.binFlux.data(), q, h.bins * sizeof(glm::dvec3));
    q += h.bins * sizeof(glm::dvec3);
    p.binFluxError.resize(h.bins);
    std::memcpy(p.binFluxError.data(), q, h.bins * sizeof(glm::dvec3));
    for (size_t b = 0; b < p.edges.size(); ++b)
        if (!(p.edges[b] > 0) || (b > 0 && !(p.edges[b] > p.edges[b - 1]))) return std::nullopt;
    for (size_t b = 0; b < h.bins; ++b)
        for (int c = 0; c < 3; ++c)
            if (!(p.binFlux[b][c] >= 0) || !(p.binFluxError[b][c] >= 0)) return std::nullopt;
    p.derive();
    return p;
}

std::optional<std::filesystem::path> mcProfileCacheDirectory() {
    const std::string root = usableCacheDirectory();
    if (root.empty()) return std::nullopt;
    return std::filesystem::path(root) / "profiles";
}

McProfile mcProfileFromDisk(const McProfileInput& in, bool* loaded) {
    if (loaded) *loaded = false;
    const auto dir = mcProfileCacheDirectory();
    const std::filesystem::path file = dir ? *dir / (mcProfileKey(in) + ".mcprofile") : "";
    std::string bytes;
    if (dir) {
        try {
            bytes = readRegularFile(file.string(), "profile cache entry");
        } catch (const Error&) {
            bytes.clear();  // a miss: simulated below
        }
    }
    if (!bytes.empty()) {
        if (auto p = parseMcProfile(bytes, in)) {
            if (loaded) *loaded = true;
            return std::move(*p);
        }
    }
    McProfile p = simulateMcProfile(in, true);
    if (dir) {
        try {
            std::filesystem::create_directories(file.parent_path());
            writeTextFile(file, serializeMcProfile(p));
        } catch (...) {
            // A cache that cannot be written is only slower.
        }
    }
    return p;
}

const McProfile& mcProfileCached(const McProfileInput& in) {
    static std::mutex mutex;
    // Keyed by the input itself: entries stay put, the profiles' closures
    // hold pointers to them.
    static std::map<std::string, std::unique_ptr<McProfile>> memo;
    const std::lock_guard<std::mutex> lock(mutex);
    const std::string key = serializeMcProfile(McProfile{in});
    auto& slot = memo[key];
    if (!slot) slot = std::make_unique<McProfile>(mcProfileFromDisk(in, nullptr));
    return *slot;
}

}  // namespace tsis
