#include "util/process.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace tsis {
namespace {

namespace fs = std::filesystem;

struct TempDir {
    fs::path path = fs::temp_directory_path() / ("tsis-process-test-" + std::to_string(::getpid()));
    TempDir() { fs::create_directories(path); }
    ~TempDir() { fs::remove_all(path); }
};

// A script that writes each argument on its own line (NUL-free args only).
void writeRecorder(const fs::path& file, const fs::path& log) {
    std::ofstream(file) << "#!/bin/sh\nfor a in \"$@\"; do printf '%s\\n' \"$a\"; done > '"
                        << log.string() << "'\nexit 3\n";
    fs::permissions(file, fs::perms::owner_all);
}

TEST(Process, ArgumentsArriveIntactAndNoShellRuns) {
    TempDir dir;
    const fs::path tool = dir.path / "tool", log = dir.path / "argv.txt";
    writeRecorder(tool, log);
    const fs::path pwned = dir.path / "PWNED";
    const std::vector<std::string> args = {"a b",
                                           "x'; touch " + pwned.string() + "; echo '",
                                           "$(touch " + pwned.string() + ")",
                                           "`id`",
                                           "\"q\"",
                                           "*"};
    EXPECT_EQ(runProgram(tool.string(), args), 3);
    std::ifstream in(log);
    std::vector<std::string> got;
    for (std::string line; std::getline(in, line);) got.push_back(line);
    EXPECT_EQ(got, args);
    EXPECT_FALSE(fs::exists(pwned));
}

TEST(Process, FindsInPathWithoutAShell) {
    TempDir dir;
    const fs::path tool = dir.path / "tsis-fake-tool";
    writeRecorder(tool, dir.path / "log");
    const std::string old = std::getenv("PATH") ? std::getenv("PATH") : "";
    ::setenv("PATH", ("/nonexistent:" + dir.path.string() + ":" + old).c_str(), 1);
    EXPECT_EQ(findInPath("tsis-fake-tool"), tool.string());
    EXPECT_EQ(findInPath("tsis-no-such-tool"), std::nullopt);
    EXPECT_EQ(findInPath("a;b"), std::nullopt);
    fs::permissions(tool, fs::perms::owner_read | fs::perms::owner_write);
    EXPECT_EQ(findInPath("tsis-fake-tool"), std::nullopt) << "not executable";
    ::setenv("PATH", old.c_str(), 1);
}

TEST(Process, MissingProgramIsAnError) {
    EXPECT_THROW(runProgram("/nonexistent/tool", {}), std::exception);
}

}  // namespace
}  // namespace tsis
