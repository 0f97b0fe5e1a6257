// On-disk cache of OpenCL program binaries (as Boost.Compute's
// program_cache / program::build_with_source_file): one file per key, the key
// a hash of everything that decides the binary. Every failure (no directory,
// unreadable, truncated or corrupt file, unwritable directory) reads as a miss
// or a skipped store; the caller then compiles from source.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tsis {

class ProgramCache {
  public:
    // dir empty: a cache that never hits and never stores.
    explicit ProgramCache(std::string dir);

    // $TSIS_CACHE_DIR, else $XDG_CACHE_HOME/tsis, else $HOME/.cache/tsis, else "".
    static std::string defaultDir();

    // 32 hex digits from the platform, device, driver version, build options and
    // the full source text (the parts are separated so "ab"+"c" ≠ "a"+"bc").
    static std::string key(const std::vector<std::string_view>& parts);

    std::string path(const std::string& key) const;  // the file a key lives in

    std::optional<std::vector<unsigned char>> load(const std::string& key) const;
    // Writes to a temporary file and renames it, so readers never see half a file.
    // Returns false (and leaves no file behind) when the write fails.
    bool store(const std::string& key, const std::vector<unsigned char>& binary) const;

  private:
    std::string dir_;
};

}  // namespace tsis
