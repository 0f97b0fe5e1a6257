// On-disk atlas cache; see cache.h.
#include "atlas/cache.h"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

#include "util/cache_dir.h"
#include "util/error.h"
#include "util/input_file.h"
#include "util/output_file.h"
#include "util/timer.h"

namespace tsis::atlas {

namespace {

constexpr char kMagic[8] = {'T', 'S', 'I', 'S', 'A', 'T', 'L', '\x01'};

struct Hash64 {  // FNV-1a
    uint64_t h;
    explicit Hash64(uint64_t seed = 0xcbf29ce484222325ull) : h(seed) {}
    void add(const void* data, size_t size) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < size; ++i) h = (h ^ p[i]) * 0x100000001b3ull;
    }
    template <typename T>
    void value(const T& v) {
        add(&v, sizeof v);
    }
};

// MurmurHash3's finaliser: spreads every input bit over the key half.
uint64_t finalize(uint64_t x) {
    x ^= x >> 33;
    x *= 0xff51afd7ed558ccdull;
    x ^= x >> 33;
    x *= 0xc4ceb9fe1a85ec53ull;
    return x ^ (x >> 33);
}

struct Header {
    char magic[8];
    uint32_t version;
    uint32_t reserved;
    char key[32];
    uint64_t outVertices, triangles, inVertices;
    int32_t charts, pad;
    double coverage, rWstd, rP01, rP99, rMin, rMax;
    uint64_t flipped, overlaps;
};

void append(std::string& out, const void* p, size_t n) {
    out.append(static_cast<const char*>(p), n);
}

}  // namespace

std::optional<std::filesystem::path> atlasCacheDirectory() {
    const std::string root = tsis::usableCacheDirectory();
    if (root.empty()) return std::nullopt;
    return std::filesystem::path(root) / "atlas";
}

std::string cacheKey(const Mesh& mesh, const AtlasOptions& opt) {
    std::string key;
    for (uint64_t seed : {0xcbf29ce484222325ull, 0x84222325cbf29ce4ull}) {
        Hash64 h(seed);
        h.value(kAtlasVersion);
        h.value(opt.resolution);
        h.value(opt.gutterTexels);
        h.value(opt.trianglesPerProxy);
        h.value(opt.minProxies);
        h.value(opt.maxProxies);
        h.value(opt.maxChartDistortion);
        const uint64_t nv = mesh.positions.size(), nt = mesh.triangles.size();
        h.value(nv);
        h.value(nt);
        h.add(mesh.positions.data(), mesh.positions.size() * sizeof(glm::vec3));
        h.add(mesh.triangles.data(), mesh.triangles.size() * sizeof(glm::uvec3));
        char hex[17];
        std::snprintf(hex, sizeof hex, "%016llx", (unsigned long long)finalize(h.h));
        key += hex;
    }
    return key;
}

void copySourceAttributes(const Mesh& mesh, const std::vector<uint32_t>& sourceVertex,
                          Mesh& atlas) {
    atlas.positions.resize(sourceVertex.size());
    for (size_t v = 0; v < sourceVertex.size(); ++v)
        atlas.positions[v] = mesh.positions[sourceVertex[v]];
    if (mesh.hasNormals()) {
        atlas.normals.resize(sourceVertex.size());
        for (size_t v = 0; v < sourceVertex.size(); ++v)
            atlas.normals[v] = mesh.normals[sourceVertex[v]];
    }
    if (mesh.hasTexcoords()) {
        atlas.texcoords.resize(sourceVertex.size());
        for (size_t v = 0; v < sourceVertex.size(); ++v)
            atlas.texcoords[v] = mesh.texcoords[sourceVertex[v]];
    }
    // Triangles keep their order and count.
    atlas.materialIds = mesh.materialIds;
}

std::optional<Mesh> loadCachedAtlas(const std::filesystem::path& file, const Mesh& mesh,
                                    AtlasStats* stats) {
    // A folder, FIFO or device where the entry should be is a miss (reading
    // one would throw or block).
    std::string bytes;
    try {
        bytes = readRegularFile(file.string(), "atlas cache entry");
    } catch (const Error&) {
        return std::nullopt;
    }
    if (bytes.size() < sizeof(Header) + sizeof(uint64_t)) return std::nullopt;
    Header h;
    std::memcpy(&h, bytes.data(), sizeof h);
    if (std::memcmp(h.magic, kMagic, sizeof kMagic) != 0 || h.version != uint32_t(kAtlasVersion))
        return std::nullopt;
    if (h.inVertices != mesh.positions.size() || h.triangles != mesh.triangles.size())
        return std::nullopt;
    if (h.outVertices > (uint64_t(1) << 32)) return std::nullopt;
    const size_t body = size_t(h.outVertices) * (sizeof(uint32_t) + 2 * sizeof(float)) +
                        size_t(h.triangles) * 3 * sizeof(uint32_t);
    if (bytes.size() != sizeof h + body + sizeof(uint64_t)) return std::nullopt;
    Hash64 sum;
    sum.add(bytes.data(), bytes.size() - sizeof(uint64_t));
    uint64_t stored;
    std::memcpy(&stored, bytes.data() + bytes.size() - sizeof stored, sizeof stored);
    if (stored != sum.h) return std::nullopt;

    const char* p = bytes.data() + sizeof h;
    std::vector<uint32_t> source(h.outVertices);
    std::memcpy(source.data(), p, source.size() * sizeof(uint32_t));
    p += source.size() * sizeof(uint32_t);
    Mesh out;
    out.name = mesh.name;
    out.uvs.resize(h.outVertices);
    std::memcpy(out.uvs.data(), p, out.uvs.size() * sizeof(glm::vec2));
    p += out.uvs.size() * sizeof(glm::vec2);
    out.triangles.resize(h.triangles);
    std::memcpy(out.triangles.data(), p, out.triangles.size() * sizeof(glm::uvec3));

    // The entry must describe this mesh: same corners, UVs in [0,1]².
    for (uint32_t s : source)
        if (s >= mesh.positions.size()) return std::nullopt;
    for (const glm::vec2& uv : out.uvs)
        if (!(uv.x >= 0 && uv.x <= 1 && uv.y >= 0 && uv.y <= 1)) return std::nullopt;
    for (size_t t = 0; t < out.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = out.triangles[t][k];
            if (v >= source.size() || source[v] != mesh.triangles[t][k]) return std::nullopt;
        }
    copySourceAttributes(mesh, source, out);
    if (stats) {
        stats->charts = h.charts;
        stats->coverage = h.coverage;
        stats->rWstd = h.rWstd;
        stats->rP01 = h.rP01;
        stats->rP99 = h.rP99;
        stats->rMin = h.rMin;
        stats->rMax = h.rMax;
        stats->flipped = h.flipped;
        stats->overlaps = h.overlaps;
        stats->fromCache = true;
    }
    return out;
}

bool storeCachedAtlas(const std::filesystem::path& file, const Mesh& atlas,
                      const std::vector<uint32_t>& sourceVertex, size_t inputVertices,
                      const AtlasStats& stats) {
    if (sourceVertex.size() != atlas.positions.size() || atlas.uvs.size() != atlas.positions.size())
        return false;
    Header h;
    std::memset(&h, 0, sizeof h);
    std::memcpy(h.magic, kMagic, sizeof kMagic);
    h.version = uint32_t(kAtlasVersion);
    const std::string stem = file.stem().string();
    std::memcpy(h.key, stem.data(), std::min(stem.size(), sizeof h.key));
    h.outVertices = atlas.positions.size();
    h.triangles = atlas.triangles.size();
    h.inVertices = inputVertices;
    h.charts = stats.charts;
    h.coverage = stats.coverage;
    h.rWstd = stats.rWstd;
    h.rP01 = stats.rP01;
    h.rP99 = stats.rP99;
    h.rMin = stats.rMin;
    h.rMax = stats.rMax;
    h.flipped = stats.flipped;
    h.overlaps = stats.overlaps;
    std::string bytes;
    append(bytes, &h, sizeof h);
    append(bytes, sourceVertex.data(), sourceVertex.size() * sizeof(uint32_t));
    append(bytes, atlas.uvs.data(), atlas.uvs.size() * sizeof(glm::vec2));
    append(bytes, atlas.triangles.data(), atlas.triangles.size() * sizeof(glm::uvec3));
    Hash64 sum;
    sum.add(bytes.data(), bytes.size());
    append(bytes, &sum.h, sizeof sum.h);
    try {
        std::filesystem::create_directories(file.parent_path());
        writeAtomically(file, [&](const std::filesystem::path& tmp) {
            std::ofstream out(tmp, std::ios::binary);
            out.write(bytes.data(), std::streamsize(bytes.size()));
            out.close();
            if (!out) throw std::runtime_error("write failed");
        });
        return true;
    } catch (...) {
        return false;
    }
}

Mesh buildAtlasCached(const Mesh& mesh, const AtlasOptions& opt, AtlasStats* stats) {
    const Timer timer;
    const auto dir = opt.useCache ? atlasCacheDirectory() : std::nullopt;
    std::filesystem::path file;
    if (dir) {
        file = *dir / (cacheKey(mesh, opt) + ".atlas");
        AtlasStats cached;
        if (auto hit = loadCachedAtlas(file, mesh, &cached)) {
            cached.seconds = timer.ms() / 1000.0;
            if (stats) *stats = cached;
            return std::move(*hit);
        }
    }
    AtlasStats built;
    std::vector<uint32_t> source;
    Mesh out = buildAtlasWithSources(mesh, opt, &built, &source);
    if (dir) storeCachedAtlas(file, out, source, mesh.positions.size(), built);
    if (stats) *stats = built;
    return out;
}

}  // namespace tsis::atlas
