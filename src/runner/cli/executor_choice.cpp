#include "runner/cli/executor_choice.h"

#include <algorithm>
#include <cstdio>

#include "platform/process.h"
#include "runner/cli/program_name.h"
#include "runner/execution/in_process_executor.h"
#include "runner/execution/isolated_executor.h"

namespace robottestingframework {
namespace runner {

std::unique_ptr<TestExecutor> inProcessExecutor(Options& options) {
    std::fprintf(stderr,
                 "%s: warning: --isolation none: a test that crashes, exits or blocks in "
                 "native code ends or holds the run; a timeout can only ask it to stop\n",
                 programName);
    // Daemons the tests leave (out of their process groups) are adopted, and end with us
    // (where the platform can: not on Windows).
    platform::becomeSubreaper();
    if (options.jobs > 1) {
        std::fprintf(stderr,
                     "%s: warning: --isolation none runs one suite at a time (tests share "
                     "the runner's process); --jobs %u is not used\n",
                     programName, options.jobs);
        options.jobs = 1;
    }
    return std::make_unique<InProcessExecutor>();
}

// The same on every platform: the isolated executor hides how workers start (a fork server on
// POSIX, a job object per worker on Windows).
std::unique_ptr<TestExecutor> chooseExecutor(Options& options, std::size_t suites,
                                             std::string& error) {
    if (options.isolation == Isolation::None) {
        return inProcessExecutor(options);
    }
    isolation::IsolationOptions isolationOptions;
    isolationOptions.verbose = options.verbose;
    isolationOptions.servers =
        std::max<std::size_t>(1, std::min<std::size_t>(options.jobs, suites));
    auto isolated = std::make_unique<isolation::IsolatedExecutor>(isolationOptions);
    if (!isolated->start(error)) {
        return nullptr;
    }
    return isolated;
}

}  // namespace runner
}  // namespace robottestingframework
