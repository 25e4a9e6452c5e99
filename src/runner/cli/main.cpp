// robottestingframework-testrunner: the story of a run. Each stage is a
// function in a file named for what it does; the exit statuses are SPEC 3.1's
// (exit_status.h).
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "platform/process_tree.h"
#include "runner/cli/attachments_folder.h"
#include "runner/cli/executor_choice.h"
#include "runner/cli/exit_status.h"
#include "runner/cli/history_import_command.h"
#include "runner/cli/history_report_command.h"
#include "runner/cli/kept_world.h"
#include "runner/cli/list_command.h"
#include "runner/cli/live_web_page.h"
#include "runner/cli/merge_command.h"
#include "runner/cli/options.h"
#include "runner/cli/output_paths.h"
#include "runner/cli/planned_run.h"
#include "runner/cli/private_networks.h"
#include "runner/cli/program_name.h"
#include "runner/cli/progress_plan.h"
#include "runner/cli/run_facts.h"
#include "runner/cli/run_history.h"
#include "runner/cli/run_inputs.h"
#include "runner/cli/run_listeners.h"
#include "runner/cli/run_rounds.h"
#include "runner/cli/slowest_tests.h"
#include "runner/cli/world_keeper.h"
#include "runner/history/history_error.h"
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
    {
        // A report to the standard output has it alone: the console goes to the standard error.
        std::string error;
        if (!keepStandardOutputForReports(options, error)) {
            std::fprintf(stderr, "%s: %s\n", programName, error.c_str());
            return configurationError;
        }
    }
    if (!options.merge.type.empty()) {
        return mergeCommand(options);
    }
    if (!options.historyImports.empty()) {
        const int status = historyImportCommand(options);
        if (status != allPassed || !options.historyReport) {
            return status;
        }
    }
    if (options.historyReport) {
        return historyReportCommand(options);
    }
    if (!options.worldDown.empty()) {
        return worldDownCommand(options);
    }

    RunInputs inputs;
    if (!readRunInputs(options, inputs)) {
        return configurationError;
    }
    PlannedRun planned = planRun(options, std::move(inputs.suites), inputs.shard);
    for (const PlanNote& note : planned.notes) {
        std::fprintf(note.stream == PlanNote::Stream::Out ? stdout : stderr, "%s: %s\n",
                     programName, note.text.c_str());
    }
    if (planned.outcome == PlannedRun::Outcome::NothingToRerun) {
        return allPassed;
    }
    if (planned.outcome == PlannedRun::Outcome::NothingSelected) {
        std::fprintf(stderr, "%s: %s\n", programName, planned.error.c_str());
        return nothingSelected;
    }
    if (planned.outcome == PlannedRun::Outcome::Error) {
        std::fprintf(stderr, "%s: %s\n", programName, planned.error.c_str());
        return configurationError;
    }
    if (options.list || options.listVariables) {
        return listCommand(options, planned, inputs.overrides);
    }
    if (!options.worldUp.empty()) {
        return worldUpCommand(options, planned, inputs);
    }
    // --world DIR: the suite's fixtures are the keeper's world, already up; its tests join it.
    KeptWorld kept;
    if (!options.world.empty()) {
        std::string error;
        if (planned.suites.size() != 1) {
            std::fprintf(stderr, "%s: --world %s: expected one suite (--suite FILE), got %zu\n",
                         programName, options.world.c_str(), planned.suites.size());
            return configurationError;
        }
        if (!joinKeptWorld(options.world, planned.suites.front().name, kept, error)) {
            std::fprintf(stderr, "%s: --world %s: %s\n", programName, options.world.c_str(),
                         error.c_str());
            return configurationError;
        }
        planned.suites.front().fixtures.clear();
        planned.suites.front().network =
            kept.network ? SuiteSpec::Network::Private : SuiteSpec::Network::Host;
    }
    {
        std::string error, cost;
        if (!preparePrivateNetworks(options, planned.suites, error, cost)) {
            std::fprintf(stderr, "%s: %s\n", programName, error.c_str());
            return configurationError;
        }
        if (options.verbose && !cost.empty()) {
            std::printf("%s: %s\n", programName, cost.c_str());
        }
    }
    std::fflush(stdout);

    // Each test's param, tags and type, and its history strip: only the HTML report shows them
    // (10 000 tests' facts are a map of 10 000 entries).
    const bool htmlReport =
        std::any_of(options.outputs.begin(), options.outputs.end(),
                    [](const OutputRequest& output) { return output.type == "html"; });

    // The history file is checked before anything runs; it is written once the run is over.
    std::unique_ptr<RunHistory> history;
    if (!options.history.empty()) {
        try {
            const auto& where = planned.reportSettings;
            history = std::make_unique<RunHistory>(
                options.history,
                thisRun(argc, argv, where.sharded, where.shardIndex, where.shardCount));
        } catch (const HistoryError& e) {
            std::fprintf(stderr, "%s: %s\n", programName, e.what());
            return configurationError;
        }
        planned.reportSettings.history = history->strips();
    }

    std::string error;
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
    plan.gate().setFailFast(options.failFast);
    plan.setRetries(options.retries);
    for (auto& suite : planned.suites) {
        applyOverrides(suite, inputs.overrides);
        if (htmlReport) {
            addTestFacts(suite, planned.reportSettings.testFacts);
        }
        plan.addSuite(std::move(suite));
    }
    if (kept.fixture) {
        plan.suite(0).addFixtureManager(kept.fixture.get());
    }
    planned.suites.clear();

    std::unique_ptr<WebProgressListener> web;
    if (options.webReporter && !(web = startWebPage(options))) {
        return configurationError;
    }
    if (web && history) {
        for (const auto& strip : history->earlierStrips()) {
            web->setTestHistory(strip.first, reporters::historyStripData(strip.second));
        }
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
