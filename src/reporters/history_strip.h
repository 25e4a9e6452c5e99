// A test's recent history as the HTML report shows it (--history): the states of its last
// runs, oldest first, their times for a sparkline, and its flaky rate. The runner reads them
// from the history file; the report embeds them beside the test and draws them with the
// script below, apart from the report's own script.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace robottestingframework {
namespace reporters {

struct HistoryStrip {
    std::vector<std::string> states;  // TestStatus's words, oldest first
    std::vector<double> durations;    // seconds, one per state
    double flakyRate = 0;             // 0 to 1
};

// Test id ("SUITE/TEST") -> its strip.
using HistoryStrips = std::map<std::string, HistoryStrip>;

// The strip's JSON value: {"states":[...],"durations":[...],"flakyRate":R}.
std::string historyStripData(const HistoryStrip& strip);

// A <style> and a <script> that define window.rtfHistoryStrip(history): the element drawing
// one test's strip of states, sparkline of durations and flaky rate.
const char* historyStripScript();

}  // namespace reporters
}  // namespace robottestingframework
