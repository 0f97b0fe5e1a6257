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

// A frame stopped because its caller asked (api::Renderer::render's `cancel`
// returned true; Ctrl-C in Python): the renderer stays usable.
class Cancelled : public Error {
  public:
    Cancelled() : Error("the frame was cancelled") {}
};

}  // namespace tsis
