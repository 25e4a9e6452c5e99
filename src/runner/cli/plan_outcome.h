// What the planning stage says (planned_run.h): its notes on the console, and the exit status
// when the run stops there (nothing to rerun, nothing selected, a configuration error).
#pragma once

#include <optional>

#include "runner/cli/planned_run.h"

namespace robottestingframework {
namespace runner {

// Prints the plan's notes and its error; the exit status when the run ends here, else none.
std::optional<int> sayPlanOutcome(const PlannedRun& planned);

}  // namespace runner
}  // namespace robottestingframework
