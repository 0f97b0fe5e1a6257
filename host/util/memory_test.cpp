#include "util/memory.h"

#include <gtest/gtest.h>

#include <cstring>
#include <memory>

namespace tsis {
namespace {

TEST(Memory, ResidentSetFollowsTouchedPages) {
    const double before = residentMegabytes();
    ASSERT_GT(before, 0.0);
    // 64 MiB written (so resident), then read back so it is not optimised away.
    constexpr size_t kBytes = size_t(64) << 20;
    std::unique_ptr<char[]> block(new char[kBytes]);
    std::memset(block.get(), 1, kBytes);
    const double after = residentMegabytes();
    EXPECT_EQ(block[kBytes - 1], 1);
    EXPECT_GT(after - before, 48.0) << before << " -> " << after << " MiB";
}

}  // namespace
}  // namespace tsis
