// 64-bit FNV-1a: cache keys and change detection (fast, not cryptographic).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace tsis {

constexpr uint64_t kFnvBasis = 0xcbf29ce484222325ull;

inline uint64_t fnv1a(const void* data, size_t bytes, uint64_t h = kFnvBasis) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < bytes; ++i) {
        h ^= p[i];
        h *= 0x100000001b3ull;
    }
    return h;
}

// Feeds values field by field (never whole structs: their padding is not data).
class Hasher {
  public:
    explicit Hasher(uint64_t seed = kFnvBasis) : h_(seed) {}
    template <typename T>
    Hasher& add(const T& value) {
        static_assert(std::is_trivially_copyable_v<T>);
        h_ = fnv1a(&value, sizeof value, h_);
        return *this;
    }
    template <typename T>
    Hasher& addAll(const std::vector<T>& values) {
        h_ = fnv1a(values.data(), values.size() * sizeof(T), h_);
        return *this;
    }
    Hasher& add(std::string_view s) {
        h_ = fnv1a(s.data(), s.size(), add(s.size()).h_);
        return *this;
    }
    Hasher& add(const std::string& s) { return add(std::string_view(s)); }
    uint64_t digest() const { return h_; }

  private:
    uint64_t h_;
};

}  // namespace tsis
