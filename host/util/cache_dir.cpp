#include "util/cache_dir.h"

#include <cstdlib>

namespace tsis {

std::string cacheDirectory() {
    auto env = [](const char* name) {
        const char* v = std::getenv(name);
        return v ? std::string(v) : std::string();
    };
    if (std::string d = env("TSIS_CACHE_DIR"); !d.empty()) return d;
    if (std::string d = env("XDG_CACHE_HOME"); !d.empty()) return d + "/tsis";
    if (std::string d = env("HOME"); !d.empty()) return d + "/.cache/tsis";
    return {};
}

}  // namespace tsis
