// Progressive accumulation (docs/design.md §6): while nothing that changes the
// radiosity changes, each frame draws a new sample set and the image shows the
// mean of the frames so far, so a still view converges towards the reference.
#pragma once

#include <cstdint>
#include <vector>

namespace tsis {

class RadiosityAccumulator {
  public:
    // Frames already averaged for this key: the index of the next sample set.
    // 0 when the key differs from the one being accumulated.
    uint32_t framesFor(uint64_t key) const { return key == key_ ? frames_ : 0; }

    // Adds a frame's RGBA radiosity (a = coverage) under `key` and returns the
    // mean RGB (a from this frame). Starts over when the key or size changes.
    const std::vector<float>& add(uint64_t key, const std::vector<float>& rgba);

  private:
    uint64_t key_ = 0;
    uint32_t frames_ = 0;
    std::vector<double> sum_;  // double: thousands of frames without round-off drift
    std::vector<float> mean_;
};

}  // namespace tsis
