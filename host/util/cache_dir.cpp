#include "util/cache_dir.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>

#include "util/error.h"
#include "util/note.h"

namespace tsis {

namespace {

std::string env(const char* name) {
    const char* v = std::getenv(name);
    return v ? std::string(v) : std::string();
}

std::string octal(unsigned mode) {
    char s[8];
    std::snprintf(s, sizeof s, "%04o", mode & 07777u);
    return s;
}

}  // namespace

std::string cacheDirectory() {
    if (std::string d = env("TSIS_CACHE_DIR"); !d.empty()) return d;
    if (std::string d = env("XDG_CACHE_HOME"); !d.empty()) return d + "/tsis";
    if (std::string d = env("HOME"); !d.empty()) return d + "/.cache/tsis";
    return {};
}

std::string privateDirectory(const std::string& dir) {
    if (::mkdir(dir.c_str(), 0700) != 0 && errno != EEXIST) return std::strerror(errno);
    struct stat st;
    if (::lstat(dir.c_str(), &st) != 0) return std::strerror(errno);
    if (S_ISLNK(st.st_mode)) return "it is a symbolic link";
    if (!S_ISDIR(st.st_mode)) return "it is not a directory";
    if (st.st_uid != ::geteuid())
        return concat("it belongs to uid ", st.st_uid, ", not to uid ", ::geteuid());
    // Writable by others: they may have put files there already.
    if (st.st_mode & (S_IWGRP | S_IWOTH))
        return concat("others can write it (mode ", octal(st.st_mode), ")");
    if ((st.st_mode & 07777) != 0700 && ::chmod(dir.c_str(), 0700) != 0)
        return concat("cannot make it private: ", std::strerror(errno));
    if (::access(dir.c_str(), W_OK | X_OK) != 0) return std::strerror(errno);
    return "";
}

std::string usableCacheDirectory() {
    std::string dir = cacheDirectory();
    if (dir.empty() || !env("TSIS_CACHE_DIR").empty()) return dir;
    std::error_code ec;
    std::filesystem::create_directories(std::filesystem::path(dir).parent_path(), ec);
    const std::string why = privateDirectory(dir);
    if (why.empty()) return dir;
    static std::once_flag once;
    std::call_once(once, [&] { emitNote("cache folder '" + dir + "' not used: " + why); });
    return "";
}

}  // namespace tsis
