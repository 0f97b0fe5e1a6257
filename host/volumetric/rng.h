// PCG32 (O'Neill 2014): small, fast and seekable by stream, so every pixel
// sample gets its own sequence and an image does not depend on how threads
// were scheduled.
#pragma once

#include <cstdint>

namespace tsis {

class Rng {
  public:
    Rng(uint64_t seed, uint64_t stream) : inc_((stream << 1u) | 1u) {
        next();
        state_ += seed;
        next();
    }

    uint32_t next() {
        const uint64_t old = state_;
        state_ = old * 6364136223846793005ull + inc_;
        const auto xorShifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
        const auto rot = static_cast<uint32_t>(old >> 59u);
        return (xorShifted >> rot) | (xorShifted << ((32u - rot) & 31u));
    }

    // Uniform in [0, 1) with 53 random bits.
    double uniform() {
        const uint64_t hi = next(), lo = next();
        return static_cast<double>(((hi << 32u) | lo) >> 11u) * 0x1p-53;
    }

  private:
    uint64_t state_ = 0;
    uint64_t inc_;
};

}  // namespace tsis
