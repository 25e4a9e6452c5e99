// What the history says, read back: each test's outcomes over the last N runs (the shards of
// one run count as one run), and each suite's latest time (for --durations-from).
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "runner/history/history_database.h"

namespace robottestingframework {
namespace runner {

struct TestHistoryEntry {
    std::string state;  // TestStatus's word
    double duration = 0;
    unsigned int attempts = 1;
};

struct TestHistory {
    std::string test;                    // its id
    std::vector<TestHistoryEntry> runs;  // oldest first
};

// A value a test measured in one of the runs read (recentMeasurements).
struct MeasuredValue {
    std::size_t run = 0;  // the run's place among the runs read, from 0 (the oldest)
    std::string name;
    double value = 0;
    std::string unit;
    std::optional<double> low;
    std::optional<double> high;
};

struct RecentMeasurements {
    std::size_t runs = 0;  // how many runs were read
    // Test id -> its values, oldest run first, in the order measured within a run.
    std::map<std::string, std::vector<MeasuredValue>> byTest;
};

// The number of runs the history holds (a run's shards count once).
std::size_t countRuns(HistoryDatabase& database);

// Whether a run (or a shard of one) with the key `runKey` is in the history already.
bool hasRun(HistoryDatabase& database, const std::string& runKey);

// Every test of the last `runs` runs, each with its entries oldest first, in the order of the
// tests' ids. Throws HistoryError.
std::vector<TestHistory> recentHistories(HistoryDatabase& database, unsigned int runs);

// The measurements of the last `runs` runs, of the tests in `only` (every test's when null):
// only the tests that measured something have an entry. Throws HistoryError.
RecentMeasurements recentMeasurements(HistoryDatabase& database, unsigned int runs,
                                      const std::set<std::string>* only);

// A test that did not pass in a run: its suite's name and its id ("SUITE/TEST").
struct FailedInHistory {
    std::string suite;
    std::string test;
};

// The tests that failed, errored, crashed or timed out in the last run (all its shards), in the
// order recorded: --rerun-failed FILE with a history file. Throws HistoryError.
std::vector<FailedInHistory> lastRunFailures(HistoryDatabase& database);

// Each suite's time (seconds, fixtures included) in the latest run that has it.
std::map<std::string, double> latestSuiteSeconds(HistoryDatabase& database);

}  // namespace runner
}  // namespace robottestingframework
