// robottestingframework-testrunner: the story of a run. Each stage is a
// function in a file named for what it does; the exit statuses are SPEC 3.1's
// (exit_status.h).
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "platform/process_tree.h"
#include "runner/cli/attachments_folder.h"
#include "runner/cli/executor_choice.h"
#include "runner/cli/exit_status.h"
#include "runner/cli/kept_world.h"
#include "runner/cli/last_run_cache.h"
#include "runner/cli/list_command.h"
#include "runner/cli/live_web_page.h"
#include "runner/cli/options.h"
#include "runner/cli/output_paths.h"
#include "runner/cli/plan_outcome.h"
#include "runner/cli/planned_run.h"
#include "runner/cli/private_networks.h"
#include "runner/cli/program_name.h"
#include "runner/cli/progress_plan.h"
#include "runner/cli/run_history.h"
#include "runner/cli/run_inputs.h"
#include "runner/cli/run_listeners.h"
#include "runner/cli/run_plan_filling.h"
#include "runner/cli/run_rounds.h"
#include "runner/cli/slowest_tests.h"
#include "runner/cli/standalone_command.h"
#include "runner/cli/watch_command.h"
#include "runner/cli/world_join.h"
#include "runner/cli/world_keeper.h"
#include "runner/plan/run_plan.h"

using namespace robottestingframework;
using namespace robottestingframework::runner;

int main(int argc, char** argv) {
    Options options;
    const ParseResult parsed = parseOptions(argc, argv, options);
    if (parsed.outcome == ParseResult::Outcome::Exit) {
        std::fputs(parsed.text.c_str(), parsed.status == 0 ? stdout : stderr);
        return parsed.status;
    }
    // A report to the standard output has it alone: the console goes to the standard error.
    std::string error;
    if (!keepStandardOutputForReports(options, error)) {
        std::fprintf(stderr, "%s: %s\n", programName, error.c_str());
        return configurationError;
    }
    if (const std::optional<int> status = standaloneCommand(options)) {
        return *status;
    }

    RunInputs inputs;
    if (!readRunInputs(options, inputs)) {
        return configurationError;
    }
    PlannedRun planned = planRun(options, std::move(inputs.suites), inputs.shard);
    if (const std::optional<int> status = sayPlanOutcome(planned)) {
        return *status;
    }
    if (options.list || options.listVariables) {
        return listCommand(options, planned, inputs.overrides);
    }
    if (options.watch) {
        return watchCommand(argc, argv, options);  // read and checked above: run in children
    }
    if (!options.worldUp.empty()) {
        return worldUpCommand(options, planned, inputs);
    }
    // --world DIR: the suite's fixtures are the keeper's world, already up; its tests join it.
    KeptWorld kept;
    if (!joinWorldOfOptions(options, planned, kept) ||
        !setUpPrivateNetworks(options, planned.suites)) {
        return configurationError;
    }
    std::fflush(stdout);

    const bool htmlReport =
        std::any_of(options.outputs.begin(), options.outputs.end(),
                    [](const OutputRequest& output) { return output.type == "html"; });
    // The history file is checked before anything runs; it is written once the run is over.
    std::unique_ptr<RunHistory> history;
    if (!openRunHistory(options, planned, argc, argv, history)) {
        return configurationError;
    }
    if (!prepareAttachmentsFolder(options, error)) {
        std::fprintf(stderr, "%s: %s\n", programName, error.c_str());
        return configurationError;
    }
    // On the main thread, which lives for the whole run (executor_choice.h).
    const std::unique_ptr<TestExecutor> executor =
        chooseExecutor(options, planned.suites.size(), error);
    if (!executor) {
        std::fprintf(stderr, "%s: cannot start process isolation: %s\n", programName,
                     error.c_str());
        return configurationError;
    }
    RunPlan plan(*executor);
    fillRunPlan(options, plan, planned, inputs, kept, htmlReport);

    std::unique_ptr<WebProgressListener> web;
    if (options.webReporter && !(web = startWebPage(options))) {
        return configurationError;
    }
    if (web && history) {
        for (const auto& strip : history->earlierStrips()) {
            web->setTestHistory(strip.first, reporters::historyStripData(strip.second));
        }
    }
    if (web) {
        web->setPlan(plannedSuites(plan));
    }
    ProgressSettings progress = progressOf(plan, planned.durations);
    RunListeners listeners(options, planned.reportSettings, web.get(), std::move(progress));
    planned.reportSettings.testFacts.clear();  // the HTML output has its own copy
    const int interrupted =
        runRounds(options, plan, std::move(inputs.pools), listeners, kept.network);
    listeners.stopCapture();
    if (options.isolation == Isolation::None) {
        endExecGuard();                         // what exec tests started, daemons included
        platform::killDescendants(::getpid());  // what the tests left behind in our process
    }

    int status = runStatus(listeners.collector(), options.failOnFlaky, interrupted);
    if (history) {
        // A warning at worst: the status stays the run's.
        history->record(listeners.collector(), stderr, htmlReport);
    }
    recordLastRun(options, listeners.collector(), stderr);  // for --lf and --ff
    if (options.slowestTests >= 0) {
        std::fputs(slowestTestsText(listeners.collector(), options.slowestTests).c_str(), stdout);
        std::fflush(stdout);
    }
    if (!listeners.writeOutputs(stderr)) {
        status = configurationError;
    }
    if (web && options.webLinger > 0 && interrupted == 0) {
        lingerOn(*web, options.webLinger);
    }
    return status;
}
