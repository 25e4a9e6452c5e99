// Windows: the tests run in the runner's process (--isolation none). Worker processes are not
// built for Windows yet (README: Platforms).
#include "runner/cli/executor_choice.h"

#include <cstdio>

#include "runner/cli/program_name.h"
#include "runner/execution/in_process_executor.h"

namespace robottestingframework {
namespace runner {

std::unique_ptr<TestExecutor> chooseExecutor(Options& options, std::string& error) {
    if (options.isolation != Isolation::None) {
        error =
            "--isolation process (the default) is not built for Windows yet: run the tests "
            "in the runner's process with --isolation none";
        return nullptr;
    }
    std::fprintf(stderr,
                 "%s: warning: --isolation none: a test that crashes, exits or blocks in "
                 "native code ends or holds the run; a timeout can only ask it to stop\n",
                 programName);
    if (options.jobs > 1) {
        std::fprintf(stderr,
                     "%s: warning: --isolation none runs one suite at a time (tests share "
                     "the runner's process); --jobs %u is not used\n",
                     programName, options.jobs);
        options.jobs = 1;
    }
    return std::make_unique<InProcessExecutor>();
}

}  // namespace runner
}  // namespace robottestingframework
