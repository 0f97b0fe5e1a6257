// Helpers for end-to-end tests: run the tsis binary, scratch folders, scenes.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "support/scratch_dir.h"

namespace tsis::test {

struct RunResult {
    int exitCode = -1;
    std::string out, err;
};

// Runs `tsis <args>` through the shell with extra environment assignments
// (e.g. "TSIS_NO_GL=1"); captures stdout and stderr.
RunResult runTsis(const std::string& args, const std::string& env = "");

std::string readFile(const std::string& path);

// `s` as one shell word (for runTsis arguments with quotes, spaces, `$()`).
std::string shellQuote(const std::string& s);

// Number of files in a folder (to prove nothing half-written was left).
size_t fileCount(const std::filesystem::path& dir);

}  // namespace tsis::test
