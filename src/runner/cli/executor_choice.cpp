#include "runner/cli/executor_choice.h"

#include <algorithm>
#include <cstdio>
#include <mutex>
#include <random>

#include "fixtures/process/child_process.h"
#include "languages/test_loader.h"
#include "platform/process.h"
#include "runner/cli/program_name.h"
#include "runner/execution/in_process_executor.h"
#include "runner/execution/isolated_executor.h"

namespace robottestingframework {
namespace runner {

namespace {

// With the tests in the runner's process, each exec test's program gets a variable of this run
// (languages::setExecGuard), and so does everything it starts; should the runner be killed,
// even by SIGKILL, a watchdog kills every process carrying it, as a world's watchdog does for
// its processes (docs/reference/world-file.md): the parent-death signal reaches the program only.
// Started with the first exec test (a run without one has no watchdog); it sweeps when the
// runner's end closes its pipe, or when endExecGuard() lets it go.
std::mutex guardMutex;
std::unique_ptr<fixtures::Watchdog> guardWatchdog;
std::string guardEntry;
bool guardTried = false;

std::string guardWhatExecTestsStart() {
    std::lock_guard<std::mutex> lock(guardMutex);
    if (guardTried) {
        return guardEntry;
    }
    guardTried = true;
    std::random_device random;
    char name[64];
    std::snprintf(name, sizeof name, "RTF_IN_PROCESS_RUN_%08x%08x=1", random(), random());
    auto watchdog = std::make_unique<fixtures::Watchdog>();
    std::string error;
    if (!watchdog->start(name, error)) {
        std::fprintf(stderr,
                     "%s: warning: --isolation none: %s; what exec tests start may outlive a "
                     "killed runner\n",
                     programName, error.c_str());
        return guardEntry;
    }
    guardWatchdog = std::move(watchdog);
    guardEntry = name;
    return guardEntry;
}

}  // namespace

void endExecGuard() {
    std::unique_ptr<fixtures::Watchdog> watchdog;
    {
        std::lock_guard<std::mutex> lock(guardMutex);
        watchdog.swap(guardWatchdog);
    }
    watchdog.reset();  // it sweeps (the runner does not carry the variable), exits, is reaped
}

std::unique_ptr<TestExecutor> inProcessExecutor(Options& options) {
    std::fprintf(stderr,
                 "%s: warning: --isolation none: a test that crashes, exits or blocks in "
                 "native code ends or holds the run; a timeout can only ask it to stop\n",
                 programName);
    // Daemons the tests leave (out of their process groups) are adopted, and end with us
    // (where the platform can: not on Windows).
    platform::becomeSubreaper();
    languages::setExecGuard(guardWhatExecTestsStart);
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
