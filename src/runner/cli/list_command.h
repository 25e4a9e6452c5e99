// --list and --list-vars: what would run, and nothing run (no plug-in loaded, no fixture
// started).
#pragma once

#include "runner/cli/options.h"
#include "runner/cli/planned_run.h"
#include "runner/plan/run_plan.h"

namespace robottestingframework {
namespace runner {

// Prints the planned suites with the overrides applied, and writes --list's JSON outputs.
// Returns allPassed, or configurationError (said on stderr) when an output cannot be written.
int listCommand(const Options& options, PlannedRun& planned, const Overrides& overrides);

}  // namespace runner
}  // namespace robottestingframework
