#include <cstdio>

#include "cli/commands.h"

int main(int argc, char** argv) {
    return tsis::runCli(argc, argv);
}
