#include "util/progress.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <regex>
#include <sstream>
#include <thread>
#include <utility>
#include <vector>

#include "support/scoped_env.h"
#include "util/error.h"

namespace tsis {
namespace {

using test::ScopedEnv;

TEST(Progress, LinesWhenStderrIsNotATerminal) {
    ScopedEnv interval("TSIS_PROGRESS_INTERVAL", "0.05");
    ScopedEnv on("TSIS_PROGRESS", "1");
    testing::internal::CaptureStderr();  // stderr becomes a file
    {
        Progress p("atlas", 200);
        p.update(84);
        std::this_thread::sleep_for(std::chrono::milliseconds(400));
        p.update(150);
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
    }
    const std::string err = testing::internal::GetCapturedStderr();
    std::istringstream in(err);
    const std::regex line(R"(tsis: atlas (\d+)% \(\d+ s\))");
    int lines = 0, last = -1;
    for (std::string l; std::getline(in, l); ++lines) {
        std::smatch m;
        ASSERT_TRUE(std::regex_match(l, m, line)) << l;
        const int pct = std::stoi(m[1]);
        EXPECT_GE(pct, last);
        last = pct;
    }
    EXPECT_GE(lines, 2) << err;  // one at least from each sleep, and the last
    EXPECT_EQ(last, 100) << err;
    EXPECT_NE(err.find("tsis: atlas 42%"), std::string::npos) << err;
}

// Issue 22: a bad value was taken silently as 10 s; now the CLI refuses it.
TEST(Progress, IntervalFromTheEnvironmentIsChecked) {
    for (const char* good : {"0.5", "10", "86400", "1e2"}) {
        ScopedEnv interval("TSIS_PROGRESS_INTERVAL", good);
        EXPECT_NO_THROW(Progress::checkEnvironment()) << good;
        EXPECT_DOUBLE_EQ(Progress::lineInterval(), std::strtod(good, nullptr)) << good;
    }
    for (const char* unset : {static_cast<const char*>(nullptr), ""}) {
        ScopedEnv interval("TSIS_PROGRESS_INTERVAL", unset);
        EXPECT_NO_THROW(Progress::checkEnvironment());
        EXPECT_DOUBLE_EQ(Progress::lineInterval(), 10.0);
    }
    for (const char* bad : {"abc", "0", "-1", "5s", "nan", "inf", "1e300", " "}) {
        ScopedEnv interval("TSIS_PROGRESS_INTERVAL", bad);
        try {
            Progress::checkEnvironment();
            ADD_FAILURE() << "accepted " << bad;
        } catch (const Error& e) {
            const std::string m = e.what();
            EXPECT_NE(m.find(std::string("TSIS_PROGRESS_INTERVAL='") + bad + "'"),
                      std::string::npos)
                << m;
        }
        EXPECT_DOUBLE_EQ(Progress::lineInterval(), 10.0) << bad;
    }
}

TEST(Progress, ShortWorkPrintsNothing) {
    ScopedEnv interval("TSIS_PROGRESS_INTERVAL", "10");
    ScopedEnv on("TSIS_PROGRESS", "1");
    testing::internal::CaptureStderr();
    {
        Progress p("atlas", 10);
        p.update(5);
        p.finish();
    }
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

TEST(Progress, OffPrintsNothing) {
    ScopedEnv interval("TSIS_PROGRESS_INTERVAL", "0.01");
    ScopedEnv off("TSIS_PROGRESS", "0");
    testing::internal::CaptureStderr();
    {
        Progress p("atlas", 10);
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

TEST(Progress, ObserverOfTheCreatingThreadSeesEveryUpdate) {
    ScopedEnv off("TSIS_PROGRESS", "0");  // the observer does not depend on stderr's mode
    std::vector<std::pair<std::string, double>> seen;
    {
        ScopedProgressObserver observer(
            [&](const std::string& label, double f) { seen.emplace_back(label, f); });
        Progress p("gather", 4);
        p.update(1);
        p.update(3);
    }
    const std::vector<std::pair<std::string, double>> expected = {
        {"gather", 0.0}, {"gather", 0.25}, {"gather", 0.75}, {"gather", 1.0}};
    EXPECT_EQ(seen, expected);
    // Gone with its scope, and never seen by another thread's Progress.
    { Progress after("after", 1); }
    std::thread other;
    {
        ScopedProgressObserver observer(
            [&](const std::string& label, double f) { seen.emplace_back(label, f); });
        other = std::thread([] { Progress p("other", 2); });
        other.join();
    }
    EXPECT_EQ(seen, expected);
}

}  // namespace
}  // namespace tsis
