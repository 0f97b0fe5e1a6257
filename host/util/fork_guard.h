// What a child forked without exec needs to exit. log4cplus 2.0 (loaded for
// OpenVDB by OpenImageIO) starts a thread pool at load and waits for its
// threads at exit; fork() copies none of them, so a child that exits through
// exit() (Python's sys.exit, the end of a script) waits forever
// (log4cplus/log4cplus#364). tsis logs nothing through it.
#pragma once

namespace tsis {

// Registers, once, a pthread_atfork handler that shuts log4cplus's pool down
// before each fork() (found with dlsym: a no-op where log4cplus is absent).
// Also run at load wherever this file is linked.
void guardForks();

}  // namespace tsis
