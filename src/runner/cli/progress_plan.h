// What the progress line needs to know before the run: how many tests, and each suite's time
// from --durations-from when one is given (for the ETA; planRun has read it).
#pragma once

#include <optional>

#include "runner/cli/suite_durations.h"
#include "runner/console/progress_line.h"
#include "runner/plan/run_plan.h"

namespace robottestingframework {
namespace runner {

ProgressSettings progressOf(RunPlan& plan, const std::optional<SuiteSeconds>& durations);

}  // namespace runner
}  // namespace robottestingframework
