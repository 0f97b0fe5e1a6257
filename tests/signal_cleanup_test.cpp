// Interrupted runs through the binary (issue 22 item 7): SIGINT, SIGTERM and
// SIGHUP end a run without leaving its temporaries (".NAME.tsis-tmp-*"), the
// --aov folder it made or animate's staging folder; and a later run removes
// the temporaries of a run that was killed outright (SIGKILL), by their pid.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <thread>
#include <vector>

#include "support/tsis_cli.h"

namespace tsis::test {
namespace {

namespace fs = std::filesystem;

const std::string kSmall = "--width 96 --height 96 --atlas-res 256 --light-res 256 ";

// `tsis ARGS` in the background, its stderr into `err`, with the default
// action for the signals under test whatever this process has.
pid_t start(const std::string& args, const std::string& err) {
    const pid_t pid = ::fork();
    if (pid == 0) {
        sigset_t none;
        sigemptyset(&none);
        ::sigprocmask(SIG_SETMASK, &none, nullptr);
        for (int sig : {SIGINT, SIGTERM, SIGHUP}) std::signal(sig, SIG_DFL);
        const int out = ::open("/dev/null", O_WRONLY);
        const int e = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        ::dup2(out, STDOUT_FILENO);
        ::dup2(e, STDERR_FILENO);
        const std::string cmd = std::string("exec ") + TSIS_BINARY + " " + args;
        ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    return pid;
}

// Waits up to a minute for `ready`; false if the process ended first or time
// ran out (then it is ended, with SIGKILL).
bool waitFor(pid_t pid, const std::function<bool()>& ready) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (std::chrono::steady_clock::now() < end) {
        if (ready()) return true;
        int status = 0;
        if (::waitpid(pid, &status, WNOHANG) == pid) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ::kill(pid, SIGKILL);
    ::waitpid(pid, nullptr, 0);
    return false;
}

// How `pid` ended: the signal that ended it, or -1 (with its exit code in the message).
int endingSignal(pid_t pid) {
    int status = 0;
    ::waitpid(pid, &status, 0);
    if (WIFSIGNALED(status)) return WTERMSIG(status);
    ADD_FAILURE() << "exited with " << (WIFEXITED(status) ? WEXITSTATUS(status) : -1);
    return -1;
}

std::vector<std::string> everything(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        names.push_back(e.path().lexically_relative(dir).string());
    std::sort(names.begin(), names.end());
    return names;
}

size_t temporariesIn(const fs::path& dir) {
    size_t n = 0;
    std::error_code ec;
    for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
        n += it->path().filename().string().find("tsis-tmp-") != std::string::npos;
    return n;
}

class Interrupted : public ::testing::TestWithParam<int> {};

// The outputs are reserved (temporaries made, the --aov folder made) before
// the mesh; many frames keep the run going until the signal.
TEST_P(Interrupted, RenderLeavesNothing) {
    const int sig = GetParam();
    ScratchDir dir;
    std::ofstream(dir.file("keep.txt")) << "x";
    const std::string err = dir.path().string() + ".err";
    const pid_t pid = start("render " + kSmall + "--frames 100000 -o " + dir.file("out.png") +
                                " --aov " + dir.file("aov/deep") + " --stats " + dir.file("s.json"),
                            err);
    ASSERT_TRUE(waitFor(pid, [&] { return temporariesIn(dir.path()) >= 8; })) << readFile(err);
    std::this_thread::sleep_for(std::chrono::milliseconds(300));  // into the frames
    ::kill(pid, sig);
    EXPECT_EQ(endingSignal(pid), sig) << readFile(err);
    EXPECT_EQ(everything(dir.path()), std::vector<std::string>{"keep.txt"});
    fs::remove(err);
}

// Frames already written into the staging folder, more coming (300 frames of
// 96² take about 15 s).
TEST_P(Interrupted, AnimateLeavesNothing) {
    const int sig = GetParam();
    ScratchDir dir;
    const std::string err = dir.path().string() + ".err";
    const fs::path anim = dir.path() / "anim";
    const pid_t pid = start("animate " + kSmall + "--frames 300 --orbit -o " + anim.string(), err);
    auto framesStaged = [&] {
        size_t n = 0;
        std::error_code ec;
        for (fs::recursive_directory_iterator it(anim, ec), end; !ec && it != end; it.increment(ec))
            n += it->is_regular_file(ec) && it->file_size(ec) > 0;
        return n >= 2;
    };
    ASSERT_TRUE(waitFor(pid, framesStaged)) << readFile(err);
    ::kill(pid, sig);
    EXPECT_EQ(endingSignal(pid), sig) << readFile(err);
    EXPECT_EQ(everything(dir.path()), std::vector<std::string>{});
    fs::remove(err);
}

INSTANTIATE_TEST_SUITE_P(Signals, Interrupted, ::testing::Values(SIGINT, SIGTERM, SIGHUP),
                         [](const auto& info) {
                             return std::string(info.param == SIGINT    ? "SIGINT"
                                                : info.param == SIGTERM ? "SIGTERM"
                                                                        : "SIGHUP");
                         });

// A pid no process has now: a child that has ended.
pid_t deadPid() {
    const pid_t pid = ::fork();
    if (pid == 0) ::_exit(0);
    ::waitpid(pid, nullptr, 0);
    return pid;
}

// SIGKILL cannot be caught: the next run writing into the folder cleans up.
TEST(StaleTemporaries, ALaterRunRemovesThoseOfDeadRuns) {
    ScratchDir dir;
    const std::string dead = std::to_string(deadPid()), alive = std::to_string(::getpid());
    const fs::path& d = dir.path();
    std::ofstream(d / (".out.tsis-tmp-" + dead + "-a1B2c3.png")) << "partial";
    std::ofstream(d / (".atlas.tsis-tmp-" + dead + ".bin")) << "partial";  // a cache's
    fs::create_directory(d / (".tsis-tmp-" + dead + "-Zz9yX8"));
    std::ofstream(d / (".tsis-tmp-" + dead + "-Zz9yX8") / "frame_0000.png") << "partial";
    // Kept: a live run's, and names that are not tsis temporaries.
    const std::vector<std::string> kept = {
        ".out.tsis-tmp-" + alive + "-q1w2e3.png",
        "notes.tsis-tmp-" + dead + "-a1B2c3.txt",  // not hidden
        ".out.tsis-tmp-abcdef.png",                // no pid
    };
    for (const std::string& k : kept) std::ofstream(d / k) << "x";
    RunResult r = runTsis("render " + kSmall + "-o " + dir.file("out.png"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::vector<std::string> expected = kept;
    expected.push_back("out.png");
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(everything(d), expected);
}

}  // namespace
}  // namespace tsis::test
