// Windows: the tests run in the runner's process (--isolation none). Worker processes are not
// built for Windows yet (README: Platforms).
#include "runner/cli/executor_choice.h"

namespace robottestingframework {
namespace runner {

std::unique_ptr<TestExecutor> chooseExecutor(Options& options, std::string& error) {
    if (options.isolation != Isolation::None) {
        error =
            "--isolation process (the default) is not built for Windows yet: run the tests "
            "in the runner's process with --isolation none";
        return nullptr;
    }
    return inProcessExecutor(options);
}

}  // namespace runner
}  // namespace robottestingframework
