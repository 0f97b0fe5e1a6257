#include "render/accumulator.h"

#include <cstddef>

namespace tsis {

const std::vector<float>& RadiosityAccumulator::add(uint64_t key, const std::vector<float>& rgba) {
    if (key != key_ || frames_ == 0 || sum_.size() != rgba.size()) {
        key_ = key;
        frames_ = 0;
        sum_.assign(rgba.size(), 0.0);
        mean_.assign(rgba.size(), 0.0f);
    }
    ++frames_;
    const double inv = 1.0 / frames_;
    for (size_t i = 0; i < rgba.size(); ++i) {
        if (i % 4 == 3) {
            mean_[i] = rgba[i];
            continue;
        }
        sum_[i] += rgba[i];
        mean_[i] = static_cast<float>(sum_[i] * inv);
    }
    return mean_;
}

}  // namespace tsis
