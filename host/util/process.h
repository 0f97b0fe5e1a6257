// Starting other programs without a shell: the arguments reach the program
// exactly as given, so quotes, spaces or `$()` in a path are just characters.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace tsis {

// The first executable file named `name` in the folders of $PATH (as execvp
// would find it); nullopt when there is none. A name with a '/' is not searched.
std::optional<std::string> findInPath(const std::string& name);

// Runs `program` with `args` (argv[1…]), stdin from /dev/null, and waits.
// Returns the exit status, or 128 + the signal that ended it. Throws
// tsis::Error when the program cannot be started.
int runProgram(const std::string& program, const std::vector<std::string>& args);

}  // namespace tsis
