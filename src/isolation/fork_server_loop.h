// The fork server's side: a process that has loaded no user code, started once per run. For
// each request from the runner it forks a worker for one test or fixture; it tells the runner
// the worker's pid and, later, how it ended. When the runner goes (even killed with SIGKILL),
// it freezes and kills every process the run started, then exits.
#pragma once

namespace robottestingframework {
namespace isolation {

// Serves requests read from `control` (a packet socket) until the runner closes it or dies.
// Returns the process exit code.
int serveForkRequests(int control);

}  // namespace isolation
}  // namespace robottestingframework
