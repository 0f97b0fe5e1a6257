#include "util/cancel.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <thread>

#include "util/error.h"

namespace tsis {
namespace {

// The poll runs on the making thread only, at most once per interval; a
// request from any thread stops every thread; a throwing poll stops.
TEST(Cancel, PollsOnItsThreadAtMostPerIntervalAndRequestsStopEverywhere) {
    int polls = 0;
    Cancel c([&] { return ++polls >= 2; });
    EXPECT_FALSE(c.stopping());  // the first poll: due at once
    EXPECT_EQ(polls, 1);
    for (int i = 0; i < 1000; ++i) EXPECT_FALSE(c.stopping());
    EXPECT_EQ(polls, 1);  // not due again within the interval
    bool elsewhere = true;
    std::thread([&] { elsewhere = c.stopping(); }).join();
    EXPECT_FALSE(elsewhere);
    EXPECT_EQ(polls, 1);  // never polled from another thread
    std::this_thread::sleep_for(Cancel::kPollInterval * 2);
    EXPECT_THROW(c.check(), Cancelled);
    EXPECT_EQ(polls, 2);
    std::thread([&] { elsewhere = c.stopping(); }).join();
    EXPECT_TRUE(elsewhere);

    Cancel none;
    EXPECT_NO_THROW(none.check());
    std::thread([&] { none.request(); }).join();
    EXPECT_THROW(none.check(), Cancelled);

    Cancel throwing([]() -> bool { throw std::runtime_error("poll"); });
    EXPECT_TRUE(throwing.stopping());
    try {
        throwing.check();
        ADD_FAILURE() << "no Cancelled";
    } catch (const Error& e) {  // a tsis::Error: the CLI's one line
        EXPECT_STREQ(e.what(), "the frame was cancelled");
    }
}

}  // namespace
}  // namespace tsis
