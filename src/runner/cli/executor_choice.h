// --isolation: the executor that runs the tests, in worker processes (the fork server) or in the
// runner's own process.
#pragma once

#include <memory>
#include <string>

#include "runner/cli/options.h"
#include "runner/model/test_executor.h"

namespace robottestingframework {
namespace runner {

// Starts the executor `options.isolation` asks for. Call it on the main thread, which lives for
// the whole run: the fork server's parent-death signal is tied to the thread that started it.
// --isolation none warns of what it cannot do, and runs one suite at a time (`options.jobs`
// becomes 1). `suites`: how many the run has; with --jobs, as many fork servers start as suites
// may run at once. Nullptr with `error` when process isolation cannot start.
std::unique_ptr<TestExecutor> chooseExecutor(Options& options, std::size_t suites,
                                             std::string& error);

// --isolation none: the warnings, and one suite at a time. chooseExecutor calls it.
std::unique_ptr<TestExecutor> inProcessExecutor(Options& options);

// --isolation none, once the tests have run: the watchdog of what exec tests started, if one
// was, kills whatever still carries the run's variable (daemons out of the runner's tree too)
// and ends. Call it before killing what the tests left among the runner's descendants, which
// would end the watchdog before its sweep.
void endExecGuard();

}  // namespace runner
}  // namespace robottestingframework
