#include "runner/cli/planned_run.h"

#include <set>
#include <stdexcept>
#include <utility>

#include "runner/cli/last_run_cache.h"
#include "runner/cli/sharded_run_setup.h"
#include "runner/history/history_database.h"
#include "runner/history/history_queries.h"
#include "runner/plan/last_failed.h"
#include "runner/plan/selection.h"
#include "runner/plan/world_logs.h"
#include "runner/reports/rerun_report.h"

namespace robottestingframework {
namespace runner {

namespace {

void say(PlannedRun& plan, const std::string& text) {
    plan.notes.push_back({PlanNote::Stream::Out, text});
}

void warn(PlannedRun& plan, const std::string& text) {
    plan.notes.push_back({PlanNote::Stream::Err, text});
}

bool hasTests(const std::vector<SuiteSpec>& suites) {
    for (const auto& suite : suites) {
        if (!suite.tests.empty()) {
            return true;
        }
    }
    return false;
}

// --rerun-failed HISTORY: the failures of the history file's last run (all its shards).
std::vector<FailedTest> failedInHistory(const std::string& path) {
    HistoryDatabase history(path, HistoryDatabase::Mode::Read);
    std::vector<FailedTest> failed;
    for (const FailedInHistory& test : lastRunFailures(history)) {
        // The history keeps the id; FailedTest is the suite and the rest of it.
        const std::string prefix = test.suite.empty() ? "" : test.suite + "/";
        const bool prefixed = test.test.rfind(prefix, 0) == 0;
        failed.push_back({test.suite, prefixed ? test.test.substr(prefix.size()) : test.test});
    }
    return failed;
}

// --rerun-failed: only the tests the report (or the history's last run) says failed. False
// when the run ends here.
bool keepFailed(const Options& options, PlannedRun& plan) {
    std::vector<FailedTest> failed;
    try {
        if (looksLikeHistoryFile(options.rerunFailed)) {
            failed = failedInHistory(options.rerunFailed);
        } else {
            const Report earlier = readReport("--rerun-failed", options.rerunFailed);
            failed = failedTests(earlier);
            plan.reportSettings.sharded = earlier.shard.known;
            plan.reportSettings.shardIndex = earlier.shard.index;
            plan.reportSettings.shardCount = earlier.shard.count;
            plan.reportSettings.shardPlan = earlier.shard.plan;
        }
        // A rerun of a shard's failures is that shard again: its tests as they are, and its
        // report says so, for --merge to put it in place of the first one.
        if (plan.shard.sharded) {
            say(plan, "--rerun-failed: the failed tests of " + options.rerunFailed +
                          " run again as they are; the shard (" + plan.shard.source +
                          ") is not taken again");
            plan.shard = ShardChoice();
        }
        plan.reportSettings.rerun = true;
    } catch (const std::exception& e) {
        plan.outcome = PlannedRun::Outcome::Error;
        plan.error = e.what();
        return false;
    }
    if (failed.empty()) {
        say(plan, options.rerunFailed + " has no failed test: nothing to rerun");
        plan.outcome = PlannedRun::Outcome::NothingToRerun;
        return false;
    }
    keepFailedTests(plan.suites, failed);
    if (plan.suites.empty()) {
        // Not a success: the rerun was asked for the wrong suites, or the tests were renamed.
        plan.outcome = PlannedRun::Outcome::Error;
        plan.error = "--rerun-failed " + options.rerunFailed + ": none of its " +
                     std::to_string(failed.size()) + " failed test(s) is a test of this run (" +
                     failed.front().suite + "/" + failed.front().test +
                     ", ...); give the suites that report was written for";
        return false;
    }
    return true;
}

// --lf, --ff: the last run's failures, from the cache folder. False when the run ends here.
bool useLastFailed(const Options& options, PlannedRun& plan) {
    std::set<std::string> ids;
    std::string error;
    if (!readLastFailed(options.cacheDir, ids, error)) {
        plan.outcome = PlannedRun::Outcome::Error;
        plan.error = error;
        return false;
    }
    const std::size_t selected = countTestsNamed(plan.suites, ids);
    const std::string count = std::to_string(selected) + " test(s)";
    const char* const option = options.lastFailed ? "--lf" : "--ff";
    if (ids.empty()) {
        // As pytest: nothing known to have failed is no reason to run nothing.
        say(plan, std::string(option) + ": no test failed in the last run (" + options.cacheDir +
                      "): running every selected test");
    } else if (selected == 0) {
        say(plan, std::string(option) + ": none of the last run's " + std::to_string(ids.size()) +
                      " failed test(s) is selected: running every selected test");
    } else if (options.lastFailed) {
        say(plan, "--lf: running the " + count + " that failed in the last run");
        keepTestsNamed(plan.suites, ids);
    }
    if (options.failedFirst && selected > 0) {
        if (!options.lastFailed) {
            say(plan, "--ff: the " + count + " that failed in the last run first");
        }
        putTestsNamedFirst(plan.suites, ids);
    }
    return true;
}

// Only this shard's suites are kept; each keeps its place in the whole selection, so the
// shards' reports merge into the one a single machine would write.
void keepShard(const Options& options, const std::vector<unsigned int>& shardOf, PlannedRun& plan) {
    const ShardChoice& shard = plan.shard;
    plan.reportSettings.shardPlan = planIdentity(plan.suites, shard.count);
    std::vector<SuiteSpec> mine;
    for (std::size_t i = 0; i < plan.suites.size(); ++i) {
        if (shardOf[i] != shard.index) {
            continue;
        }
        SuiteSpec& suite = plan.suites[i];
        plan.reportSettings.suitePlaces.push_back(i);
        if (options.verbose) {
            say(plan, "shard " + std::to_string(shard.index) + " runs suite " + suite.name +
                          (suite.where.file.empty() ? "" : " (" + suite.where.file + ")"));
        }
        mine.push_back(std::move(suite));
    }
    plan.suites = std::move(mine);
    if (plan.suites.empty()) {
        say(plan, "shard " + std::to_string(shard.index) + " of " + std::to_string(shard.count) +
                      " has no suite to run");
    }
    plan.reportSettings.sharded = true;
    plan.reportSettings.shardIndex = shard.index;
    plan.reportSettings.shardCount = shard.count;
}

}  // namespace

PlannedRun planRun(const Options& options, std::vector<SuiteSpec> suites, ShardChoice shard) {
    PlannedRun plan;
    plan.suites = std::move(suites);
    plan.shard = std::move(shard);
    plan.error = filterNamingNoTest(plan.suites, options.selection);
    if (!plan.error.empty()) {
        plan.outcome = PlannedRun::Outcome::Error;
        return plan;
    }
    if (!options.rerunFailed.empty() && !keepFailed(options, plan)) {
        return plan;
    }
    // Suites written without tests run as RTF 2.x ran them (its own tests run such a suite and
    // expect exit 0); only a selection that leaves nothing of a plan with tests is exit 5.
    if (!hasTests(plan.suites)) {
        say(plan, "note: the suites given have no test");
    } else {
        if (!options.selection.empty()) {
            applySelection(plan.suites, options.selection);
        }
        if (!hasTests(plan.suites)) {
            if (!options.allowEmpty && !options.list && !options.listVariables) {
                plan.outcome = PlannedRun::Outcome::NothingSelected;
                plan.error =
                    "no test is selected (by -k, --filter, --tag or --exclude-tag); "
                    "--allow-empty makes that a success";
                return plan;
            }
            warn(plan, "warning: no test is selected");
        }
    }
    if ((options.lastFailed || options.failedFirst) && !useLastFailed(options, plan)) {
        return plan;
    }
    separateWorldLogs(plan.suites);
    if (!options.durations.empty()) {
        try {
            plan.durations = suiteDurations(options.durations);
        } catch (const std::exception& e) {
            if (plan.shard.sharded) {
                plan.outcome = PlannedRun::Outcome::Error;
                plan.error = e.what();
                return plan;
            }
            warn(plan, std::string("warning: ") + e.what() + "; no ETA");
        }
    }
    if (!plan.shard.sharded) {
        return plan;  // the durations feed the progress line's ETA alone: nothing to warn about
    }
    const std::vector<unsigned int> shardOf =
        shardsOf(plan.suites, plan.shard.count, plan.durations);
    std::size_t mine = 0;
    for (unsigned int of : shardOf) {
        mine += of == plan.shard.index ? 1 : 0;
    }
    say(plan, "shard " + std::to_string(plan.shard.index) + " of " +
                  std::to_string(plan.shard.count) + " (from " + plan.shard.source + ")" +
                  (options.durations.empty() ? "" : ", balanced by " + options.durations) + ": " +
                  std::to_string(mine) + " of " + std::to_string(plan.suites.size()) + " suites");
    if (options.list || options.listVariables) {
        plan.shardOf = std::move(shardOf);
    } else {
        keepShard(options, shardOf, plan);
    }
    return plan;
}

}  // namespace runner
}  // namespace robottestingframework
