// --web-reporter: the live page of the run, served from before the first test until the run
// ends, and --web-linger after it.
#pragma once

#include <memory>
#include <vector>

#include <robottestingframework/WebProgressListener.h>

#include "runner/cli/options.h"
#include "runner/plan/run_plan.h"

namespace robottestingframework {
namespace runner {

// Starts serving the page and says where on stdout (a warning on stderr when it is served
// beyond this machine's loopback address). Nullptr, the error said on stderr, when it cannot
// listen.
std::unique_ptr<WebProgressListener> startWebPage(const Options& options);

// The plan's suites, in order, for WebProgressListener::setPlan: every suite and test is on
// the page from the start, also with -j N.
std::vector<const TestSuite*> plannedSuites(RunPlan& plan);

// Keeps serving the final page for `seconds`, or until Ctrl-C or SIGTERM.
void lingerOn(const WebProgressListener& web, double seconds);

}  // namespace runner
}  // namespace robottestingframework
