// Rd(r) of a semi-infinite medium from Monte Carlo (--profile mc, docs/design.md
// §2 "Profile models"): the slab light tracer (slab.h) run once per albedo
// triple α′ = σs′/σt′ and η, at σt′ = 1 (isotropic phase, σs = σs′; a pencil
// beam entering normally at the origin, as the dipole assumes; Fresnel and
// total internal reflection at the surface). The profile scales exactly with
// the mean free path ℓ = 1/σt′ at fixed α′ and η: Rd(r) = σt′²·ρ(σt′·r), ρ the
// unit medium's exitant flux per unit area. So one simulation serves every
// --size-mm, and it is cached on disk.
//
// ρ between bin centres: log-log interpolation of the annuli's area-normalised
// flux, 10 per decade from 0.01 to 1000 free paths; inside kMcCoreMfp, the
// flux the walks left there (R minus the flux binned beyond) spread evenly:
// single scattering's ρ ∝ 1/x is integrable but, point-sampled at texels
// beside the pixel, speckles the image. Beyond the last bin past
// the flux's peak whose relative error is below kMcTrustedError, a tail
// A·e^(−νx)/x^p, ν transport theory's asymptotic decay (α′·atanh(ν)/ν = 1;
// Grosjean's σtr of the better dipole meets it as α′ → 1), A and p fitted to
// the last trusted bins, blended in over them.
//
// Cache: <cacheDirectory()>/profiles/<key>.mcprofile (util/cache_dir.h), key
// a hash of (α′, η, the path count, kMcProfileVersion); the file holds those
// and the simulation's bins and a 64-bit checksum. A short, foreign or corrupt
// file is ignored and simulated again; failing to write is ignored.
#pragma once

#include <filesystem>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

namespace tsis {

// Bump when the simulation or the file changes.
constexpr int kMcProfileVersion = 1;
// Paths per simulation; TSIS_MC_PROFILE_PATHS overrides it (tests, benches).
constexpr long long kMcProfilePaths = 1LL << 20;
// Inside this radius (free paths) ρ is the disk's mean.
constexpr double kMcCoreMfp = 0.1;
// A bin is trusted while its relative standard error is below this.
constexpr double kMcTrustedError = 0.03;
// α′ is simulated at most this (σa = 0 would walk for ever in the half-space).
constexpr double kMcMaxAlbedo = 1.0 - 1e-4;

struct McProfileInput {
    glm::dvec3 albedo{0.0};  // σs′/σt′ per channel, clamped to kMcMaxAlbedo
    double eta = 1.0;
    long long paths = kMcProfilePaths;
    bool operator==(const McProfileInput& o) const {
        return albedo == o.albedo && eta == o.eta && paths == o.paths;
    }
};

// The simulation's result, at σt′ = 1 (distances in free paths).
struct McProfile {
    McProfileInput input;
    glm::dvec3 reflectance{0.0}, reflectanceError{0.0};  // ∫ρ 2πx dx per entered flux
    std::vector<double> edges;                           // annuli, free paths
    std::vector<glm::dvec3> binFlux, binFluxError;       // flux per annulus, its error

    // Derived from the above (derive()): per channel, the bin centres' ln ρ,
    // the trusted bin count and the tail.
    std::vector<double> lnCentre;
    std::vector<glm::dvec3> lnDensity;
    int trusted[3] = {0, 0, 0};
    glm::dvec3 nu{0.0}, power{0.0}, lnA{0.0};
    size_t core = 0;        // the first bin outside the core disk
    glm::dvec3 inner{0.0};  // ρ over the core disk

    void derive();
    // ρ of `channel` at x free paths.
    double density(int channel, double x) const;
    // Rd(r) at r mm of a medium with these σt′ per channel.
    glm::dvec3 rd(double r, const glm::dvec3& sigmaT) const;
    // The radius (free paths) within which `fraction` of channel's flux leaves.
    double radiusHolding(int channel, double fraction) const;
};

// The input per channel of σs′, σa, η (the path count from
// TSIS_MC_PROFILE_PATHS, else kMcProfilePaths; a value that is not a whole
// number in [1000, 2^40] throws Error).
McProfileInput mcProfileInput(const glm::dvec3& sigmaSPrime, const glm::dvec3& sigmaA, double eta);
// ν with α′·atanh(ν)/ν = 1 (0 at α′ = 1, → 1 as α′ → 0).
double asymptoticDecay(double albedo);

// Runs the simulation (deterministic: its seed is a hash of the input).
McProfile simulateMcProfile(const McProfileInput& in, bool progress = false);

std::string mcProfileKey(const McProfileInput& in);
std::string serializeMcProfile(const McProfile& p);
std::optional<McProfile> parseMcProfile(const std::string& bytes, const McProfileInput& in);
std::optional<std::filesystem::path> mcProfileCacheDirectory();

// The profile of `in` from the disk cache, else simulated (with a progress
// line) and stored; *loaded says which.
McProfile mcProfileFromDisk(const McProfileInput& in, bool* loaded);
// The profile of `in`: from this process' memory, else the disk cache, else
// simulated (with a progress line) and stored. Thread-safe.
const McProfile& mcProfileCached(const McProfileInput& in);

}  // namespace tsis
