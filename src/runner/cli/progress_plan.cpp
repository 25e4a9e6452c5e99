#include "runner/cli/progress_plan.h"

#include <exception>
#include <map>

#include "runner/cli/suite_durations.h"

namespace robottestingframework {
namespace runner {

ProgressSettings progressOf(RunPlan& plan, const std::string& durations,
                            std::vector<std::string>& warnings) {
    ProgressSettings settings;
    settings.tests = plan.testCount();
    std::map<std::string, double> seconds;
    if (!durations.empty()) {
        try {
            seconds = suiteDurations(durations);
        } catch (const std::exception& e) {
            warnings.push_back(std::string("warning: ") + e.what() + "; no ETA");
        }
    }
    for (std::size_t s = 0; s < plan.suiteCount(); ++s) {
        const std::string& name = plan.spec(s).name;
        auto found = seconds.find(name);
        settings.suites.emplace_back(name, found == seconds.end() ? -1.0 : found->second);
    }
    return settings;
}

}  // namespace runner
}  // namespace robottestingframework
