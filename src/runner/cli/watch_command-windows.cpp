// --watch on Windows: not supported yet (watch_command.h).
#include <cstdio>

#include "platform/file_watch.h"
#include "runner/cli/exit_status.h"
#include "runner/cli/program_name.h"
#include "runner/cli/watch_command.h"

namespace robottestingframework {
namespace runner {

int watchCommand(int /*argc*/, char** /*argv*/, Options& /*options*/) {
    platform::FileWatch watch;
    std::string error;
    watch.watch({}, error);
    std::fprintf(stderr, "%s: %s\n", programName, error.c_str());
    return configurationError;
}

}  // namespace runner
}  // namespace robottestingframework
