// Ctrl-C and `kill` of a long run: SIGINT / SIGTERM set a flag instead of ending the process, so
// the run stops its child processes (runWorkers, runProgram), writes what it has and says that it
// was interrupted. A second signal ends the process at once (the default action, restored).
#pragma once

namespace mb::process {

// Installs the handler for SIGINT and SIGTERM (once; later calls do nothing).
void catchInterrupts();
// The signal that arrived (SIGINT, SIGTERM), or 0.
int interruptSignal();
// "SIGINT" / "SIGTERM" for the message.
const char* interruptName();

}  // namespace mb::process
