// A test's recent history as the HTML report and the live page show it (--history): the states
// of its last runs, oldest first, their times for a sparkline, its flaky rate, and the values
// of each of its measurements across those runs. The runner reads them from the history file;
// the pages embed them beside the test and draw them with html_page/trends.js.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace robottestingframework {
namespace reporters {

// One measurement's values across the runs, oldest first (a run that measured it several
// times, repetitions, gives several).
struct MeasurementTrend {
    std::string name;
    std::string unit;                   // its newest value's
    std::vector<double> values;         // oldest first
    std::vector<unsigned int> runsAgo;  // per value: 0 the newest run read, 1 the one before...
    std::vector<std::size_t> outside;   // the places of the values outside their own limits
    std::optional<double> low;          // its newest value's limits, drawn as lines
    std::optional<double> high;
};

struct HistoryStrip {
    std::vector<std::string> states;             // TestStatus's words, oldest first
    std::vector<double> durations;               // seconds, one per state
    double flakyRate = 0;                        // 0 to 1
    std::vector<MeasurementTrend> measurements;  // by name, in the order first measured
};

// Test id ("SUITE/TEST") -> its strip.
using HistoryStrips = std::map<std::string, HistoryStrip>;

// The strip's JSON value: {"states":[...],"durations":[...],"flakyRate":R}, with
// "measurements":[{"name","unit","values","ago","outside","low","high"}] when it has any.
std::string historyStripData(const HistoryStrip& strip);

}  // namespace reporters
}  // namespace robottestingframework
