// What the history says, read back: each test's outcomes over the last N runs (the shards of
// one run count as one run), and each suite's latest time (for --durations).
#pragma once

#include <map>
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

// The number of runs the history holds (a run's shards count once).
std::size_t countRuns(HistoryDatabase& database);

// Every test of the last `runs` runs, each with its entries oldest first, in the order of the
// tests' ids. Throws HistoryError.
std::vector<TestHistory> recentHistories(HistoryDatabase& database, unsigned int runs);

// Each suite's time (seconds, fixtures included) in the latest run that has it.
std::map<std::string, double> latestSuiteSeconds(HistoryDatabase& database);

}  // namespace runner
}  // namespace robottestingframework
