#include "runner/cli/run_history.h"

#include <sys/stat.h>

#include <chrono>
#include <map>
#include <set>

#include <robottestingframework/Measurement.h>

#include "reporters/host_name.h"
#include "runner/cli/program_name.h"
#include "runner/history/collected_run.h"
#include "runner/history/history_database.h"
#include "runner/history/history_error.h"
#include "runner/history/history_queries.h"
#include "runner/history/history_run_key.h"
#include "runner/history/history_trends.h"
#include "runner/history/run_appender.h"

namespace robottestingframework {
namespace runner {

namespace {

// Each measurement of `values` (a test's, oldest run first) as a trend per name, in the order
// first measured. `newest` runs ago is the newest run read.
std::vector<reporters::MeasurementTrend> trendsOf(const std::vector<MeasuredValue>& values,
                                                  std::size_t runs, unsigned int newest) {
    std::vector<reporters::MeasurementTrend> trends;
    std::map<std::string, std::size_t> places;
    for (const MeasuredValue& value : values) {
        const auto place = places.emplace(value.name, trends.size());
        if (place.second) {
            trends.emplace_back();
            trends.back().name = value.name;
        }
        reporters::MeasurementTrend& trend = trends[place.first->second];
        Measurement measured{value.name, value.value, value.unit, value.low, value.high};
        if (!measured.withinLimits()) {
            trend.outside.push_back(trend.values.size());
        }
        trend.values.push_back(value.value);
        trend.runsAgo.push_back(static_cast<unsigned int>(runs - 1 - value.run) + newest);
        trend.unit = value.unit;
        trend.low = value.low;
        trend.high = value.high;
    }
    return trends;
}

// The strips of the last `runs` runs, of the tests in `only` (of every test when null); the
// newest run read is `newest` runs ago (0: this run).
reporters::HistoryStrips readStrips(HistoryDatabase& database, unsigned int runs,
                                    const std::set<std::string>* only, unsigned int newest) {
    reporters::HistoryStrips strips;
    for (const TestHistory& history : recentHistories(database, runs)) {
        if (only != nullptr && only->count(history.test) == 0) {
            continue;
        }
        reporters::HistoryStrip& strip = strips[history.test];
        for (const TestHistoryEntry& entry : history.runs) {
            strip.states.push_back(entry.state);
            strip.durations.push_back(entry.duration);
        }
        strip.flakyRate = flakyRate(history);
    }
    // Only the tests that measured something get trends (10 000 tests without: no cost).
    const RecentMeasurements measured = recentMeasurements(database, runs, only);
    for (const auto& test : measured.byTest) {
        strips[test.first].measurements = trendsOf(test.second, measured.runs, newest);
    }
    return strips;
}

}  // namespace

RunHistory::RunHistory(std::string path, HistoryRun run)
    : path_(std::move(path)),
      run_(std::move(run)),
      strips_(std::make_shared<reporters::HistoryStrips>()) {
    checkHistoryFileKind(path_);  // /dev/null is refused before the run, not after it
    struct stat status {};
    if (::stat(path_.c_str(), &status) == 0 && status.st_size > 0) {
        HistoryDatabase check(path_, HistoryDatabase::Mode::Check);  // throws when not ours
    }
}

reporters::HistoryStrips RunHistory::earlierStrips() const {
    try {
        HistoryDatabase database(path_, HistoryDatabase::Mode::Read);
        return readStrips(database, shownRuns - 1, nullptr, 1);
    } catch (const HistoryError&) {
        return {};  // no file yet: nothing to show (a damaged one was refused at the start)
    }
}

bool RunHistory::record(const TestResultCollector& collector, std::FILE* console, bool readBack) {
    bool recorded = true;
    try {
        HistoryDatabase database(path_, HistoryDatabase::Mode::Append);
        RunAppender appender(database, run_);
        appendCollectedRun(appender, collector);
        appender.commit();
    } catch (const HistoryError& e) {
        std::fprintf(console,
                     "%s: warning: this run is not in the history: %s (the outputs are still "
                     "written)\n",
                     programName, e.what());
        recorded = false;
    }
    if (!readBack) {
        return recorded;
    }
    try {
        std::set<std::string> ran;
        for (const SuiteRecord& suite : collector.suites()) {
            for (const TestRecord& test : suite.tests) {
                ran.insert(historyTestId(suite, test));
            }
        }
        HistoryDatabase database(path_, HistoryDatabase::Mode::Read);
        *strips_ = readStrips(database, shownRuns, &ran, recorded ? 0 : 1);
    } catch (const HistoryError& e) {
        if (recorded) {
            std::fprintf(console, "%s: warning: cannot read the history back: %s\n", programName,
                         e.what());
        }
        return false;
    }
    return recorded;
}

HistoryRun thisRun(int argc, const char* const* argv, bool sharded, unsigned int shardIndex,
                   unsigned int shardCount) {
    HistoryRun run;
    run.runKey = historyRunKey();
    run.started =
        std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
    run.host = reporters::hostName();
    for (int i = 0; i < argc; ++i) {
        const std::string word = argv[i];
        const bool quote = word.empty() || word.find_first_of(" \t\"'\\$") != std::string::npos;
        run.command += (i == 0 ? "" : " ") + (quote ? "'" + word + "'" : word);
    }
    run.sharded = sharded;
    run.shardIndex = shardIndex;
    run.shardCount = shardCount;
    return run;
}

bool openRunHistory(const Options& options, PlannedRun& planned, int argc, const char* const* argv,
                    std::unique_ptr<RunHistory>& history) {
    if (options.history.empty()) {
        return true;
    }
    try {
        const auto& where = planned.reportSettings;
        history = std::make_unique<RunHistory>(
            options.history,
            thisRun(argc, argv, where.sharded, where.shardIndex, where.shardCount));
    } catch (const HistoryError& e) {
        std::fprintf(stderr, "%s: %s\n", programName, e.what());
        return false;
    }
    planned.reportSettings.history = history->strips();
    return true;
}

}  // namespace runner
}  // namespace robottestingframework
