#include "util/fork_guard.h"

#include <dlfcn.h>
#include <pthread.h>

#include <mutex>

namespace tsis {

namespace {

void shutDownLog4cplusPool() {
    // log4cplus::shutdownThreadPool(): joins the idle workers; the pool is
    // not started again (2.0.x), and nothing of tsis's logs through it.
    using Fn = void (*)();
    static const auto fn =
        reinterpret_cast<Fn>(dlsym(RTLD_DEFAULT, "_ZN9log4cplus18shutdownThreadPoolEv"));
    if (fn) fn();
}

}  // namespace

void guardForks() {
    static std::once_flag once;
    std::call_once(once, [] { pthread_atfork(shutDownLog4cplusPool, nullptr, nullptr); });
}

namespace {

// At load, wherever this file is linked in (api::Renderer calls guardForks):
// `import tsis` and a fork before any renderer.
[[maybe_unused]] const bool gGuarded = (guardForks(), true);

}  // namespace

}  // namespace tsis
