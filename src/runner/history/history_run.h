// What one run (or one imported report) adds to the history, as plain data: the run, its
// suites, each test's outcome and each measurement. Made from the collector's records
// (collected_run.h) or from a report (--history-import).
#pragma once

#include <string>
#include <vector>

namespace robottestingframework {
namespace runner {

struct HistoryRun {
    // The shards of one run share it (history_run_key.h); every other run has its own.
    std::string runKey;
    double started = 0;  // seconds since the Unix epoch
    std::string host;
    std::string command;  // the command line, as given
    bool sharded = false;
    unsigned int shardIndex = 0;
    unsigned int shardCount = 0;
    std::string source = "run";  // "run", or the path of an imported report
};

struct HistoryTestResult {
    std::string test;           // its id, "SUITE/TEST" (docs/reference/test-ids.md)
    std::string suite;          // the suite's name
    std::string state;          // TestStatus's word: "passed", "timed out", "flaky", ...
    double duration = 0;        // seconds, every attempt's
    unsigned int attempts = 1;  // 1 + its retries
};

struct HistorySuiteResult {
    std::string name;
    double duration = 0;  // seconds, fixtures included
};

// A value a test measured; `low`/`high` its limits when it gave them.
struct HistoryMeasurement {
    std::string test;  // the test's id
    std::string name;
    double value = 0;
    std::string unit;
    bool hasLow = false;
    double low = 0;
    bool hasHigh = false;
    double high = 0;
};

}  // namespace runner
}  // namespace robottestingframework
