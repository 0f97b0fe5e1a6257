// The object's own transport between patches of its surface (--transport
// object, docs/design.md §14): the volumetric walk's flux from each patch to
// every other of its medium, against what the frame's profile model gives
// for the same patches, so that a frame can add the difference at the cost of
// a small matrix product. The semi-infinite profile loses what a finite,
// curved object keeps (light that comes out the far side, thin parts, the
// unlit side of a small object); the walk inside the real boundary has it.
//
// Patches: each medium's covered atlas texels clustered by position and
// normal (farthest-point seeds, then Lloyd steps), `patches` in all, shared
// out by area. Truth: photons entering each patch at texels drawn by area,
// along a refracted direction d = −n·cos θe + t·sin θe (t a random unit
// tangent), random-walking in the homogeneous medium (isotropic, σs = σs′)
// behind the smooth dielectric boundary (Fresnel and total internal
// reflection) until they leave; where they leave is their exit patch. The
// entry angle spans the refracted cone (sin²θe uniform on [0, 1/η²]). Their
// mean is the transfer T0; its first moment in the tangential part s = t·sin θe
// of the direction of travel the gradient G, and its slope in q = |s|² about
// q's mean μ the angular term H: T(s) ≈ T0 + G·s + H·(q − μ) (light entering
// obliquely goes on forwards, a back-lit object's rim; light entering steeply
// goes deeper, which a thin part lets through). Model: the
// profile's exitance at every texel of the medium from entry points drawn the
// same way. All are "exitant flux in patch j per unit flux entering patch i".
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

#include "mesh/mesh.h"
#include "physics/material.h"
#include "physics/profile_table.h"

namespace tsis {

// Bump when the fit or its file changes.
constexpr int kPatchTransferVersion = 5;

// The covered texels of the geometry atlas, on the host.
struct SurfaceTexels {
    std::vector<glm::vec3> position, normal;
    std::vector<float> area;  // mm²
    std::vector<int> medium;  // 0-based (mesh/media.h)
    std::vector<int> texel;   // y·resolution + x in the atlas (GL row order)
    size_t size() const { return position.size(); }
};

// One medium's inputs: its coefficients and the frame's profile as exitance
// (k_exit·Rd: the exit term's exitance per unit B times the profile the
// methods integrate, --energy included).
struct TransferMedium {
    Material material;
    ProfileTable exitance;
};

struct PatchTransferOptions {
    int patches = 384;      // in all media together
    int photons = 4096;     // per patch and channel
    int modelSamples = 16;  // entry points per patch for the model's transfer
    // Leave out the paths that leave unscattered (across a thin part): they
    // leave along the light's direction, not diffusely.
    bool excludeUnscattered = true;
    // Leave out the paths that leave after one scattering (--single-scatter
    // adds that term for the light's own entry).
    bool excludeSingle = false;
    // The top of sin θe's range (tests); 0: 1/η, the refracted cone's edge,
    // TSIS_ENTRY_TOP_SIN2, which the frame's μ (TSIS_ENTRY_MEAN_SIN2) assumes.
    double entrySin = 0.0;
    uint32_t seed = 1;
};

// Patches sorted by medium; Δ = truth − model per medium as a dense block.
struct PatchTransfer {
    std::vector<glm::vec3> centre, normal;
    std::vector<float> area, radius;  // radius: of the patch's disk of equal area
    std::vector<int> medium;
    std::vector<int> mediumStart;  // patches of medium m: [mediumStart[m], mediumStart[m+1])
    std::vector<int> texelPatch;   // per SurfaceTexels entry
    // Block of medium m at blockStart[m]: row i (entry), column j (exit),
    // both counted from mediumStart[m].
    std::vector<glm::vec3> delta;
    // The same layout, three vec3 per pair: G per channel (world frame).
    std::vector<glm::vec3> gradient;
    // The same layout as delta: H (rgb), the slope in q = |s|² about its mean.
    std::vector<glm::vec3> angular;
    std::vector<size_t> blockStart;
    // Per medium, the mean over its patches of Σ_j T(i, j): the share of the
    // entered light that leaves, by the walk and by the model.
    std::vector<glm::vec3> truthOut, modelOut;
    uint64_t key = 0;
    double seconds = 0;  // to fit (0 when read from the cache)

    int patches() const { return static_cast<int>(centre.size()); }
    size_t media() const { return mediumStart.empty() ? 0 : mediumStart.size() - 1; }
    const glm::vec3& at(int m, int i, int j) const {
        const size_t k = static_cast<size_t>(mediumStart[m + 1] - mediumStart[m]);
        return delta[blockStart[m] + static_cast<size_t>(i - mediumStart[m]) * k +
                     static_cast<size_t>(j - mediumStart[m])];
    }
    const glm::vec3& angularAt(int m, int i, int j) const {
        return angular[static_cast<size_t>(&at(m, i, j) - delta.data())];
    }
    // G of channel c from patch i to patch j of medium m.
    const glm::vec3& gradientAt(int m, int i, int j, int c) const {
        return gradient[(&at(m, i, j) - delta.data()) * 3 + static_cast<size_t>(c)];
    }
};

// Fits the transfer (progress on a terminal). `key` names the inputs (the
// caller hashes them: texels, materials, profiles, options).
PatchTransfer fitPatchTransfer(const Mesh& mesh, const SurfaceTexels& texels,
                               const std::vector<TransferMedium>& media,
                               const PatchTransferOptions& options, uint64_t key);

// The disk cache's fit of `key` (<cache>/transport/<key>.transfer, the atlas
// cache's folder) when a valid file of it for `texels` texels exists.
std::optional<PatchTransfer> loadPatchTransfer(uint64_t key, size_t texels);
// Writes `t` there as the fit of `key` (a cache that cannot be written is only slower).
void storePatchTransfer(const PatchTransfer& t, uint64_t key);

// The same through the disk cache: read when a valid file of this key exists,
// else fitted and written. `loaded` tells which.
PatchTransfer cachedPatchTransfer(const Mesh& mesh, const SurfaceTexels& texels,
                                  const std::vector<TransferMedium>& media,
                                  const PatchTransferOptions& options, uint64_t key,
                                  bool* loaded = nullptr);

// Serialisation (the cache file; tests).
std::string serializePatchTransfer(const PatchTransfer& t);
bool parsePatchTransfer(const std::string& bytes, uint64_t key, size_t texels, PatchTransfer& out);

}  // namespace tsis
