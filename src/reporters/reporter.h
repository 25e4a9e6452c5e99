// The one interface every output format stands on. A reporter hears the run's events (it is a
// TestListener) and, at the end, gives its whole file. Two bases, as Catch2 has them:
// StreamingReporter builds its text as events arrive (TAP); CumulativeReporter writes from the
// collector's finished records (text, JUnit, JSON, HTML).
#pragma once

#include <cstddef>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <robottestingframework/TestListener.h>
#include <robottestingframework/TestResultCollector.h>

#include "reporters/history_strip.h"

namespace robottestingframework {
namespace reporters {

// What the plan says of a test that its events do not: the HTML report shows it.
struct TestFacts {
    std::string type;    // "dll", "python", ...; empty: from the file
    std::string plugin;  // as the suite wrote it
    std::string param;   // expanded
    std::vector<std::string> tags;
};

// What the command line says about every output.
struct ReporterSettings {
    // The runner's reports keep everything whatever -v/-d say (those change only the console).
    // RTF 2.x's outputters keep these only when made verbose: passed checks (JUnitOutputter,
    // TextOutputter), reports and what tests printed (TextOutputter).
    bool passedChecks = true;
    bool reports = true;
    bool summary = true;  // --no-summary turns it off (text only)
    // The shard this run is (--shard-index/--shard-count or a CI engine's variables): JUnit
    // and JSON say so, for --merge --expect-shards to check.
    bool sharded = false;
    unsigned int shardIndex = 0;
    unsigned int shardCount = 0;
    bool rerun = false;  // --rerun-failed: --merge lets it replace the tests it reruns
    // The place (from 0) of each suite of this run among every selected suite, before a shard
    // was taken: JUnit's testsuite id and JSON's testId, so merged shards order their suites
    // as one machine would. Empty: the suites' places in this run.
    std::vector<std::size_t> suitePlaces;
    // What the run was, as "name: value" pairs in order (command line, variables, host,
    // version, isolation, jobs): the HTML report's run metadata. Empty outside the runner.
    std::vector<std::pair<std::string, std::string>> runFacts;
    // Each planned test's facts by its whole id ("SUITE/id"). Empty outside the runner.
    std::map<std::string, TestFacts> testFacts;
    std::size_t suitePlace(std::size_t index) const {
        return suitePlaces.empty() ? index : suitePlaces[index % suitePlaces.size()];
    }
    // --history: each test's recent runs, filled once this run is in the history (before the
    // outputs are written); null without --history.
    std::shared_ptr<const HistoryStrips> history;
};

class Reporter : public TestListener {
public:
    // The file's whole content as things stand. Called once the run is over, or cut short (then
    // with what is known: tests still open show as interrupted).
    virtual std::string document() = 0;
    // Writes document() whole or not at all; on failure false, with `error` naming the file.
    bool write(const std::string& filename, TestMessage* error);
};

// Reacts to each event; events say which test they are about, so nothing is inferred from order.
class StreamingReporter : public Reporter {};

// Ignores events: the collector (a listener of the same run) keeps the records it writes from.
class CumulativeReporter : public Reporter {
public:
    CumulativeReporter(const TestResultCollector& collector, ReporterSettings settings)
        : collector_(collector), settings_(settings) {}

protected:
    const TestResultCollector& collector_;
    ReporterSettings settings_;
};

}  // namespace reporters
}  // namespace robottestingframework
