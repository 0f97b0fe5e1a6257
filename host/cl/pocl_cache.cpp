#include "cl/pocl_cache.h"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "util/cache_dir.h"

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
    // PoCL aborts on an empty POCL_CACHE_DIR: empty means unset, as for tsis' own variables.
    if (const char* set = std::getenv("POCL_CACHE_DIR"); set && !*set) ::unsetenv("POCL_CACHE_DIR");
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
    // Folders tsis picks itself hold code PoCL will dlopen: private ones only
    // (util/cache_dir.h), never one a local user planted in the temporary folder.
    std::error_code ec;
    const std::string tsisCache = usableCacheDirectory();
    const fs::path tmpRoot = fs::temp_directory_path(ec);
    const fs::path tmp = ec ? fs::path() : tmpRoot / ("tsis-pocl-" + std::to_string(::geteuid()));
    std::string refused;
    for (const fs::path& dir :
         {tsisCache.empty() ? fs::path() : fs::path(tsisCache) / "pocl", tmp}) {
        if (dir.empty()) continue;
        if (const std::string why = privateDirectory(dir); !why.empty()) {
            refused = "; '" + dir.string() + "' is not safe to use: " + why;
            continue;
        }
        ::setenv("POCL_CACHE_DIR", dir.c_str(), 1);
        return "";
    }
    return "PoCL cannot write its cache folder '" + def.string() +
           "'; set POCL_CACHE_DIR to a writable folder" + refused;
}

}  // namespace tsis
