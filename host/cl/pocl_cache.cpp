#include "cl/pocl_cache.h"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "cl/program_cache.h"

namespace tsis {

namespace {

namespace fs = std::filesystem;

bool writableDir(const fs::path& dir) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    return fs::is_directory(dir, ec) && ::access(dir.c_str(), W_OK | X_OK) == 0;
}

std::string env(const char* name) {
    const char* v = std::getenv(name);
    return v ? v : "";
}

}  // namespace

std::string preparePoclCache() {
    if (const std::string set = env("POCL_CACHE_DIR"); !set.empty())
        return writableDir(set)
                   ? ""
                   : "PoCL cannot write its cache folder '" + set + "' (POCL_CACHE_DIR)";
    // PoCL's own choice (pocl_cache.c).
    fs::path def;
    if (const std::string xdg = env("XDG_CACHE_HOME"); !xdg.empty())
        def = fs::path(xdg) / "pocl";
    else if (const std::string home = env("HOME"); !home.empty())
        def = fs::path(home) / ".cache" / "pocl";
    else
        return "";  // PoCL uses /tmp
    if (writableDir(def / "kcache")) return "";
    std::error_code ec;
    const std::string tsisCache = ProgramCache::defaultDir();
    const fs::path tmp = fs::temp_directory_path(ec) / ("tsis-pocl-" + std::to_string(::getuid()));
    for (const fs::path& dir :
         {tsisCache.empty() ? fs::path() : fs::path(tsisCache) / "pocl", tmp}) {
        if (!dir.empty() && writableDir(dir)) {
            ::setenv("POCL_CACHE_DIR", dir.c_str(), 1);
            return "";
        }
    }
    return "PoCL cannot write its cache folder '" + def.string() +
           "'; set POCL_CACHE_DIR to a writable folder";
}

}  // namespace tsis
