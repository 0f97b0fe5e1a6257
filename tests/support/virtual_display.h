// An X display for the window's end-to-end tests (`tsis view`): a private
// Xvfb started on a free display number and stopped with this object when
// Xvfb is installed (setup.sh installs it), else the session's $DISPLAY.
#pragma once

#include <sys/types.h>

#include <string>

namespace tsis::test {

class VirtualDisplay {
  public:
    VirtualDisplay();
    ~VirtualDisplay();
    VirtualDisplay(const VirtualDisplay&) = delete;
    VirtualDisplay& operator=(const VirtualDisplay&) = delete;

    // ":N", or empty when there is neither Xvfb nor $DISPLAY.
    const std::string& name() const { return name_; }
    // "DISPLAY=:N", for runTsis's environment.
    std::string env() const { return "DISPLAY=" + name_; }

  private:
    pid_t pid_ = -1;
    std::string name_;
};

}  // namespace tsis::test
