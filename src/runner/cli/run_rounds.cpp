#include "runner/cli/run_rounds.h"

#include <cstdio>
#include <utility>

#include "runner/cli/exit_status.h"
#include "runner/cli/interrupt_watcher.h"
#include "runner/cli/program_name.h"
#include "runner/schedule/scheduler.h"

namespace robottestingframework {
namespace runner {

int runRounds(const Options& options, RunPlan& plan, ResourcePools pools, RunListeners& listeners,
              std::shared_ptr<const platform::PrivateNetwork> network) {
    SchedulerSettings schedulerSettings;
    schedulerSettings.jobs = options.jobs;
    schedulerSettings.inlineSuites = options.isolation == Isolation::None;
    schedulerSettings.verbose = options.verbose;
    schedulerSettings.view = &listeners.schedulerView();
    schedulerSettings.network = std::move(network);
    Scheduler scheduler(plan, std::move(pools), schedulerSettings);

    std::FILE* console = listeners.console();
    InterruptWatcher watcher([&scheduler] { scheduler.interrupt(); }, console,
                             [&listeners] { listeners.quit(); });
    const unsigned int rounds = options.repeatUntilFail == 0 ? 1 : options.repeatUntilFail;
    for (unsigned int round = 1; round <= rounds; ++round) {
        if (rounds > 1) {
            std::fprintf(console, "%s: round %u of %u\n", programName, round, rounds);
            std::fflush(console);
        }
        scheduler.run(listeners.result());
        if (watcher.interrupted() || anythingFailed(listeners.collector())) {
            if (rounds > 1 && !watcher.interrupted()) {
                std::fprintf(console, "%s: round %u failed; stopping\n", programName, round);
            }
            break;
        }
    }
    return watcher.stop();
}

}  // namespace runner
}  // namespace robottestingframework
