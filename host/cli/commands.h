// The `tsis` command line: subcommands and their dispatch.
#pragma once

namespace tsis {

// Parses argv, runs the subcommand, reports a user error once as one line on
// stderr ("tsis: error: ..."), and returns the process exit status.
int runCli(int argc, char** argv);

}  // namespace tsis
