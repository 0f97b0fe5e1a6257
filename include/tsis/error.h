// The one exception tsis throws for a user error (bad input, a missing device):
// its what() is the one line `tsis` prints after "tsis: error: ". Part of the
// public API (include/tsis/); host/util/error.h builds on it.
#pragma once

#include <stdexcept>

namespace tsis {

class Error : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

}  // namespace tsis
