// What the progress line needs to know before the run: how many tests, and each suite's time
// from --durations REPORT when one is given (for the ETA).
#pragma once

#include <string>
#include <vector>

#include "runner/console/progress_line.h"
#include "runner/plan/run_plan.h"

namespace robottestingframework {
namespace runner {

// `warnings` gets a line when the durations report cannot be read (the run goes on without an
// ETA: a sharded run has already stopped on it).
ProgressSettings progressOf(RunPlan& plan, const std::string& durations,
                            std::vector<std::string>& warnings);

}  // namespace runner
}  // namespace robottestingframework
