#include "volumetric/patch_transfer.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <glm/ext/vector_int3.hpp>
#include <glm/geometric.hpp>
#include <iterator>
#include <limits>
#include <numeric>

#include "physics/fresnel.h"
#include "tsis_shared.h"
#include "util/cache_dir.h"
#include "util/error.h"
#include "util/hash.h"
#include "util/input_file.h"
#include "util/output_file.h"
#include "util/parallel.h"
#include "util/progress.h"
#include "util/timer.h"
#include "volumetric/dielectric.h"
#include "volumetric/mesh_boundary.h"
#include "volumetric/rng.h"

namespace tsis {

namespace {

constexpr double kRoulette = 0.05;  // a path below this weight survives with p = w/kRoulette
constexpr int kMaxBounces = 1 << 16;
constexpr int kLloydSteps = 3;

std::string hexKey(uint64_t key) {
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(key));
    return hex;
}

// The clustering's distance: position, and the normals' disagreement at the
// patch's scale, so the two sides of a thin part fall in different patches.
double patchDistance(const glm::vec3& x, const glm::vec3& n, const glm::vec3& c,
                     const glm::vec3& nc, double radius2) {
    const glm::vec3 d = x - c;
    return static_cast<double>(glm::dot(d, d)) +
           radius2 * (1.0 - static_cast<double>(glm::dot(n, nc)));
}

// Each medium's patches, indexed by a uniform grid of their centres for the
// walks' exit lookups.
class PatchIndex {
  public:
    PatchIndex(const PatchTransfer& t, int m)
        : t_(t), first_(t.mediumStart[m]), last_(t.mediumStart[m + 1]) {
        const int last = last_;
        lo_ = glm::vec3(std::numeric_limits<float>::max());
        glm::vec3 hi(-std::numeric_limits<float>::max());
        double r = 0;
        for (int p = first_; p < last; ++p) {
            lo_ = glm::min(lo_, t.centre[p]);
            hi = glm::max(hi, t.centre[p]);
            r = std::max(r, static_cast<double>(t.radius[p]));
        }
        radius2_ = r * r;
        cell_ = static_cast<float>(std::max(2.0 * r, 1e-6));
        for (int a = 0; a < 3; ++a)
            dims_[a] = std::clamp(static_cast<int>((hi[a] - lo_[a]) / cell_) + 1, 1, 256);
        cells_.assign(static_cast<size_t>(dims_[0]) * dims_[1] * dims_[2], {});
        for (int p = first_; p < last; ++p) cells_[cellOf(t.centre[p])].push_back(p);
    }
    int nearest(const glm::vec3& x, const glm::vec3& n) const {
        int best = -1;
        double bestD = std::numeric_limits<double>::infinity();
        const glm::ivec3 c = coords(x);
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const glm::ivec3 q = c + glm::ivec3(dx, dy, dz);
                    if (q.x < 0 || q.y < 0 || q.z < 0 || q.x >= dims_[0] || q.y >= dims_[1] ||
                        q.z >= dims_[2])
                        continue;
                    for (int p : cells_[index(q)]) {
                        const double d = patchDistance(x, n, t_.centre[p], t_.normal[p], radius2_);
                        if (d < bestD) bestD = d, best = p;
                    }
                }
        if (best >= 0) return best;
        for (int p = first_; p < last_; ++p) {
            const double d = patchDistance(x, n, t_.centre[p], t_.normal[p], radius2_);
            if (d < bestD) bestD = d, best = p;
        }
        return best;
    }

  private:
    glm::ivec3 coords(const glm::vec3& x) const {
        glm::ivec3 c;
        for (int a = 0; a < 3; ++a)
            c[a] = std::clamp(static_cast<int>((x[a] - lo_[a]) / cell_), 0, dims_[a] - 1);
        return c;
    }
    size_t index(const glm::ivec3& c) const {
        return (static_cast<size_t>(c.z) * dims_[1] + c.y) * dims_[0] + c.x;
    }
    size_t cellOf(const glm::vec3& x) const { return index(coords(x)); }

    const PatchTransfer& t_;
    int first_, last_;
    glm::vec3 lo_;
    float cell_;
    int dims_[3];
    double radius2_;
    std::vector<std::vector<int>> cells_;
};

// Clusters each medium's texels into patches (sorted by medium).
void makePatches(const SurfaceTexels& tx, size_t mediaCount, int budget, PatchTransfer& t) {
    std::vector<std::vector<int>> byMedium(mediaCount);
    std::vector<double> mediumArea(mediaCount, 0.0);
    double total = 0;
    for (size_t k = 0; k < tx.size(); ++k) {
        byMedium[static_cast<size_t>(tx.medium[k])].push_back(static_cast<int>(k));
        mediumArea[static_cast<size_t>(tx.medium[k])] += tx.area[k];
        total += tx.area[k];
    }
    t.texelPatch.assign(tx.size(), -1);
    t.mediumStart.assign(1, 0);
    for (size_t m = 0; m < mediaCount; ++m) {
        const std::vector<int>& own = byMedium[m];
        const int first = t.patches();
        int k = own.empty() ? 0
                            : std::clamp(static_cast<int>(std::lround(budget * mediumArea[m] /
                                                                      std::max(total, 1e-30))),
                                         4, budget);
        k = std::min<int>(k, static_cast<int>(own.size()));
        const double r2 = mediumArea[m] / (M_PI * std::max(k, 1));
        // Farthest-point seeds from the texel nearest the medium's first.
        std::vector<double> dist(own.size(), std::numeric_limits<double>::infinity());
        std::vector<glm::vec3> c, n;
        size_t next = 0;
        for (int s = 0; s < k; ++s) {
            const int seed = own[next];
            c.push_back(tx.position[static_cast<size_t>(seed)]);
            n.push_back(tx.normal[static_cast<size_t>(seed)]);
            double far = -1;
            for (size_t q = 0; q < own.size(); ++q) {
                const auto i = static_cast<size_t>(own[q]);
                dist[q] = std::min(
                    dist[q], patchDistance(tx.position[i], tx.normal[i], c.back(), n.back(), r2));
                if (dist[q] > far) far = dist[q], next = q;
            }
        }
        // Lloyd steps: assign, then move each centre to its texels' mean.
        std::vector<int> assign(own.size(), 0);
        for (int step = 0; step <= kLloydSteps; ++step) {
            parallelFor(own.size(), 4096, [&](size_t b, size_t e) {
                for (size_t q = b; q < e; ++q) {
                    const auto i = static_cast<size_t>(own[q]);
                    double best = std::numeric_limits<double>::infinity();
                    for (int p = 0; p < k; ++p) {
                        const double d =
                            patchDistance(tx.position[i], tx.normal[i], c[static_cast<size_t>(p)],
                                          n[static_cast<size_t>(p)], r2);
                        if (d < best) best = d, assign[q] = p;
                    }
                }
            });
            if (step == kLloydSteps) break;
            std::vector<glm::dvec3> sc(static_cast<size_t>(k), glm::dvec3(0.0)),
                sn(static_cast<size_t>(k), glm::dvec3(0.0));
            std::vector<double> sa(static_cast<size_t>(k), 0.0);
            for (size_t q = 0; q < own.size(); ++q) {
                const auto i = static_cast<size_t>(own[q]);
                const auto p = static_cast<size_t>(assign[q]);
                sc[p] += glm::dvec3(tx.position[i]) * static_cast<double>(tx.area[i]);
                sn[p] += glm::dvec3(tx.normal[i]) * static_cast<double>(tx.area[i]);
                sa[p] += tx.area[i];
            }
            for (size_t p = 0; p < static_cast<size_t>(k); ++p)
                if (sa[p] > 0) {
                    // The centre stays on the surface: the texel nearest the mean.
                    c[p] = glm::vec3(sc[p] / sa[p]);
                    const double len = glm::length(sn[p]);
                    if (len > 0) n[p] = glm::vec3(sn[p] / len);
                }
        }
        std::vector<double> area(static_cast<size_t>(k), 0.0);
        for (size_t q = 0; q < own.size(); ++q) {
            area[static_cast<size_t>(assign[q])] += tx.area[static_cast<size_t>(own[q])];
            t.texelPatch[static_cast<size_t>(own[q])] = first + assign[q];
        }
        for (int p = 0; p < k; ++p) {
            t.centre.push_back(c[static_cast<size_t>(p)]);
            t.normal.push_back(n[static_cast<size_t>(p)]);
            t.area.push_back(static_cast<float>(area[static_cast<size_t>(p)]));
            t.radius.push_back(static_cast<float>(std::sqrt(area[static_cast<size_t>(p)] / M_PI)));
            t.medium.push_back(static_cast<int>(m));
        }
        t.mediumStart.push_back(t.patches());
    }
    size_t offset = 0;
    t.blockStart.clear();
    for (size_t m = 0; m < mediaCount; ++m) {
        t.blockStart.push_back(offset);
        const auto k = static_cast<size_t>(t.mediumStart[m + 1] - t.mediumStart[m]);
        offset += k * k;
    }
    t.delta.assign(offset, glm::vec3(0.0f));
    t.gradient.assign(offset * 3, glm::vec3(0.0f));
    t.angular.assign(offset, glm::vec3(0.0f));
}

// Each patch's texels and their area CDF, to draw entry points.
struct PatchTexels {
    std::vector<std::vector<int>> texels;
    std::vector<std::vector<double>> cdf;
};

PatchTexels patchTexels(const SurfaceTexels& tx, const PatchTransfer& t) {
    PatchTexels pt;
    pt.texels.resize(static_cast<size_t>(t.patches()));
    pt.cdf.resize(static_cast<size_t>(t.patches()));
    for (size_t k = 0; k < tx.size(); ++k) {
        const auto p = static_cast<size_t>(t.texelPatch[k]);
        pt.texels[p].push_back(static_cast<int>(k));
        pt.cdf[p].push_back((pt.cdf[p].empty() ? 0.0 : pt.cdf[p].back()) + tx.area[k]);
    }
    return pt;
}

int drawTexel(const PatchTexels& pt, size_t patch, double u) {
    const std::vector<double>& cdf = pt.cdf[patch];
    const double x = u * cdf.back();
    const auto it = std::upper_bound(cdf.begin(), cdf.end(), x);
    const auto i = std::min<size_t>(static_cast<size_t>(it - cdf.begin()), cdf.size() - 1);
    return pt.texels[patch][i];
}

// A unit tangent of n at angle phi (any frame: the azimuth is uniform).
glm::dvec3 tangentAt(const glm::dvec3& n, double phi) {
    const glm::dvec3 a = std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 u = glm::normalize(glm::cross(n, a)), v = glm::cross(n, u);
    return u * std::cos(phi) + v * std::sin(phi);
}

// Row `patch` of the walk's transfer, channel c: exit flux per patch of the
// medium (counted from its first) per unit flux entering, its gradient in the
// tangential part of the direction of entry and its slope in that part's square.
struct WalkRow {
    std::vector<double> row, angular;
    std::vector<glm::dvec3> gradient;
    explicit WalkRow(size_t k) : row(k, 0.0), angular(k, 0.0), gradient(k, glm::dvec3(0.0)) {}
};
void walkRow(const MeshBoundary& boundary, const SurfaceTexels& tx, const PatchTexels& pt,
             const PatchIndex& index, const Material& mat, int first, int patch, int channel,
             const PatchTransferOptions& opt, WalkRow& out) {
    const double sigmaT = mat.sigmaSPrime[channel] + mat.sigmaA[channel];
    const double albedo = mat.sigmaSPrime[channel] / sigmaT;
    const double eps = boundary.epsilon();
    const double invEta = 1.0 / mat.eta;
    const double qTop =
        opt.entrySin > 0 ? opt.entrySin * opt.entrySin : TSIS_ENTRY_TOP_SIN2(mat.eta);
    const double qMean = 0.5 * qTop;
    const int pairs = (opt.photons + 1) / 2;
    // Pairs take the strata of q in an order unrelated to their azimuths'
    // (a stride coprime to their count), so the two slopes do not mix.
    int stride = pairs / 2 + 1;
    while (std::gcd(stride, pairs) != 1) ++stride;
    for (int k = 0; k < opt.photons; ++k) {
        Rng rng(opt.seed, (static_cast<uint64_t>(patch) * 3 + static_cast<uint64_t>(channel)) *
                                  static_cast<uint64_t>(opt.photons) +
                              static_cast<uint64_t>(k));
        const auto t = static_cast<size_t>(
            drawTexel(pt, static_cast<size_t>(patch), (k + rng.uniform()) / opt.photons));
        const glm::dvec3 n = glm::normalize(glm::dvec3(tx.normal[t]));
        // Azimuths in antithetic pairs at one angle: the gradient's estimate
        // loses the mean's variance.
        const int pair = k / 2;
        const double phi = 2.0 * M_PI * (pair + rng.uniform()) / pairs + (k % 2 ? M_PI : 0.0);
        const double q =
            qTop * (static_cast<double>((static_cast<long long>(pair) * stride) % pairs) + 0.5) /
            pairs;
        const double sinE = std::sqrt(q), cosE = std::sqrt(1.0 - q);
        const glm::dvec3 tangent = tangentAt(n, phi);
        glm::dvec3 pos = glm::dvec3(tx.position[t]) - n * eps;
        glm::dvec3 dir = -n * cosE + tangent * sinE;
        double w = 1.0;
        int scatterings = 0;
        for (int bounce = 0; bounce < kMaxBounces; ++bounce) {
            const double s = -std::log(1.0 - rng.uniform()) / sigmaT;
            SurfaceHit hit;
            if (!boundary.intersect(pos, dir, s, hit)) {
                pos += dir * s;
                ++scatterings;
                w *= albedo;
                if (w < kRoulette) {
                    if (rng.uniform() >= w / kRoulette) break;
                    w = kRoulette;
                }
                dir = uniformSphere(rng.uniform(), rng.uniform());
                continue;
            }
            const double cosI = glm::dot(dir, hit.normal);
            if (rng.uniform() < fresnelReflectance(invEta, std::abs(cosI))) {
                dir = reflect(dir, hit.normal);
                pos = hit.position - hit.normal * (cosI > 0 ? eps : -eps);
                continue;
            }
            // Light that crosses a thin part unscattered leaves along the
            // light's direction, not diffusely (docs/design.md §14): not counted.
            if (scatterings == 0 && opt.excludeUnscattered) break;
            // With --single-scatter the frame adds Jensen's L⁽¹⁾ itself.
            if (scatterings == 1 && opt.excludeSingle) break;
            const auto j = static_cast<size_t>(
                index.nearest(glm::vec3(hit.position), glm::vec3(hit.normal)) - first);
            out.row[j] += w;
            out.gradient[j] += w * sinE * tangent;
            out.angular[j] += w * (q - qMean);
            break;
        }
    }
    if (opt.photons == 0) return;  // the model alone (tests)
    // T ≈ T0 + G·s + H·(q − μ), s = sin θe·t, q = |s|² uniform on [0, qTop]:
    // E[w·s] = G·E[s sᵀ] = G·μ/2 and E[w·(q − μ)] = H·Var q = H·qTop²/12.
    for (size_t j = 0; j < out.row.size(); ++j) {
        out.row[j] /= opt.photons;
        out.gradient[j] *= 2.0 / (qMean * opt.photons);
        out.angular[j] *= 12.0 / (qTop * qTop * opt.photons);
    }
}

// Row `patch` of the model's transfer (rgb): the profile's exitance at the
// medium's texels from modelSamples entry points drawn by area. A patch farther
// than kFarRadii of its radii from the entry point is taken whole at its centre
// (the profile varies little across it there), a nearer one texel by texel.
constexpr double kFarRadii = 4.0;
void modelRow(const SurfaceTexels& tx, const PatchTexels& pt, const PatchTransfer& t,
              const ProfileTable& exitance, int first, int last, int patch, int samples,
              std::vector<glm::dvec3>& row) {
    for (int s = 0; s < samples; ++s) {
        const glm::vec3 y = tx.position[static_cast<size_t>(
            drawTexel(pt, static_cast<size_t>(patch), (s + 0.5) / samples))];
        for (int j = first; j < last; ++j) {
            const auto ju = static_cast<size_t>(j);
            const float d = glm::length(t.centre[ju] - y);
            glm::dvec3& out = row[static_cast<size_t>(j - first)];
            if (d > kFarRadii * t.radius[ju]) {
                out += glm::dvec3(exitance.lookup(d)) * static_cast<double>(t.area[ju]);
                continue;
            }
            for (int x : pt.texels[ju]) {
                const auto xi = static_cast<size_t>(x);
                out += glm::dvec3(exitance.lookup(glm::length(tx.position[xi] - y)) * tx.area[xi]);
            }
        }
    }
    for (glm::dvec3& v : row) v /= samples;
}

}  // namespace

PatchTransfer fitPatchTransfer(const Mesh& mesh, const SurfaceTexels& texels,
                               const std::vector<TransferMedium>& media,
                               const PatchTransferOptions& opt, uint64_t key) {
    Timer timer;
    PatchTransfer t;
    t.key = key;
    makePatches(texels, media.size(), opt.patches, t);
    const PatchTexels pt = patchTexels(texels, t);
    const MeshBoundary boundary(mesh);
    // One task per patch: its rows (walk and model, three channels) are its own.
    Progress progress("object transport", t.patches());
    std::atomic<long long> done{0};
    t.truthOut.assign(media.size(), glm::vec3(0.0f));
    t.modelOut.assign(media.size(), glm::vec3(0.0f));
    std::vector<glm::dvec3> truthOut(static_cast<size_t>(t.patches())),
        modelOut(static_cast<size_t>(t.patches()));
    std::vector<PatchIndex> indices;
    for (size_t m = 0; m < media.size(); ++m) indices.emplace_back(t, static_cast<int>(m));
    parallelFor(static_cast<size_t>(t.patches()), 1, [&](size_t b, size_t e) {
        for (size_t p = b; p < e; ++p) {
            const int m = t.medium[p];
            const int first = t.mediumStart[static_cast<size_t>(m)];
            const auto k = static_cast<size_t>(t.mediumStart[static_cast<size_t>(m) + 1] - first);
            std::vector<glm::dvec3> model(k, glm::dvec3(0.0));
            modelRow(texels, pt, t, media[static_cast<size_t>(m)].exitance, first,
                     t.mediumStart[static_cast<size_t>(m) + 1], static_cast<int>(p),
                     opt.modelSamples, model);
            glm::dvec3 truthSum(0.0), modelSum(0.0);
            glm::vec3* out = &t.delta[t.blockStart[static_cast<size_t>(m)] +
                                      (p - static_cast<size_t>(first)) * k];
            glm::vec3* grad = &t.gradient[(t.blockStart[static_cast<size_t>(m)] +
                                           (p - static_cast<size_t>(first)) * k) *
                                          3];
            glm::vec3* angular = &t.angular[static_cast<size_t>(out - t.delta.data())];
            for (int c = 0; c < 3; ++c) {
                WalkRow walk(k);
                walkRow(boundary, texels, pt, indices[static_cast<size_t>(m)],
                        media[static_cast<size_t>(m)].material, first, static_cast<int>(p), c, opt,
                        walk);
                for (size_t j = 0; j < k; ++j) {
                    grad[j * 3 + static_cast<size_t>(c)] = glm::vec3(walk.gradient[j]);
                    angular[j][c] = static_cast<float>(walk.angular[j]);
                    out[j][c] = static_cast<float>(walk.row[j] - model[j][c]);
                    truthSum[c] += walk.row[j];
                    modelSum[c] += model[j][c];
                }
            }
            truthOut[p] = truthSum;
            modelOut[p] = modelSum;
            progress.update(++done);
        }
    });
    progress.finish();
    for (size_t p = 0; p < static_cast<size_t>(t.patches()); ++p) {
        const auto m = static_cast<size_t>(t.medium[p]);
        const double n = t.mediumStart[m + 1] - t.mediumStart[m];
        t.truthOut[m] += glm::vec3(truthOut[p] / n);
        t.modelOut[m] += glm::vec3(modelOut[p] / n);
    }
    t.seconds = timer.ms() / 1000.0;
    return t;
}

// The file: magic, version, key, counts, then the arrays, then an FNV-1a checksum.
namespace {
constexpr char kMagic[8] = {'t', 's', 'i', 's', 'p', 't', 'r', '1'};

template <typename T>
void put(std::string& s, const std::vector<T>& v) {
    const uint64_t n = v.size();
    s.append(reinterpret_cast<const char*>(&n), sizeof n);
    s.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}
template <typename T>
bool get(const std::string& s, size_t& at, std::vector<T>& v, uint64_t most) {
    uint64_t n;
    if (at + sizeof n > s.size()) return false;
    std::memcpy(&n, s.data() + at, sizeof n);
    at += sizeof n;
    if (n > most || at + n * sizeof(T) > s.size()) return false;
    v.resize(n);
    std::memcpy(v.data(), s.data() + at, n * sizeof(T));
    at += n * sizeof(T);
    return true;
}
}  // namespace

std::string serializePatchTransfer(const PatchTransfer& t) {
    std::string s(kMagic, sizeof kMagic);
    const int32_t version = kPatchTransferVersion;
    s.append(reinterpret_cast<const char*>(&version), sizeof version);
    s.append(reinterpret_cast<const char*>(&t.key), sizeof t.key);
    put(s, t.centre);
    put(s, t.normal);
    put(s, t.area);
    put(s, t.radius);
    put(s, t.medium);
    put(s, t.mediumStart);
    put(s, t.texelPatch);
    put(s, t.delta);
    put(s, t.gradient);
    put(s, t.angular);
    put(s, t.blockStart);
    put(s, t.truthOut);
    put(s, t.modelOut);
    const uint64_t sum = fnv1a(s.data(), s.size());
    s.append(reinterpret_cast<const char*>(&sum), sizeof sum);
    return s;
}

bool parsePatchTransfer(const std::string& s, uint64_t key, size_t texels, PatchTransfer& t) {
    const size_t head = sizeof kMagic + sizeof(int32_t) + sizeof(uint64_t);
    if (s.size() < head + sizeof(uint64_t) || std::memcmp(s.data(), kMagic, sizeof kMagic) != 0)
        return false;
    uint64_t sum;
    std::memcpy(&sum, s.data() + s.size() - sizeof sum, sizeof sum);
    if (sum != fnv1a(s.data(), s.size() - sizeof sum)) return false;
    int32_t version;
    std::memcpy(&version, s.data() + sizeof kMagic, sizeof version);
    std::memcpy(&t.key, s.data() + sizeof kMagic + sizeof version, sizeof t.key);
    if (version != kPatchTransferVersion || t.key != key) return false;
    size_t at = head;
    const uint64_t most = s.size();
    if (!(get(s, at, t.centre, most) && get(s, at, t.normal, most) && get(s, at, t.area, most) &&
          get(s, at, t.radius, most) && get(s, at, t.medium, most) &&
          get(s, at, t.mediumStart, most) && get(s, at, t.texelPatch, most) &&
          get(s, at, t.delta, most) && get(s, at, t.gradient, most) &&
          get(s, at, t.angular, most) && get(s, at, t.blockStart, most) &&
          get(s, at, t.truthOut, most) && get(s, at, t.modelOut, most)))
        return false;
    // Consistent counts, or the file is not for these texels.
    const size_t k = t.centre.size();
    if (t.texelPatch.size() != texels || t.normal.size() != k || t.area.size() != k ||
        t.radius.size() != k || t.medium.size() != k || t.mediumStart.empty() ||
        t.blockStart.size() + 1 != t.mediumStart.size() || t.truthOut.size() != t.blockStart.size())
        return false;
    size_t cells = 0;
    for (size_t m = 0; m + 1 < t.mediumStart.size(); ++m) {
        const int a = t.mediumStart[m], b = t.mediumStart[m + 1];
        if (a < 0 || b < a || static_cast<size_t>(b) > k || t.blockStart[m] != cells) return false;
        cells += static_cast<size_t>(b - a) * static_cast<size_t>(b - a);
    }
    if (t.delta.size() != cells || t.gradient.size() != 3 * cells || t.angular.size() != cells ||
        static_cast<size_t>(t.mediumStart.back()) != k)
        return false;
    for (int p : t.texelPatch)
        if (p < 0 || static_cast<size_t>(p) >= k) return false;
    return true;
}

namespace {

// The cache file of `key`, or none without a usable cache folder.
std::filesystem::path transferFile(uint64_t key) {
    const std::string root = usableCacheDirectory();
    if (root.empty()) return {};
    return std::filesystem::path(root) / "transport" / (hexKey(key) + ".transfer");
}

}  // namespace

std::optional<PatchTransfer> loadPatchTransfer(uint64_t key, size_t texels) {
    const std::filesystem::path file = transferFile(key);
    if (file.empty() || !notRegularFile(file.string()).empty()) return std::nullopt;
    std::ifstream f(file, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    PatchTransfer t;
    if (!parsePatchTransfer(bytes, key, texels, t)) return std::nullopt;
    return t;
}

void storePatchTransfer(const PatchTransfer& t, uint64_t key) {
    const std::filesystem::path file = transferFile(key);
    if (file.empty()) return;
    try {
        std::filesystem::create_directories(file.parent_path());
        writeTextFile(file, serializePatchTransfer(t));
    } catch (...) {
        // A cache that cannot be written is only slower.
    }
}

PatchTransfer cachedPatchTransfer(const Mesh& mesh, const SurfaceTexels& texels,
                                  const std::vector<TransferMedium>& media,
                                  const PatchTransferOptions& options, uint64_t key, bool* loaded) {
    std::optional<PatchTransfer> t = loadPatchTransfer(key, texels.size());
    if (loaded) *loaded = t.has_value();
    if (t) return std::move(*t);
    PatchTransfer fitted = fitPatchTransfer(mesh, texels, media, options, key);
    storePatchTransfer(fitted, key);
    return fitted;
}

}  // namespace tsis
