#include "view/thread_priority.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace tsis {

void lowerThisThreadPriority() {
    // On Linux the nice value belongs to the thread (setpriority with its id).
    const id_t tid = static_cast<id_t>(::syscall(SYS_gettid));
    const int now = ::getpriority(PRIO_PROCESS, tid);
    (void)::setpriority(PRIO_PROCESS, tid, now + 10);
}

}  // namespace tsis
