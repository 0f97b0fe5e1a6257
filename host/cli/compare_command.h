// `tsis compare A.exr B.exr`: error metrics of A against the reference B.
#pragma once

#include <string>
#include <vector>

namespace tsis {

int runCompare(const std::vector<std::string>& argv);

}  // namespace tsis
