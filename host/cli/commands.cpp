#include "cli/commands.h"

#include <cstdio>

namespace tsis {

int runCli(int, char**) {
    std::fprintf(stderr, "tsis: not yet\n");
    return 1;
}

}  // namespace tsis
