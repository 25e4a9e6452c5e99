// Windows: no world keeper (it needs AF_UNIX control sockets with SCM_RIGHTS and sessions);
// robottestingframework_discover_tests keeps one world per test there.
#include <cstdio>

#include "runner/cli/exit_status.h"
#include "runner/cli/program_name.h"
#include "runner/cli/world_keeper.h"

namespace robottestingframework {
namespace runner {

namespace {

int notSupported(const char* option) {
    std::fprintf(stderr,
                 "%s: %s is not supported on Windows (no world keeper: one world per test)\n",
                 programName, option);
    return configurationError;
}

}  // namespace

int worldUpCommand(Options&, PlannedRun&, RunInputs&) {
    return notSupported("--world-up");
}

int worldDownCommand(const Options&) {
    return notSupported("--world-down");
}

}  // namespace runner
}  // namespace robottestingframework
