#include "runner/cli/progress_plan.h"

namespace robottestingframework {
namespace runner {

ProgressSettings progressOf(RunPlan& plan, const std::optional<SuiteSeconds>& durations) {
    ProgressSettings settings;
    settings.tests = plan.testCount();
    for (std::size_t s = 0; s < plan.suiteCount(); ++s) {
        const std::string& name = plan.spec(s).name;
        double seconds = -1.0;
        if (durations) {
            const auto found = durations->find(name);
            seconds = found == durations->end() ? -1.0 : found->second;
        }
        settings.suites.emplace_back(name, seconds);
    }
    return settings;
}

}  // namespace runner
}  // namespace robottestingframework
