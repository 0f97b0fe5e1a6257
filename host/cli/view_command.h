// `tsis view [render options]`: the interactive window (host/view).
#pragma once

#include <string>
#include <vector>

namespace tsis {

int runView(const std::vector<std::string>& argv);

}  // namespace tsis
