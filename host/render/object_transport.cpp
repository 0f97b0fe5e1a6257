#include "render/object_transport.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <glm/geometric.hpp>
#include <string>

#include "cl/launch.h"
#include "physics/fresnel.h"
#include "render/frame_keys.h"
#include "tsis_shared.h"
#include "util/error.h"
#include "util/hash.h"
#include "util/parallel.h"
#include "util/parse.h"
#include "util/progress.h"

namespace tsis {

namespace {

constexpr int kMaxGridCells = 64;
const glm::dvec3 kLuma(TSIS_LUMA_R, TSIS_LUMA_G, TSIS_LUMA_B);

// TSIS_TRANSPORT_PATCHES / _PHOTONS (tests, benches) over the defaults.
PatchTransferOptions transferOptions(uint32_t seed) {
    PatchTransferOptions o;
    o.seed = seed;
    auto read = [](const char* name, int& field, long long lo, long long hi) {
        if (const char* v = std::getenv(name))
            field = static_cast<int>(std::clamp(parseInteger(name, v), lo, hi));
    };
    read("TSIS_TRANSPORT_PATCHES", o.patches, 1, 4096);
    read("TSIS_TRANSPORT_PHOTONS", o.photons, 1, 1 << 20);

    return o;
}

// The lights for the kernel: (vec, type: 0 point, 1 directional), (rgb, 0).
std::vector<float> lightTable(const Scene& scene) {
    std::vector<float> out;
    for (const Light& l : scene.lights)
        out.insert(out.end(),
                   {l.vec.x, l.vec.y, l.vec.z, l.type == Light::Type::Point ? 0.0f : 1.0f, l.rgb.x,
                    l.rgb.y, l.rgb.z, 0.0f});
    return out;
}

}  // namespace

TransportGrid::Read TransportGrid::read(const glm::vec3& x) const {
    Read r;
    r.f = (x - origin) / cell;
    glm::ivec3 i0;
    for (int a = 0; a < 3; ++a) {
        r.f[a] = std::clamp(r.f[a], 0.0f, static_cast<float>(dims[a] - 1));
        i0[a] = std::min(static_cast<int>(r.f[a]), std::max(dims[a] - 2, 0));
        r.f[a] -= static_cast<float>(i0[a]);
    }
    for (int c = 0; c < 8; ++c) {
        const glm::ivec3 q = glm::min(i0 + glm::ivec3(c & 1, (c >> 1) & 1, (c >> 2) & 1), dims - 1);
        r.node[c] = static_cast<uint32_t>((static_cast<size_t>(q.z) * dims.y + q.y) * dims.x + q.x);
    }
    return r;
}

glm::vec3 TransportGrid::blend(const Read& r) const {
    const glm::vec3& f = r.f;
    glm::vec3 sum(0.0f);
    for (int c = 0; c < 8; ++c) {
        const float w = ((c & 1) ? f.x : 1 - f.x) * (((c >> 1) & 1) ? f.y : 1 - f.y) *
                        (((c >> 2) & 1) ? f.z : 1 - f.z);
        sum += w * value[r.node[c]];
    }
    return sum;
}

void TransportGrid::setNode(size_t n, const std::vector<glm::vec3>& correction, int first) {
    glm::vec3 v(0.0f);
    for (size_t k = 0; k < kTaps; ++k) {
        const int p = patch[n * kTaps + k];
        if (p >= 0) v += weight[n * kTaps + k] * correction[static_cast<size_t>(p - first)];
    }
    value[n] = v;
}

TransportGrid transportGrid(const PatchTransfer& t, int m) {
    TransportGrid g;
    const int first = t.mediumStart[static_cast<size_t>(m)];
    const int last = t.mediumStart[static_cast<size_t>(m) + 1];
    if (first == last) return g;
    glm::vec3 lo(1e30f), hi(-1e30f);
    float r = 0;
    for (int p = first; p < last; ++p) {
        lo = glm::min(lo, t.centre[static_cast<size_t>(p)]);
        hi = glm::max(hi, t.centre[static_cast<size_t>(p)]);
        r = std::max(r, t.radius[static_cast<size_t>(p)]);
    }
    lo -= glm::vec3(2 * r);
    hi += glm::vec3(2 * r);
    const float extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
    g.cell = std::max(0.5f * r, extent / (kMaxGridCells - 1));
    g.origin = lo;
    for (int a = 0; a < 3; ++a)
        g.dims[a] =
            std::clamp(static_cast<int>(std::ceil((hi[a] - lo[a]) / g.cell)) + 1, 2, kMaxGridCells);
    g.patch.assign(g.nodes() * TransportGrid::kTaps, -1);
    g.weight.assign(g.nodes() * TransportGrid::kTaps, 0.0f);
    g.value.assign(g.nodes(), glm::vec3(0.0f));
    g.made.assign(g.nodes(), 0);
    // Gaussian weights of width r over the nearest kTaps centres; each node
    // on its own (a 64³ grid over a few hundred patches: the threads share it).
    const float inv = 1.0f / (r * r);
    parallelFor(g.nodes(), 2048, [&](size_t begin, size_t end) {
        std::vector<std::pair<float, int>> near;
        for (size_t n = begin; n < end; ++n) {
            const glm::ivec3 q(
                static_cast<int>(n % static_cast<size_t>(g.dims.x)),
                static_cast<int>(n / static_cast<size_t>(g.dims.x) % static_cast<size_t>(g.dims.y)),
                static_cast<int>(n / (static_cast<size_t>(g.dims.x) * g.dims.y)));
            const glm::vec3 x = g.origin + glm::vec3(q) * g.cell;
            near.clear();
            for (int p = first; p < last; ++p) {
                const glm::vec3 d = x - t.centre[static_cast<size_t>(p)];
                near.emplace_back(glm::dot(d, d), p);
            }
            const size_t k = std::min<size_t>(TransportGrid::kTaps, near.size());
            std::partial_sort(near.begin(), near.begin() + static_cast<long>(k), near.end());
            // Relative to the nearest, so far nodes still get their nearest
            // patches. The node's value is Σ g·ΔE / Σ g·A over its patches
            // (flux over area, not a mean of densities): a sliver of a patch
            // with a photon or two on it cannot dominate.
            const float d0 = near[0].first;
            float sum = 0;
            for (size_t j = 0; j < k; ++j)
                sum += std::exp(-(near[j].first - d0) * inv) *
                       t.area[static_cast<size_t>(near[j].second)];
            for (size_t j = 0; j < k; ++j) {
                g.patch[n * TransportGrid::kTaps + j] = near[j].second;
                g.weight[n * TransportGrid::kTaps + j] =
                    sum > 0 ? std::exp(-(near[j].first - d0) * inv) / sum : 0.0f;
            }
        }
    });
    return g;
}

namespace {

// bfloat16: a float's top 16 bits, rounded to nearest even.
uint16_t toBfloat16(float v) {
    uint32_t u = 0;
    std::memcpy(&u, &v, sizeof u);
    u += 0x7fffu + ((u >> 16) & 1u);
    return static_cast<uint16_t>(u >> 16);
}

float fromBfloat16(uint16_t h) {
    const uint32_t u = static_cast<uint32_t>(h) << 16;
    float v = 0;
    std::memcpy(&v, &u, sizeof v);
    return v;
}

}  // namespace

PackedTransfer packTransfer(const PatchTransfer& t) {
    PackedTransfer p;
    const size_t media = t.mediumStart.empty() ? 0 : t.mediumStart.size() - 1;
    for (size_t m = 0; m < media; ++m) {
        const int first = t.mediumStart[m];
        const auto k = static_cast<size_t>(t.mediumStart[m + 1] - first);
        p.first.push_back(first);
        p.count.push_back(static_cast<int>(k));
        std::vector<uint16_t>& out = p.pairs.emplace_back(k * k * PackedTransfer::kPerPair, 0);
        for (size_t pair = 0; pair < k * k; ++pair) {
            const size_t at = t.blockStart[m] + pair;
            uint16_t* o = &out[pair * PackedTransfer::kPerPair];
            const glm::vec3 d = t.delta[at], h = t.angular[at];
            for (int c = 0; c < 3; ++c) {
                o[c] = toBfloat16(d[c]);
                o[3 + c] = toBfloat16(h[c]);
                // G's rows are per channel, its columns the axes.
                for (int axis = 0; axis < 3; ++axis)
                    o[6 + 3 * axis + c] = toBfloat16(t.gradient[at * 3 + size_t(c)][axis]);
            }
        }
    }
    return p;
}

std::vector<glm::vec3> patchCorrection(const PackedTransfer& t, int m,
                                       const std::vector<glm::vec3>& flux,
                                       const std::vector<glm::vec4>& direction,
                                       double exitancePerB) {
    const auto first = static_cast<size_t>(t.first[static_cast<size_t>(m)]);
    const auto k = static_cast<size_t>(t.count[static_cast<size_t>(m)]);
    const std::vector<uint16_t>& pairs = t.pairs[static_cast<size_t>(m)];
    // Per entry patch: its flux, the mean tangential direction of the light
    // entering it and that direction's mean square less the walks' (w).
    struct Entry {
        glm::vec3 phi, s;
        float dq = 0;
        size_t i = 0;
    };
    std::vector<Entry> entries;
    for (size_t i = 0; i < k; ++i) {
        const glm::vec3 phi = flux[first + i];
        if (phi == glm::vec3(0.0f)) continue;
        const double y = kLuma.x * phi.x + kLuma.y * phi.y + kLuma.z * phi.z;
        const glm::dvec4 dir(direction[first + i]);
        entries.push_back({phi, y > 0 ? glm::vec3(glm::dvec3(dir) / y) : glm::vec3(0.0f),
                           y > 0 ? static_cast<float>(dir.w / y) : 0.0f, i});
    }
    // Columns in chunks over the cores, each summed over the entries in order
    // (the same bytes for any thread count).
    std::vector<glm::dvec3> sum(k, glm::dvec3(0.0));
    parallelFor(k, 64, [&](size_t begin, size_t end) {
        for (const Entry& e : entries) {
            const uint16_t* row = &pairs[e.i * k * PackedTransfer::kPerPair];
            for (size_t j = begin; j < end; ++j) {
                const uint16_t* c = row + j * PackedTransfer::kPerPair;
                glm::vec3 v;
                for (int ch = 0; ch < 3; ++ch)
                    v[ch] = fromBfloat16(c[ch]) + fromBfloat16(c[3 + ch]) * e.dq +
                            fromBfloat16(c[6 + ch]) * e.s.x + fromBfloat16(c[9 + ch]) * e.s.y +
                            fromBfloat16(c[12 + ch]) * e.s.z;
                sum[j] += glm::dvec3(e.phi * v);
            }
        }
    });
    std::vector<glm::vec3> out(k);
    for (size_t j = 0; j < k; ++j) out[j] = glm::vec3(sum[j] / exitancePerB);
    return out;
}

int ObjectTransport::gridIndexOfTag(float tag) const {
    const int m = static_cast<int>(std::lround(tag)) - 1;
    if (m < 0 || static_cast<size_t>(m) >= grids_.size() ||
        grids_[static_cast<size_t>(m)].value.empty())
        return -1;
    return m;
}

void ObjectTransport::clearGrids() {
    grids_.clear();
    corrections_.clear();
    ++installs_;
}

const ObjectTransport::PointReads& ObjectTransport::readsOf(PointReads& cache,
                                                            const std::vector<float>& points,
                                                            size_t count) {
    const auto end = points.begin() + static_cast<std::ptrdiff_t>(count * 4);
    // Bytewise: the same bits give the same reads.
    if (cache.installed == installs_ && cache.points.size() == count * 4 &&
        (count == 0 ||
         std::memcmp(points.data(), cache.points.data(), count * 4 * sizeof(float)) == 0))
        return cache;
    cache.points.assign(points.begin(), end);
    cache.installed = installs_;
    cache.grid.assign(count, -1);
    cache.reads.resize(count);
    parallelFor(count, 8192, [&](size_t begin, size_t last) {
        for (size_t k = begin; k < last; ++k) {
            const int g = gridIndexOfTag(points[k * 4 + 3]);
            cache.grid[k] = g;
            if (g >= 0)
                cache.reads[k] = grids_[static_cast<size_t>(g)].read(
                    glm::vec3(points[k * 4], points[k * 4 + 1], points[k * 4 + 2]));
        }
    });
    // Each node once, in node order.
    cache.nodes.assign(grids_.size(), {});
    std::vector<std::vector<uint8_t>> read(grids_.size());
    for (size_t g = 0; g < grids_.size(); ++g) read[g].assign(grids_[g].value.size(), 0);
    for (size_t k = 0; k < count; ++k)
        if (cache.grid[k] >= 0)
            for (uint32_t n : cache.reads[k].node) read[static_cast<size_t>(cache.grid[k])][n] = 1;
    for (size_t g = 0; g < grids_.size(); ++g)
        for (size_t n = 0; n < read[g].size(); ++n)
            if (read[g][n]) cache.nodes[g].push_back(static_cast<uint32_t>(n));
    return cache;
}

void ObjectTransport::fillNodes(const PointReads& r) {
    for (size_t g = 0; g < grids_.size(); ++g) {
        TransportGrid& grid = grids_[g];
        const std::vector<uint32_t>& nodes = r.nodes[g];
        if (g >= corrections_.size() || corrections_[g].empty()) continue;
        const int first = transfer_.mediumStart[g];
        parallelFor(nodes.size(), 4096, [&](size_t begin, size_t end) {
            for (size_t i = begin; i < end; ++i) {
                const uint32_t n = nodes[i];
                if (grid.made[n] == gridsMade_) continue;
                grid.setNode(n, corrections_[g], first);
                grid.made[n] = gridsMade_;
            }
        });
    }
}

const AtlasRadiosity* ObjectTransport::corrected(const AtlasRadiosity& copy, uint64_t lighting) {
    madeCopy_ = false;
    if (!fitted_ || lighting == 0 || lighting != lightingOf_ || grids_.empty()) return nullptr;
    const uint64_t key = Hasher(copy.radiosityKey).add(copy.positionsKey).add(gridsMade_).digest();
    madeCopy_ = key != correctedOf_;
    if (madeCopy_) {
        correctedB_ = *copy.radiosity;
        const PointReads& r = readsOf(copyReads_, *copy.positions, correctedB_.size() / 4);
        fillNodes(r);
        parallelFor(correctedB_.size() / 4, 16384, [&](size_t begin, size_t end) {
            for (size_t t = begin; t < end; ++t) {
                if (r.grid[t] < 0) continue;
                const glm::vec3 add = grids_[static_cast<size_t>(r.grid[t])].blend(r.reads[t]);
                // Not clamped here: the composite clamps B after the
                // lookup's interpolation, as the CL side does at the point.
                for (size_t c = 0; c < 3; ++c) correctedB_[t * 4 + c] += add[c];
            }
        });
        corrected_ = copy;
        corrected_.radiosity = &correctedB_;
        corrected_.radiosityKey = key;
        correctedOf_ = key;
    }
    return &corrected_;
}

ObjectTransport::ObjectTransport(ClRuntime& cl)
    : cl_(cl), kernel_(cl.kernel("patch_flux.cl", "tsis_patch_flux")) {}

bool ObjectTransport::fit(const FrameContext& ctx, const std::vector<KeyedProfile>& slotProfiles,
                          const AtlasCl& position, const AtlasCl& normal,
                          FrameGraph::Resources& res) {
    const SceneMedia& sm = *ctx.media;
    const size_t media = sm.etaOfMedium.size();
    // The walks' seed is the fit's own, not the frame's: methods without
    // random numbers stay the same image for any --seed.
    // What the fit depends on besides the geometry: each medium's material,
    // profile and exit term.
    Hasher inputs;
    inputs.add(kPatchTransferVersion).add(ctx.options->exit);
    std::vector<TransferMedium> mediaIn(media);
    exitancePerB_.assign(media, 1.0);
    for (size_t m = 0; m < media; ++m) {
        const size_t slot = sm.slotOfMedium[m];
        const Material& mat = sm.slotMedium(*ctx.scene, slot);
        mediaIn[m].material = mat;
        // Exitance per unit B: Jensen's Ft/π·B lets out c·B, the normalised term B.
        exitancePerB_[m] = exitScale(ctx.options->exit, mat.eta) / normalizedExitScale(mat.eta);
        inputs.add(mat.sigmaSPrime).add(mat.sigmaA).add(mat.eta).add(slotProfiles[slot].key);
    }
    PatchTransferOptions opt = transferOptions(1);
    opt.excludeSingle = addsSingleScatter(*ctx.options);
    inputs.add(opt.patches)
        .add(opt.photons)
        .add(opt.modelSamples)
        .add(opt.excludeUnscattered)
        .add(opt.excludeSingle)
        .add(opt.entrySin);
    // The mesh's own hash too: a view that resizes the object keeps its atlas.
    const uint64_t geometry = Hasher(position.version)
                                  .add(normal.version)
                                  .add(ctx.meshKey)
                                  .add(ctx.atlasResolution)
                                  .digest();
    if (fitted_ && geometry == geometryOf_ && inputs.digest() == inputsKey_) return true;
    // No correction of other inputs while this frame's is made.
    fitted_ = false;
    clearGrids();
    std::shared_ptr<FitRequest> request = waiting_;
    if (!request || request->geometry != geometry || request->inputs != inputs.digest()) {
        const size_t texels = static_cast<size_t>(ctx.atlasResolution) * ctx.atlasResolution;
        std::vector<float> pos(texels * 4), nrm(texels * 4);
        cl::CommandQueue& q = cl_.queue();
        q.enqueueReadBuffer(position.buffer, CL_TRUE, 0, texels * 16, pos.data());
        q.enqueueReadBuffer(normal.buffer, CL_TRUE, 0, texels * 16, nrm.data());
        SurfaceTexels tx;
        for (size_t i = 0; i < texels; ++i) {
            const float tag = pos[i * 4 + 3], area = nrm[i * 4 + 3];
            if (!(tag > 0) || !(area > 0)) continue;
            tx.position.emplace_back(pos[i * 4], pos[i * 4 + 1], pos[i * 4 + 2]);
            glm::vec3 n(nrm[i * 4], nrm[i * 4 + 1], nrm[i * 4 + 2]);
            const float len = glm::length(n);
            tx.normal.push_back(len > 0 ? n / len : glm::vec3(0, 1, 0));
            tx.area.push_back(area);
            tx.medium.push_back(
                std::clamp(static_cast<int>(std::lround(tag)) - 1, 0, static_cast<int>(media) - 1));
            tx.texel.push_back(static_cast<int>(i));
        }
        const double rMax = ctx.maxDistance();
        for (size_t m = 0; m < media; ++m) {
            const KeyedProfile& p = slotProfiles[sm.slotOfMedium[m]];
            const double k = exitancePerB_[m];
            mediaIn[m].exitance = ProfileTable::build([&](double r) { return p.f(r) * k; }, rMax);
        }
        const uint64_t key =
            Hasher(inputs.digest()).addAll(tx.position).addAll(tx.normal).addAll(tx.area).digest();
        request = std::make_shared<FitRequest>();
        *request = {key, geometry, inputs.digest(), std::move(tx), std::move(mediaIn),
                    opt, nullptr};
    }
    bool loaded = false;
    if (background_) {
        std::optional<PatchTransfer> t = fitInBackground(request, ctx.scene->mesh, loaded);
        if (!t) {
            waiting_ = request;
            res.stats().set("transport_pending", 1.0);
            return false;
        }
        transfer_ = std::move(*t);
    } else {
        transfer_ = cachedPatchTransfer(ctx.scene->mesh, request->texels, request->media,
                                        request->options, request->key, &loaded);
    }
    waiting_.reset();
    res.stats().set("transport_fit_s", transfer_.seconds);
    res.stats().set("transport_loaded", loaded ? 1.0 : 0.0);
    fitted_ = true;
    geometryOf_ = geometry;
    inputsKey_ = inputs.digest();
    fluxOf_ = 0;
    install(*request, res);
    return true;
}

void ObjectTransport::install(const FitRequest& request, FrameGraph::Resources& res) {
    const SurfaceTexels& tx = request.texels;
    const size_t media = request.media.size();
    cl::CommandQueue& q = cl_.queue();
    // The patches' texels for the device's sums (CSR by patch).
    const auto patches = static_cast<size_t>(transfer_.patches());
    clearGrids();
    packed_ = packTransfer(transfer_);
    if (patches == 0) return;  // nothing covered: no correction
    std::vector<int> start(patches + 1, 0), list(tx.size());
    std::vector<size_t> of(tx.size());  // each list entry's SurfaceTexels index
    for (int p : transfer_.texelPatch) ++start[static_cast<size_t>(p) + 1];
    for (size_t p = 0; p < patches; ++p) start[p + 1] += start[p];
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (size_t k = 0; k < tx.size(); ++k) {
        const auto at = static_cast<size_t>(fill[static_cast<size_t>(transfer_.texelPatch[k])]++);
        list[at] = tx.texel[k];
        of[at] = k;
    }
    q.enqueueWriteBuffer(start_.reserve(cl_.context(), start.size() * sizeof(int)), CL_TRUE, 0,
                         start.size() * sizeof(int), start.data());
    q.enqueueWriteBuffer(texels_.reserve(cl_.context(), std::max<size_t>(list.size(), 1) * 4),
                         CL_TRUE, 0, list.size() * sizeof(int), list.data());
    // The texels that give each patch's light direction, evenly along its
    // list (atlas order: spread over the patch), with their position (w: the
    // medium) and normal side by side: the kernel's cost was reading those
    // from two atlases at random.
    constexpr size_t kSamples = TSIS_PATCH_DIRECTION_SAMPLES;
    std::vector<int> sampleTexel(patches * kSamples, -1);
    std::vector<float> sampleGeometry(patches * kSamples * 8, 0.0f);
    for (size_t p = 0; p < patches; ++p) {
        const int n = start[p + 1] - start[p];
        const int ns = std::min<int>(n, static_cast<int>(kSamples));
        for (int i = 0; i < ns; ++i) {
            const size_t at = static_cast<size_t>(start[p]) + static_cast<size_t>(2 * i + 1) *
                                                                  static_cast<size_t>(n) /
                                                                  static_cast<size_t>(2 * ns);
            const size_t k = of[at], j = p * kSamples + static_cast<size_t>(i);
            sampleTexel[j] = list[at];
            const glm::vec3 x = tx.position[k], nrm = glm::normalize(tx.normal[k]);
            std::copy_n(&x.x, 3, &sampleGeometry[j * 8]);
            sampleGeometry[j * 8 + 3] = static_cast<float>(tx.medium[k]);
            std::copy_n(&nrm.x, 3, &sampleGeometry[j * 8 + 4]);
        }
    }
    q.enqueueWriteBuffer(sampleTexels_.reserve(cl_.context(), sampleTexel.size() * sizeof(int)),
                         CL_TRUE, 0, sampleTexel.size() * sizeof(int), sampleTexel.data());
    q.enqueueWriteBuffer(
        sampleGeometry_.reserve(cl_.context(), sampleGeometry.size() * sizeof(float)), CL_TRUE, 0,
        sampleGeometry.size() * sizeof(float), sampleGeometry.data());
    // The grids follow the patches alone (not the materials): a switch back
    // and forth between materials finds them made.
    int made = 0;
    for (size_t m = 0; m < media; ++m) {
        const auto first = static_cast<size_t>(transfer_.mediumStart[m]);
        const auto last = static_cast<size_t>(transfer_.mediumStart[m + 1]);
        Hasher h;
        for (size_t p = first; p < last; ++p)
            h.add(transfer_.centre[p]).add(transfer_.radius[p]).add(transfer_.area[p]);
        const uint64_t gridKey = h.add(first).add(last).digest();
        auto cached = std::find_if(gridCache_.begin(), gridCache_.end(),
                                   [&](const auto& e) { return e.first == gridKey; });
        if (cached == gridCache_.end()) {
            if (gridCache_.size() == kCachedGrids) gridCache_.erase(gridCache_.begin());
            gridCache_.emplace_back(gridKey, transportGrid(transfer_, static_cast<int>(m)));
            cached = gridCache_.end() - 1;
            ++made;
        }
        grids_.push_back(cached->second);
    }
    res.stats().set("transport_grids_made", made);
}

bool ObjectTransport::backgroundFitReady() const {
    return running_.valid() &&
           running_.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
}

void ObjectTransport::collectBackgroundFit() {
    if (!backgroundFitReady()) return;
    const uint64_t key = runningKey_;
    made_.emplace(key, running_.get());  // a fit's error is this frame's
    if (queued_) {
        std::shared_ptr<FitRequest> next = std::move(queued_);
        queued_.reset();
        if (next->key != key) startBackgroundFit(std::move(next));
    }
}

void ObjectTransport::startBackgroundFit(std::shared_ptr<FitRequest> request) {
    if (running_.valid()) {
        if (runningKey_ != request->key) queued_ = std::move(request);
        return;
    }
    runningKey_ = request->key;
    // The fit reports to this thread's observer (the viewer's panel).
    running_ = std::async(std::launch::async, [request, observer = currentProgressObserver()] {
        ScopedProgressObserver scoped(observer);
        PatchTransfer t = fitPatchTransfer(*request->mesh, request->texels, request->media,
                                           request->options, request->key);
        storePatchTransfer(t, request->key);
        return t;
    });
}

std::optional<PatchTransfer> ObjectTransport::fitInBackground(
    const std::shared_ptr<FitRequest>& request, const Mesh& mesh, bool& loaded) {
    collectBackgroundFit();
    loaded = false;
    if (made_ && made_->first == request->key) {
        PatchTransfer t = std::move(made_->second);
        made_.reset();
        return t;
    }
    if (std::optional<PatchTransfer> t = loadPatchTransfer(request->key, request->texels.size())) {
        loaded = true;
        return t;
    }
    if (!request->mesh) request->mesh = std::make_shared<const Mesh>(mesh);
    startBackgroundFit(request);
    return std::nullopt;
}

void ObjectTransport::addPass(FrameGraph& graph, const FrameContext& ctx,
                              std::vector<KeyedProfile> slotProfiles,
                              FrameGraphId<RadiosityImage> radiosity) {
    graph.addPass(
        "object_transport",
        [&](FrameGraph::Builder& b) {
            b.read(ctx.fluxAtlas);
            b.read(ctx.positionAtlas);
            b.read(ctx.normalAtlas);
            b.read(ctx.points);
            b.read(radiosity);
            b.write(radiosity);
        },
        [this, &ctx, profiles = std::move(slotProfiles), radiosity](FrameGraph::Resources& res) {
            const AtlasCl& flux = res.read(ctx.fluxAtlas);
            lightingOf_ = 0;
            if (!fit(ctx, profiles, res.read(ctx.positionAtlas), res.read(ctx.normalAtlas), res))
                return;  // made in the background: this frame has no correction
            const auto patches = static_cast<size_t>(transfer_.patches());
            if (patches == 0) return;
            if (flux.version != fluxOf_) {
                cl::CommandQueue& q = cl_.queue();
                const std::vector<float> lights = lightTable(*ctx.scene);
                const SceneMedia& sm = *ctx.media;
                cl::Buffer& lightBuffer =
                    lights_.reserve(cl_.context(), std::max<size_t>(lights.size(), 4) * 4);
                if (!lights.empty())
                    q.enqueueWriteBuffer(lightBuffer, CL_TRUE, 0, lights.size() * 4, lights.data());
                cl::Buffer& etaBuffer = etas_.reserve(cl_.context(), sm.etaOfMedium.size() * 4);
                q.enqueueWriteBuffer(etaBuffer, CL_TRUE, 0, sm.etaOfMedium.size() * 4,
                                     sm.etaOfMedium.data());
                cl::Buffer& out = flux_.reserve(cl_.context(), patches * 16);
                cl::Buffer& dirOut = direction_.reserve(cl_.context(), patches * 16);
                setKernelArgs(kernel_, flux.buffer, sampleTexels_.buffer, sampleGeometry_.buffer,
                              etaBuffer, lightBuffer, static_cast<int>(lights.size() / 8),
                              start_.buffer, texels_.buffer, static_cast<int>(patches), out,
                              dirOut);
                enqueue1D(q, kernel_, patches * TSIS_PATCH_GROUP, TSIS_PATCH_GROUP, nullptr);
                std::vector<float> sums(patches * 4), dirs(patches * 4);
                q.enqueueReadBuffer(out, CL_TRUE, 0, patches * 16, sums.data());
                q.enqueueReadBuffer(dirOut, CL_TRUE, 0, patches * 16, dirs.data());
                std::vector<glm::vec3> phi(patches);
                std::vector<glm::vec4> dir(patches);
                for (size_t p = 0; p < patches; ++p) {
                    phi[p] = glm::vec3(sums[p * 4], sums[p * 4 + 1], sums[p * 4 + 2]);
                    dir[p] =
                        glm::vec4(dirs[p * 4], dirs[p * 4 + 1], dirs[p * 4 + 2], dirs[p * 4 + 3]);
                }
                // The grids' nodes are filled when a frame reads them (fillNodes).
                corrections_.assign(grids_.size(), {});
                for (size_t m = 0; m < grids_.size(); ++m)
                    if (!grids_[m].value.empty())
                        corrections_[m] = patchCorrection(packed_, static_cast<int>(m), phi, dir,
                                                          exitancePerB_[m]);
                fluxOf_ = flux.version;
                ++gridsMade_;
            }
            lightingOf_ = ctx.lighting;
            const SurfacePoints& points = res.read(ctx.points);
            const PointReads& r =
                readsOf(pointReads_, points.host, static_cast<size_t>(points.count));
            fillNodes(r);
            std::vector<float>& rgba = res.write(radiosity).rgba;
            parallelFor(static_cast<size_t>(points.count), 8192, [&](size_t begin, size_t end) {
                for (size_t k = begin; k < end; ++k) {
                    if (r.grid[k] < 0) continue;
                    glm::vec3 add = grids_[static_cast<size_t>(r.grid[k])].blend(r.reads[k]);
                    if (!points.exitAlbedo.empty())
                        add *= glm::vec3(points.exitAlbedo[k * 3], points.exitAlbedo[k * 3 + 1],
                                         points.exitAlbedo[k * 3 + 2]);
                    float* b = &rgba[static_cast<size_t>(points.pixel[k]) * 4];
                    for (int c = 0; c < 3; ++c) b[c] = std::max(0.0f, b[c] + add[c]);
                }
            });
            res.stats().set("transport_patches", static_cast<double>(patches));
        });
}

}  // namespace tsis
