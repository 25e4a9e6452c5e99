// Coverage counters of processes that end with _exit.
#pragma once

namespace robottestingframework {
namespace platform {

// gcov writes its counters from an exit handler, which _exit skips: a forked worker, fork
// server or watchdog calls this just before its _exit so what it ran is counted. Does nothing
// unless the build has RTF_COVERAGE on.
void flushCoverage();

}  // namespace platform
}  // namespace robottestingframework
