#include "util/error.h"

#include <cstdio>
#include <cstdlib>

namespace tsis {

void checkFailed(const char* file, int line, const std::string& what) {
    std::fprintf(stderr, "tsis: internal error at %s:%d: %s\n", file, line, what.c_str());
    std::abort();
}

}  // namespace tsis
