#include "util/memory.h"

#include <fstream>
#include <string>

namespace tsis {

double residentMegabytes() {
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);)
        if (line.rfind("VmRSS:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;  // kB
    return 0.0;
}

}  // namespace tsis
