// Helpers for the mesh tests: the message of the tsis::Error a call throws,
// and scratch files.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>

#include "util/error.h"

namespace tsis::test {

// The message of the Error `f` throws; "(no error)" when it returns. Fails
// the test when the message is not one line or does not name `file`.
template <typename F>
std::string errorOf(F&& f, const std::string& file = "") {
    try {
        f();
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        if (!file.empty()) {
            EXPECT_NE(what.find("'" + file + "'"), std::string::npos) << what;
        }
        return what;
    }
    return "(no error)";
}

// A fresh directory under the system temp dir, removed on destruction.
class ScratchDir {
  public:
    ScratchDir() {
        static std::atomic<int> counter{0};
        path_ = std::filesystem::temp_directory_path() /
                ("tsis_mesh_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
        std::filesystem::create_directories(path_);
    }
    ~ScratchDir() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    std::string file(const std::string& name, const std::string& contents) const {
        const std::string p = (path_ / name).string();
        std::ofstream(p, std::ios::binary) << contents;
        return p;
    }
    std::string path() const { return path_.string(); }

  private:
    std::filesystem::path path_;
};

}  // namespace tsis::test
