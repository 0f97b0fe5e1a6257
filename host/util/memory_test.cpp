#include "util/memory.h"

#include <gtest/gtest.h>

#include <cstring>
#include <memory>

#include "support/scoped_env.h"
#include "util/error.h"

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

TEST(Memory, AvailableIsKnownAndLimitedByTheEnvironment) {
    const std::optional<uint64_t> machine = availableMemoryBytes();
    ASSERT_TRUE(machine.has_value()) << "Linux has MemAvailable";
    EXPECT_GT(*machine, uint64_t(0));
    {
        test::ScopedEnv limit("TSIS_MEMORY_LIMIT_MB", "100");
        EXPECT_EQ(availableMemoryBytes(), std::min<uint64_t>(*machine, 100000000));
    }
    test::ScopedEnv bad("TSIS_MEMORY_LIMIT_MB", "lots");
    EXPECT_THROW(availableMemoryBytes(), Error);
}

TEST(Memory, RequireMemoryRefusesPastTheAvailable) {
    EXPECT_NO_THROW(requireMemory(2000000000, std::nullopt, "x"));  // unknown: no check
    EXPECT_NO_THROW(requireMemory(2000000000, 2000000000, "x"));
    try {
        requireMemory(8300000000, 4200000000, "a 8192×8192 frame");
        FAIL() << "accepted";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(),
                     "a 8192×8192 frame needs about 8.3 GB of memory but 4.2 GB is available");
    }
}

}  // namespace
}  // namespace tsis
