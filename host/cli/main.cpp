#include <cstdio>

#include "cli/commands.h"
#include "util/temporaries.h"

int main(int argc, char** argv) {
    // First, before any thread starts: an interrupted run leaves no temporaries.
    tsis::installSignalCleanup();
    return tsis::runCli(argc, argv);
}
