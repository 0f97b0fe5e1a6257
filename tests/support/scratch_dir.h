// A fresh empty folder under the system temp dir, removed with everything in
// it by the destructor: scratch files for the loader tests and the outputs of
// the end-to-end tests.
#pragma once

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>

namespace tsis::test {

class ScratchDir {
  public:
    ScratchDir() {
        static std::atomic<int> counter{0};
        path_ = std::filesystem::temp_directory_path() /
                ("tsis-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~ScratchDir() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;

    const std::filesystem::path& path() const { return path_; }
    // The path of `name` in the folder.
    std::string file(const std::string& name) const { return (path_ / name).string(); }
    // The same, after writing `contents` there.
    std::string file(const std::string& name, const std::string& contents) const {
        const std::string p = file(name);
        std::ofstream(p, std::ios::binary) << contents;
        return p;
    }

  private:
    std::filesystem::path path_;
};

}  // namespace tsis::test
