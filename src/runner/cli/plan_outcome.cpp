#include "runner/cli/plan_outcome.h"

#include <cstdio>

#include "runner/cli/exit_status.h"
#include "runner/cli/program_name.h"

namespace robottestingframework {
namespace runner {

std::optional<int> sayPlanOutcome(const PlannedRun& planned) {
    for (const PlanNote& note : planned.notes) {
        std::fprintf(note.stream == PlanNote::Stream::Out ? stdout : stderr, "%s: %s\n",
                     programName, note.text.c_str());
    }
    switch (planned.outcome) {
        case PlannedRun::Outcome::NothingToRerun:
            return allPassed;
        case PlannedRun::Outcome::NothingSelected:
            std::fprintf(stderr, "%s: %s\n", programName, planned.error.c_str());
            return nothingSelected;
        case PlannedRun::Outcome::Error:
            std::fprintf(stderr, "%s: %s\n", programName, planned.error.c_str());
            return configurationError;
        case PlannedRun::Outcome::Run:
            break;
    }
    return std::nullopt;
}

}  // namespace runner
}  // namespace robottestingframework
