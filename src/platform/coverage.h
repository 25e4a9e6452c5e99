// Coverage counters of processes that end with _exit.
#pragma once

namespace robottestingframework {
namespace platform {

// gcov writes its counters from an exit handler, which _exit skips: a forked worker, fork
// server or watchdog calls this just before its _exit so what it ran is counted. Does nothing
// unless the build has RTF_COVERAGE on.
void flushCoverage();

// True in a build with RTF_COVERAGE on: a process that writes its counters on the way out must
// not be killed then (a half-written .gcda loses that file's counts for every later process),
// so who would kill a finishing process waits for it first.
bool coverageBuild();

}  // namespace platform
}  // namespace robottestingframework
