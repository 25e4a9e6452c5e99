// --world DIR for a run: the one suite planned joins the world its keeper holds (kept_world.h),
// in place of its own fixtures, and its tests live in the keeper's network.
#pragma once

#include "runner/cli/kept_world.h"
#include "runner/cli/options.h"
#include "runner/cli/planned_run.h"

namespace robottestingframework {
namespace runner {

// Without --world: true, nothing done. Else joins the keeper into `kept` and takes the suite's
// fixtures away; false, having said why, when there is not one suite or no keeper answers.
bool joinWorldOfOptions(const Options& options, PlannedRun& planned, KeptWorld& kept);

}  // namespace runner
}  // namespace robottestingframework
