// The planned suites into the run plan the scheduler runs: each with the command line's
// overrides (-p, -e, --repetition, --timeout, --var), the kept world's stand-in fixture under
// --world, and, for the HTML report, each test's facts.
#pragma once

#include "runner/cli/kept_world.h"
#include "runner/cli/options.h"
#include "runner/cli/planned_run.h"
#include "runner/cli/run_inputs.h"
#include "runner/plan/run_plan.h"

namespace robottestingframework {
namespace runner {

// Moves `planned`'s suites into `plan` (planned.suites is left empty); `htmlReport`: an HTML
// output is asked for, which shows each test's param, tags and type.
void fillRunPlan(const Options& options, RunPlan& plan, PlannedRun& planned,
                 const RunInputs& inputs, KeptWorld& kept, bool htmlReport);

}  // namespace runner
}  // namespace robottestingframework
