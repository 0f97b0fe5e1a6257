#include "cl/program_cache.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>

#include "util/cache_dir.h"
#include "util/hash.h"

namespace tsis {
namespace {

// File layout: magic, payload size, payload hash (all little-endian as
// written by this host), payload. The hash catches truncation and garbage
// before the driver sees the bytes.
constexpr char kMagic[8] = {'T', 'S', 'I', 'S', 'C', 'L', 'B', '1'};

}  // namespace

ProgramCache::ProgramCache(std::string dir) : dir_(std::move(dir)) {}

std::string ProgramCache::defaultDir() {
    return cacheDirectory();
}

std::string ProgramCache::key(const std::vector<std::string_view>& parts) {
    // Two independent 64-bit FNV-1a streams: 128 bits against accidental collisions.
    uint64_t a = kFnvBasis;
    uint64_t b = kFnvBasis ^ 0x9e3779b97f4a7c15ull;
    for (std::string_view part : parts) {
        const uint64_t len = part.size();
        const auto* p = reinterpret_cast<const unsigned char*>(part.data());
        const auto* l = reinterpret_cast<const unsigned char*>(&len);
        a = fnv1a(p, part.size(), fnv1a(l, sizeof len, a));
        b = fnv1a(l, sizeof len, fnv1a(p, part.size(), b));
    }
    char s[33];
    std::snprintf(s, sizeof s, "%016llx%016llx", static_cast<unsigned long long>(a),
                  static_cast<unsigned long long>(b));
    return s;
}

std::string ProgramCache::path(const std::string& key) const {
    return dir_.empty() ? std::string() : dir_ + "/" + key + ".clbin";
}

std::optional<std::vector<unsigned char>> ProgramCache::load(const std::string& key) const {
    if (dir_.empty()) return std::nullopt;
    std::ifstream in(path(key), std::ios::binary);
    if (!in) return std::nullopt;
    char magic[sizeof kMagic];
    uint64_t size = 0;
    uint64_t hash = 0;
    in.read(magic, sizeof magic);
    in.read(reinterpret_cast<char*>(&size), sizeof size);
    in.read(reinterpret_cast<char*>(&hash), sizeof hash);
    if (!in || std::memcmp(magic, kMagic, sizeof kMagic) != 0) return std::nullopt;
    if (size == 0 || size > (uint64_t{1} << 30)) return std::nullopt;
    std::vector<unsigned char> binary(size);
    in.read(reinterpret_cast<char*>(binary.data()), static_cast<std::streamsize>(size));
    if (!in || in.peek() != std::ifstream::traits_type::eof()) return std::nullopt;
    if (fnv1a(binary.data(), binary.size(), kFnvBasis) != hash) return std::nullopt;
    return binary;
}

bool ProgramCache::store(const std::string& key, const std::vector<unsigned char>& binary) const {
    if (dir_.empty() || binary.empty()) return false;
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::create_directories(dir_, ec);
    if (ec) return false;
    const std::string final = path(key);
    const std::string tmp =
        final + ".tmp" + std::to_string(::getpid()) + "_" + std::to_string(std::random_device{}());
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        const uint64_t size = binary.size();
        const uint64_t hash = fnv1a(binary.data(), binary.size(), kFnvBasis);
        out.write(kMagic, sizeof kMagic);
        out.write(reinterpret_cast<const char*>(&size), sizeof size);
        out.write(reinterpret_cast<const char*>(&hash), sizeof hash);
        out.write(reinterpret_cast<const char*>(binary.data()),
                  static_cast<std::streamsize>(binary.size()));
        out.close();
        if (!out) {
            fs::remove(tmp, ec);
            return false;
        }
    }
    fs::rename(tmp, final, ec);
    if (ec) {
        fs::remove(tmp, ec);
        return false;
    }
    return true;
}

}  // namespace tsis
